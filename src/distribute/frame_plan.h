#pragma once
// The frames of a render: its sweeps expanded, every frame's -D values and image file, planned
// before any scene is loaded so that every mistake is reported before the first frame.
#include <map>
#include <string>
#include <vector>

#include "distribute/sweep.h"

namespace columba {

// What a render's frames are planned from: the options `columba render` and `columba slurm` share.
struct FrameRequest {
  std::string scenePath;             // "" for the built-in scene
  std::string sceneText;             // the scene file's text (or the built-in scene's), for its hash
  std::vector<std::string> defines;  // -D name=value
  std::vector<std::string> sweeps;   // --sweep specifications
  std::string framesPattern;         // --frames, or ""
  std::string output;                // -o, or "" for the scene's name in the working directory
};

struct FramePlan {
  std::map<std::string, std::string> defines;  // the -D given
  std::vector<SweepAxis> axes;
  std::vector<SweepFrame> frames;
  std::vector<std::string> files;  // each frame's image
  std::string sceneHash;           // of the scene's text
  // The -D values of frame f.
  std::map<std::string, std::string> frameDefines(int f) const;
};

// Throws std::runtime_error for a bad -D, sweep, pattern or output name.
FramePlan planFrames(const FrameRequest& request);

// The image a render writes without -o: SCENE.exr in the working directory (default.exr for the
// built-in scene).
std::string defaultOutput(const std::string& scenePath);

// "name=value" lines, as images and manifests record their defines.
std::string describeDefines(const std::map<std::string, std::string>& defines);

}  // namespace columba
