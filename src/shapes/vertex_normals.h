#pragma once
// Smooth vertex normals for a triangle mesh whose file gives none, as Mitsuba makes them.
#include <cstdint>
#include <vector>
#include "core/vector.h"

namespace columba {

// Each vertex's normal is the sum of the unit normals of the triangles around it, each weighted
// by the triangle's angle at the vertex (Thürmer and Wüthrich 1998), normalised; so splitting a
// polygon into more triangles does not tilt it. Degenerate triangles add nothing; a vertex whose
// sum vanishes gets the zero vector, which shading treats as "no vertex normal".
std::vector<Vec3> angleWeightedVertexNormals(const std::vector<Vec3>& positions, const std::vector<uint32_t>& indices);

}  // namespace columba
