#include "core/surface_attributes.h"

#include <stdexcept>

#include "core/name_table.h"

namespace columba {

namespace {
NameTable& attributeNames() {
  static NameTable names;
  return names;
}
}  // namespace

SurfaceAttributeKey::SurfaceAttributeKey(std::string_view name) {
  slot_ = attributeNames().idOf(name);
  if (slot_ >= SurfaceAttributes::kCapacity)
    throw std::logic_error("more than SurfaceAttributes::kCapacity distinct attribute names");
}

std::optional<SurfaceAttributeKey> SurfaceAttributeKey::find(std::string_view name) {
  const int slot = attributeNames().find(name);
  if (slot < 0) return std::nullopt;
  return SurfaceAttributeKey(slot);
}

std::string SurfaceAttributeKey::name() const { return attributeNames().nameOf(slot_); }

std::string SurfaceAttributes::names(const std::string& prefix) const {
  std::string out;
  for (int slot = 0; slot < kCapacity; ++slot)
    if (given_ >> slot & 1u) out += (out.empty() ? "" : ", ") + prefix + attributeNames().nameOf(slot);
  return out;
}

}  // namespace columba
