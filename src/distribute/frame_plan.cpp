#include "distribute/frame_plan.h"

#include <fmt/format.h>

#include <filesystem>
#include <stdexcept>

#include "distribute/pieces.h"

namespace columba {

namespace {

std::map<std::string, std::string> parseDefines(const std::vector<std::string>& items) {
  std::map<std::string, std::string> defines;
  for (const std::string& item : items) {
    size_t eq = item.find('=');
    if (eq == std::string::npos || eq == 0) throw std::runtime_error("-D expects name=value, got '" + item + "'");
    defines[item.substr(0, eq)] = item.substr(eq + 1);
  }
  return defines;
}

}  // namespace

std::map<std::string, std::string> FramePlan::frameDefines(int f) const {
  std::map<std::string, std::string> all = defines;
  for (const auto& [name, value] : frames[size_t(f)].values) all[name] = value;
  return all;
}

FramePlan planFrames(const FrameRequest& request) {
  FramePlan plan;
  plan.defines = parseDefines(request.defines);
  for (const std::string& spec : request.sweeps) {
    plan.axes.push_back(parseSweep(spec));
    if (plan.defines.count(plan.axes.back().name))
      throw std::runtime_error(
          fmt::format("-D {0}=... and --sweep {0}=... both set ${0}; give one of them", plan.axes.back().name));
  }
  plan.frames = expandSweeps(plan.axes);
  plan.files = frameFiles(request.output.empty() ? defaultOutput(request.scenePath) : request.output,
                          request.framesPattern, plan.frames);
  plan.sceneHash = textHash(request.sceneText);
  return plan;
}

std::string defaultOutput(const std::string& scenePath) {
  return (scenePath.empty() ? std::string("default") : std::filesystem::path(scenePath).stem().string()) + ".exr";
}

std::string describeDefines(const std::map<std::string, std::string>& defines) {
  std::string text;
  for (const auto& [name, value] : defines) text += (text.empty() ? "" : "\n") + name + "=" + value;
  return text;
}

}  // namespace columba
