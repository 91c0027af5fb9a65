#pragma once
// Parameter sweeps: `--sweep NAME=START:STOP:STEP` or `--sweep NAME=v1,v2,...`; several sweeps
// form a grid (the first one given varies slowest). Each frame of the sweep is one render with
// `-D NAME=value` for every swept name.
#include <string>
#include <utility>
#include <vector>

namespace columba {

struct SweepAxis {
  std::string name;
  std::vector<std::string> values;  // as given to -D
  std::string spec;                 // the text it was parsed from
};

// "NAME=START:STOP:STEP": START, START + STEP, ... up to STOP inclusive (within round-off of the
// step), each value written with as many decimals as the three numbers have, without trailing
// zeros ("0:1:0.25" gives 0, 0.25, 0.5, 0.75, 1). "NAME=v1,v2,...": the values as written (any
// text, such as file names). "NAME=v": one value. Throws std::runtime_error naming the problem.
SweepAxis parseSweep(const std::string& text);

struct SweepFrame {
  int index = 0;                                            // 0-based, in grid order
  std::vector<std::pair<std::string, std::string>> values;  // (name, value) in the order of the axes
};

// Every combination of the axes' values, the first axis varying slowest; one frame without
// values when there are no axes. Throws when names repeat or the grid exceeds 1,000,000 frames.
std::vector<SweepFrame> expandSweeps(const std::vector<SweepAxis>& axes);

// A frame's image file. From a render's output OUT.exr: OUT_<name>=<value>_....exr (values made
// safe for a file name: characters other than letters, digits and . + - , = become _); the
// output itself when the frame has no values. From a --frames pattern: "%d" (or "%03d", "%5d",
// ...) is the frame index, "{name}" a swept value as given and "{name:spec}" the value
// formatted by a {fmt} spec ("{angle:03}" writes -10, 000, 010); "%%", "{{" and "}}" are
// literal. Throws std::runtime_error for a malformed pattern, an unknown name, or a width or
// precision above 255 (the longest file name).
std::string frameFileFromOutput(const std::string& output, const SweepFrame& frame);
std::string frameFileFromPattern(const std::string& pattern, const SweepFrame& frame);
// The frames' files (from the pattern if it is not empty, else from the output); throws if two
// frames would get the same file, or if a file's name or path is longer than Linux allows (255
// and 4,095 bytes).
std::vector<std::string> frameFiles(const std::string& output, const std::string& pattern,
                                    const std::vector<SweepFrame>& frames);

}  // namespace columba
