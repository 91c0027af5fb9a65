#pragma once
#include <CLI/CLI.hpp>

namespace columba {

// `columba merge PIECES... -o OUT.exr` puts the pieces of a split render (--part, --pass) back
// together into OUT.exr and OUT.png; `columba merge --manifest FILE [--frame I]` merges every
// frame of a split sweep (as the merge job of `columba slurm` does).
void addMergeCommand(CLI::App& app);

// `columba compare A.exr B.exr [--tolerance T]`: whether two images are bit-identical (or differ
// by at most T), with the largest difference and where it is.
void addCompareCommand(CLI::App& app);

}  // namespace columba
