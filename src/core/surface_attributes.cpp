#include "core/surface_attributes.h"

#include <mutex>
#include <stdexcept>
#include <string>
#include <vector>

namespace columba {

SurfaceAttributeKey::SurfaceAttributeKey(std::string_view name) {
  // Keys are made while scenes are built (or at start-up), never per ray.
  static std::mutex mutex;
  static std::vector<std::string> names;
  std::lock_guard<std::mutex> lock(mutex);
  for (size_t i = 0; i < names.size(); ++i)
    if (names[i] == name) {
      slot_ = int(i);
      return;
    }
  if (names.size() == size_t(SurfaceAttributes::kCapacity))
    throw std::logic_error("more than SurfaceAttributes::kCapacity distinct attribute names");
  names.emplace_back(name);
  slot_ = int(names.size() - 1);
}

}  // namespace columba
