#include "shapes/ply_attributes.h"

#include <array>
#include <limits>

#include "io/image.h"

namespace columba {

namespace {

// Suffix sets that group consecutive properties, each with the optional fourth one that follows.
const std::array<std::array<const char*, 4>, 4> kGroupSuffixes = {{
    {"x", "y", "z", "w"},
    {"r", "g", "b", "a"},
    {"0", "1", "2", "3"},
    {"1", "2", "3", "4"},
}};

// Whether the properties from `i` are `names[0..2]` in order (any may be taken), and if a fourth,
// `fourth`, follows.
bool matchesAt(const PlyElement& e, size_t i, const std::array<std::string, 3>& names, const std::string& fourth,
               size_t& consumed) {
  if (i + 3 > e.properties.size()) return false;
  for (size_t k = 0; k < 3; ++k)
    if (e.properties[i + k].isList || e.properties[i + k].name != names[k]) return false;
  consumed = 3;
  if (i + 3 < e.properties.size() && !e.properties[i + 3].isList && e.properties[i + 3].name == fourth) consumed = 4;
  return true;
}

// Whether property `i`, named `stem` and a set's first suffix, is a component on its own: the next
// property is not that set's second one. Mitsuba names such a one-channel attribute by its stem
// ("weight_0" is "face_weight").
bool startsLoneComponent(const PlyElement& e, size_t i, const std::string& stem) {
  const std::string suffix = e.properties[i].name.substr(stem.size());
  for (const auto& suffixes : kGroupSuffixes)
    if (suffix == suffixes[0]) return i + 1 == e.properties.size() || e.properties[i + 1].name != stem + suffixes[1];
  return false;
}

}  // namespace

std::vector<PlyAttributeGroup> plyAttributeGroups(const PlyElement& e, const std::string& prefix,
                                                  const std::unordered_set<std::string>& reserved) {
  std::vector<PlyAttributeGroup> groups;
  for (size_t i = 0; i < e.properties.size();) {
    const PlyProperty& p = e.properties[i];
    if (p.isList || reserved.count(p.name)) {
      ++i;
      continue;
    }
    size_t consumed = 0;
    std::string name;
    if (matchesAt(e, i, {"r", "g", "b"}, "a", consumed) ||
        matchesAt(e, i, {"red", "green", "blue"}, "alpha", consumed)) {
      name = "color";
    } else if (const size_t underscore = p.name.rfind('_'); underscore != std::string::npos && underscore > 0) {
      const std::string stem = p.name.substr(0, underscore + 1);
      for (const auto& suffixes : kGroupSuffixes)
        if (matchesAt(e, i, {stem + suffixes[0], stem + suffixes[1], stem + suffixes[2]}, stem + suffixes[3],
                      consumed)) {
          name = p.name.substr(0, underscore);
          break;
        }
      if (consumed == 0 && startsLoneComponent(e, i, stem)) name = p.name.substr(0, underscore);
    }
    PlyAttributeGroup g;
    if (consumed > 0) {
      g.name = prefix + name;
      g.properties = {int(i), int(i + 1), int(i + 2)};
      i += consumed;
    } else {
      g.name = prefix + (name.empty() ? p.name : name);
      g.properties = {int(i)};
      ++i;
    }
    groups.push_back(std::move(g));
  }
  return groups;
}

float plyAttributeValue(double value, PlyType type) {
  double largest = 0;
  switch (type) {
    case PlyType::Int8:
      largest = std::numeric_limits<int8_t>::max();
      break;
    case PlyType::UInt8:
      largest = std::numeric_limits<uint8_t>::max();
      break;
    case PlyType::Int16:
      largest = std::numeric_limits<int16_t>::max();
      break;
    case PlyType::UInt16:
      largest = std::numeric_limits<uint16_t>::max();
      break;
    case PlyType::Int32:
      largest = std::numeric_limits<int32_t>::max();
      break;
    case PlyType::UInt32:
      largest = std::numeric_limits<uint32_t>::max();
      break;
    case PlyType::Float32:
    case PlyType::Float64:
      return float(value);
  }
  return srgbToLinear(float(value / largest));
}

}  // namespace columba
