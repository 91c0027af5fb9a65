#pragma once
// Reads the Mitsuba 2/3 XML scene dialect into plug-in objects.
#include <map>
#include <memory>
#include <string>
#include <vector>
#include "scene/plugin_registry.h"

namespace columba {

// The top-level plug-ins of a <scene>, in document order (shapes, emitters, sensor, ...).
struct ParsedScene {
  std::vector<std::shared_ptr<Object>> objects;
  std::vector<std::string> unusedDefines;  // -D names that no $variable of the scene used
};

using Defines = std::map<std::string, std::string>;

// `defines` are the -D name=value pairs; they override <default>s. Throws InputError with
// file:line for every malformed input.
ParsedScene loadSceneFile(const std::string& path, const Defines& defines, const PluginRegistry& registry);
// `sourceName` names the text in messages; `baseDir` stands for the scene file's directory.
ParsedScene loadSceneString(const std::string& xml, const std::string& sourceName, const std::string& baseDir,
                            const Defines& defines, const PluginRegistry& registry);

}  // namespace columba
