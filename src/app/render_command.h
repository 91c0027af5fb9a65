#pragma once
#include <CLI/CLI.hpp>

namespace columba {

// `columba render [SCENE.xml] [-o OUT.exr] [-D name=value]... [--spp N] [--threads N] [--seed S]`
void addRenderCommand(CLI::App& app);

}  // namespace columba
