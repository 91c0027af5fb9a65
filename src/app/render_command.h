#pragma once
#include <CLI/CLI.hpp>

namespace columba {

// `columba render [SCENE.xml] [-o OUT.exr|OUT.png] [-D name=value]... [--spp N] [--threads N] [--seed S]`
// writes OUT.exr and OUT.png; an interrupted render writes OUT.partial.exr and OUT.partial.png.
void addRenderCommand(CLI::App& app);

}  // namespace columba
