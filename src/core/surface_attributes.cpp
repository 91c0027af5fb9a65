#include "core/surface_attributes.h"

#include <stdexcept>

#include "core/name_table.h"

namespace columba {

SurfaceAttributeKey::SurfaceAttributeKey(std::string_view name) {
  static NameTable names;
  slot_ = names.idOf(name);
  if (slot_ >= SurfaceAttributes::kCapacity)
    throw std::logic_error("more than SurfaceAttributes::kCapacity distinct attribute names");
}

}  // namespace columba
