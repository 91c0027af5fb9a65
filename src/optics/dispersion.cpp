#include "optics/dispersion.h"

#include <cmath>
#include <cstdlib>
#include "optics/ior_table.h"

namespace columba {

std::optional<CauchyIOR> iorFromName(const std::string& name) {
  if (name == "keratin") return CauchyIOR::keratin();
  if (auto named = lookupIOR(name)) return CauchyIOR::constant(*named);
  // Mitsuba also accepts the index itself in a string parameter.
  char* end = nullptr;
  float value = std::strtof(name.c_str(), &end);
  if (!name.empty() && end == name.c_str() + name.size() && std::isfinite(value) && value > 0.0f)
    return CauchyIOR::constant(value);
  return std::nullopt;
}

}  // namespace columba
