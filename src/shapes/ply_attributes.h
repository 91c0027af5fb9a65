#pragma once
// A PLY element's further properties as mesh attributes, named as Mitsuba's PLY loader names them:
// consecutive properties {prefix}_x/y/z, {prefix}_r/g/b, {prefix}_0/1/2 or {prefix}_1/2/3 make one
// 3-channel attribute "{vertex|face}_{prefix}", and r/g/b or red/green/blue make
// "{vertex|face}_color"; a fourth component that follows (w, a, alpha, 3 or 4) is read past and not
// kept, as Columba's attributes have 1 or 3 channels. A lone first component ({prefix}_x, _r, _0 or
// _1 not followed by the second) is the 1-channel attribute "{vertex|face}_{prefix}", as Mitsuba
// writes and reads one; any other scalar property is a 1-channel attribute "{vertex|face}_{name}". As in Mitsuba, integer values are divided by their type's
// largest value and decoded from sRGB (8-bit colours), floats are kept as they are.
#include <string>
#include <unordered_set>
#include <vector>
#include "io/ply_file.h"

namespace columba {

struct PlyAttributeGroup {
  std::string name;             // "vertex_color"
  std::vector<int> properties;  // 1 or 3 property indices of the element
};

// The attributes of element `e` ("vertex_" or "face_" as `prefix`), skipping `reserved` names and
// list properties.
std::vector<PlyAttributeGroup> plyAttributeGroups(const PlyElement& e, const std::string& prefix,
                                                  const std::unordered_set<std::string>& reserved);

// A property's value as an attribute value: integers normalised and decoded from sRGB.
float plyAttributeValue(double value, PlyType type);

}  // namespace columba
