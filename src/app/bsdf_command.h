#pragma once
#include <CLI/CLI.hpp>

namespace columba {

// `columba bsdf [--b B] [--phi_0 ..] [--phi_1 ..] [--mu ..] [--H ..] [--height ..] [--theta T]
// [--phi P] [--res N] [-o DIR]`: scatterometer image and lobe spectra of the barbule BSDF.
void addBSDFCommand(CLI::App& app);

}  // namespace columba
