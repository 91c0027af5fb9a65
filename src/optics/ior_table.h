#pragma once
// Named indices of refraction, as Mitsuba accepts them for `int_ior` / `ext_ior`.
#include <optional>
#include <string>

namespace columba {

// nullopt for an unknown name.
std::optional<float> lookupIOR(const std::string& name);

}  // namespace columba
