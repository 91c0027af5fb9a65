#pragma once
#include <CLI/CLI.hpp>

namespace columba {

// `columba slurm [SCENE.xml] [render options] [--sweep ...]... --parts N [--passes M] [--partition P]
//                [--time T] [--cpus-per-task C] [--out-dir DIR] [--submit]`: writes a Slurm job array
// (one task per frame x part x pass) and a merge job after it, prints the sbatch commands, and with
// --submit submits them. Run again, it submits only the pieces still missing.
void addSlurmCommand(CLI::App& app);

}  // namespace columba
