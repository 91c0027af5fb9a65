#pragma once
// `columba feather`: writes procedural feather geometry (one feather or a neck) as a feather PLY.
#include <CLI/CLI.hpp>

namespace columba {

void addFeatherCommand(CLI::App& app);

}  // namespace columba
