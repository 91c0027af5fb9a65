#pragma once
// Reader for the feather PLY variant: every face is one barb, a polyline of exactly
// kBarbVertices vertices listed from the barb's base (at the rachis) to its tip.
//
//   element vertex N   float x y z, optional float H mu height (per-vertex barbule spacing,
//                      tilt and cortex thickness), the vane normal as out1 out2 out3 (or nx ny nz)
//   element face M     property list uchar int vertex_indices (any integer types)
//
// ASCII and binary_little_endian; one element per line in ASCII. Other properties and elements
// are skipped. Every problem is an InputError naming the file and the line (ASCII) or the
// element's index (binary).
#include <cstdint>
#include <string>
#include <vector>
#include "core/error.h"
#include "core/vector.h"

namespace columba {

inline constexpr int kBarbVertices = 64;
inline constexpr int kBarbSegments = kBarbVertices - 1;

struct FeatherPlyData {
  std::string path;
  std::vector<Vec3> positions;
  std::vector<Vec3> normals;  // unit
  // Per-vertex barbule parameters, each empty when the file does not have it.
  std::vector<float> barbuleH, barbuleMu, barbuleHeight;
  std::vector<uint32_t> barbIndices;  // kBarbVertices per barb
  int firstFaceLine = 0;              // ASCII: line of face 0; binary: 0

  size_t barbCount() const { return barbIndices.size() / kBarbVertices; }
  // Where barb `i` was declared, for errors found after loading.
  SourceLocation faceLocation(size_t i) const;
  // True when barb i is simply vertices [i * kBarbVertices, (i + 1) * kBarbVertices).
  bool barbsAreSequential() const;
};

FeatherPlyData readFeatherPly(const std::string& path);

}  // namespace columba
