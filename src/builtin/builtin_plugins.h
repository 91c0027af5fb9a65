#pragma once
// The program's composition root: the one place that knows every plug-in Columba ships.
#include "scene/plugin_registry.h"

namespace columba {

// Every built-in plug-in, by scene element and type name.
const PluginRegistry& builtinPlugins();

}  // namespace columba
