#pragma once
#include <CLI/CLI.hpp>

namespace columba {

// `columba montage -o SHEET.png [--columns N] [--tile W] [--title T] IMAGE.png|IMAGE.exr...`:
// a contact sheet of images, each labelled with its file name.
void addMontageCommand(CLI::App& app);

}  // namespace columba
