#pragma once
#include <CLI/CLI.hpp>

namespace columba {

// `columba fit SCENE.xml --target IMAGE.exr --vary NAME=LO:HI[:START]... [-o DIR]` or
// `columba fit --spectra SPECTRA.csv --vary NAME=LO:HI[:START]... [-o DIR]`: the values of scene
// variables (or barbule parameters) that best reproduce a measurement, with uncertainties.
void addFitCommand(CLI::App& app);

}  // namespace columba
