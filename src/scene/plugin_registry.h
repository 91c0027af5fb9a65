#pragma once
// Maps a scene element (tag, type), e.g. ("bsdf", "diffuse"), to the factory that builds it.
#include <functional>
#include <map>
#include <memory>
#include <string>
#include <utility>
#include "scene/properties.h"

namespace columba {

using PluginFactory = std::function<std::shared_ptr<Object>(const Properties&)>;

class PluginRegistry {
 public:
  void add(const std::string& tag, const std::string& type, PluginFactory factory) {
    factories_[{tag, type}] = std::move(factory);
  }
  const PluginFactory* find(const std::string& tag, const std::string& type) const {
    auto it = factories_.find({tag, type});
    return it == factories_.end() ? nullptr : &it->second;
  }
  // Every plug-in Columba ships (defined in builtin_plugins.cpp).
  static const PluginRegistry& builtin();

 private:
  std::map<std::pair<std::string, std::string>, PluginFactory> factories_;
};

// A built-in plug-in with all parameters at their defaults (e.g. the diffuse BSDF a shape gets
// when none is given), reported at `where`.
template <typename T>
std::shared_ptr<T> makeDefaultPlugin(const std::string& tag, const std::string& type, const SourceLocation& where) {
  Properties defaults;
  defaults.tag = tag;
  defaults.type = type;
  defaults.location = where;
  const PluginFactory* factory = PluginRegistry::builtin().find(tag, type);
  auto object = factory ? std::dynamic_pointer_cast<T>((*factory)(defaults)) : nullptr;
  if (!object) throw InputError(where, "no built-in " + tag + " plug-in '" + type + "'");
  return object;
}

}  // namespace columba
