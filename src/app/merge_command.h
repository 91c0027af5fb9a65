#pragma once
#include <CLI/CLI.hpp>

namespace columba {

// `columba merge PIECES... -o OUT.exr` puts the pieces of a split render (--part, --pass) back
// together into OUT.exr and OUT.png; `columba merge --manifest FILE [--frame I]` merges every
// frame of a split sweep (as the merge job of `columba slurm` does).
void addMergeCommand(CLI::App& app);

}  // namespace columba
