#pragma once
#include <CLI/CLI.hpp>

namespace columba {

// `columba render [SCENE.xml] [-o OUT.exr|OUT.png] [-D name=value]... [--spp N] [--threads N] [--seed S]
//                 [--sweep NAME=START:STOP:STEP|NAME=v1,v2,...]... [--frames PATTERN] [--frame I]
//                 [--part K/N] [--pass K/N] [--manifest FILE]`
// writes OUT.exr and OUT.png (one pair per frame of a sweep); an interrupted render writes
// OUT.partial.exr and OUT.partial.png; a piece (--part, --pass) writes OUT.part2of4.exr.
void addRenderCommand(CLI::App& app);

}  // namespace columba
