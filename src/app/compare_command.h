#pragma once
#include <CLI/CLI.hpp>

namespace columba {

// `columba compare A.exr B.exr [--tolerance T]`: whether two images are bit-identical (or differ
// by at most T), with the largest difference and where it is.
void addCompareCommand(CLI::App& app);

}  // namespace columba
