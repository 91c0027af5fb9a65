#pragma once
// Maps a scene element (tag, type), e.g. ("bsdf", "diffuse"), to the factory that builds it.
#include <functional>
#include <map>
#include <memory>
#include <string>
#include <utility>
#include "core/properties.h"

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

 private:
  std::map<std::pair<std::string, std::string>, PluginFactory> factories_;
};

}  // namespace columba
