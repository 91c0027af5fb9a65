#pragma once
#include <CLI/CLI.hpp>
#include <map>
#include <string>
#include <vector>

#include "distribute/sweep.h"
#include "scene/scene_loader.h"

namespace columba {

// `columba render [SCENE.xml] [-o OUT.exr|OUT.png] [-D name=value]... [--spp N] [--threads N] [--seed S]
//                 [--sweep NAME=START:STOP:STEP|NAME=v1,v2,...]... [--frames PATTERN] [--frame I]
//                 [--part K/N] [--pass K/N] [--manifest FILE]`
// writes OUT.exr and OUT.png (one pair per frame of a sweep); an interrupted render writes
// OUT.partial.exr and OUT.partial.png; a piece (--part, --pass) writes OUT.part2of4.exr.
void addRenderCommand(CLI::App& app);

// What a render is of: the options `columba render` and `columba slurm` share.
struct SceneOptions {
  std::string scenePath;
  std::vector<std::string> defines;
  std::string spp;  // checked by parseCount, so that every value gets the same message
  uint64_t seed = 0;
  bool spectral = false;  // radiance per wavelength bin in the EXR besides RGB
  std::string bins = "16";
  std::vector<std::string> sweeps;
  std::string framesPattern;
};
void addSceneOptions(CLI::App* command, SceneOptions& options);

// The frames of a render: the sweeps expanded, every frame's -D values and image file.
struct FramePlan {
  std::map<std::string, std::string> defines;  // the -D given
  std::vector<SweepAxis> axes;
  std::vector<SweepFrame> frames;
  std::vector<std::string> files;  // each frame's image
  std::string sceneHash;           // of the scene file's text (or the built-in scene's)
  // The -D values of frame f.
  std::map<std::string, std::string> frameDefines(int f) const;
};
// `output` is -o (or "" for the scene's name in the working directory); throws std::runtime_error
// for a bad sweep, pattern, output name or scene path, before any work.
FramePlan planFrames(const SceneOptions& options, const std::string& output);
// A frame's scene with its -D values (`defines`), loaded as `columba render` loads it (the
// built-in scene when options.scenePath is empty), and the name messages give it.
ParsedScene loadFrameScene(const SceneOptions& options, const Defines& defines);
SourceLocation frameSceneSource(const SceneOptions& options);
// "name=value" lines, as images record their defines.
std::string describeDefines(const std::map<std::string, std::string>& defines);
// A whole number given for `option`, or 0 if it was not given.
int parseCount(const char* option, const std::string& text, int lowest, int highest);

}  // namespace columba
