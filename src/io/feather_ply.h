#pragma once
// Reader for the feather PLY variant: every face is one barb, a polyline of exactly
// kBarbVertices vertices listed from the barb's base (at the rachis) to its tip.
//
//   comment barbwidth W  optional: the barb width the barbs were laid out for (PLY units)
//   element vertex N   float x y z, optional float H mu height (per-vertex barbule spacing,
//                      tilt and cortex thickness, in the file convention of
//                      feather_barbule_values.h), optional stack (the barbule BSDF's layer
//                      stack, a whole number), the vane normal as out1 out2 out3 (or nx ny nz)
//   element face M     property list uchar int vertex_indices (any integer types)
//
// ASCII and binary_little_endian; one element per line in ASCII. Other properties and elements
// are skipped. H, mu and height are used only all together, as the original implementation
// reads them (a warning names the file when some are missing, and none is used); H must be
// positive and height not negative. Every problem is an InputError naming the file and the line
// (ASCII) or the element's index (binary), and the value.
#include <cstdint>
#include <optional>
#include <string>
#include <vector>
#include "core/error.h"
#include "core/vector.h"

namespace columba {

inline constexpr int kBarbVertices = 64;
inline constexpr int kBarbSegments = kBarbVertices - 1;
// The largest layer stack a vertex may choose; the BSDF decides which it has.
inline constexpr int kMaxVertexLayerStack = 255;

struct FeatherPlyData {
  std::string path;
  std::vector<Vec3> positions;
  std::vector<Vec3> normals;  // unit
  // Per-vertex barbule values as the file gives them; all three empty when it has not all three.
  std::vector<float> barbuleH, barbuleMu, barbuleHeight;
  // Per-vertex layer stack (0 to kMaxVertexLayerStack), empty when the file gives none; the
  // largest a barb's vertex chooses (-1: none), the first vertex choosing it and that vertex's
  // line (ASCII; 0 in binary files).
  std::vector<uint8_t> layerStack;
  int largestLayerStack = -1;
  size_t largestLayerStackVertex = 0;
  int largestLayerStackLine = 0;
  // From a `comment barbwidth W` header line.
  std::optional<float> barbWidth;
  std::vector<uint32_t> barbIndices;  // kBarbVertices per barb
  int firstFaceLine = 0;              // ASCII: line of face 0; binary: 0
  int firstVertexLine = 0;            // ASCII: line of vertex 0; binary: 0

  size_t barbCount() const { return barbIndices.size() / kBarbVertices; }
  bool hasBarbuleValues() const { return !barbuleH.empty(); }
  // Where barb `i` was declared, for errors found after loading.
  SourceLocation faceLocation(size_t i) const;
  // True when barb i is simply vertices [i * kBarbVertices, (i + 1) * kBarbVertices).
  bool barbsAreSequential() const;
};

FeatherPlyData readFeatherPly(const std::string& path);

// The header comment that records the barb width a file was made for.
inline constexpr const char* kBarbWidthComment = "barbwidth";

}  // namespace columba
