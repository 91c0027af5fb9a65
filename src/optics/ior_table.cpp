#include "optics/ior_table.h"

#include <map>

namespace columba {

std::optional<float> lookupIOR(const std::string& name) {
  static const std::map<std::string, float> table = {
      {"vacuum", 1.0f},      {"helium", 1.000036f},        {"hydrogen", 1.000132f},
      {"air", 1.000277f},    {"carbon dioxide", 1.00045f}, {"water", 1.3330f},
      {"acetone", 1.36f},    {"ethanol", 1.361f},          {"carbon tetrachloride", 1.461f},
      {"glycerol", 1.4729f}, {"benzene", 1.501f},          {"silicone oil", 1.52045f},
      {"bromine", 1.661f},   {"water ice", 1.31f},         {"fused quartz", 1.458f},
      {"pyrex", 1.470f},     {"acrylic glass", 1.49f},     {"polypropylene", 1.49f},
      {"bk7", 1.5046f},      {"sodium chloride", 1.544f},  {"amber", 1.55f},
      {"pet", 1.5750f},      {"diamond", 2.419f}};
  auto it = table.find(name);
  if (it == table.end()) return std::nullopt;
  return it->second;
}

}  // namespace columba
