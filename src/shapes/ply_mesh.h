#pragma once
// Mitsuba's `ply` shape: a triangle mesh read from a PLY file.
//
//   element vertex N   x y z, optional normals nx ny nz, optional texture coordinates
//                      u v (or s t, or texture_u texture_v); any scalar types
//   element face M     list vertex_indices (or vertex_index) of 3 or more vertices each;
//                      polygons are triangulated as fans around their first vertex
//
// ASCII and binary_little_endian; other properties and elements are skipped. Every problem is
// an InputError naming the file and the line (ASCII) or the element's index (binary).
#include <memory>
#include <string>
#include "core/properties.h"
#include "shapes/triangle_mesh.h"

namespace columba {

MeshData readPlyMesh(const std::string& path);

// <shape type="ply">: its parameters are in docs/reference/shapes.md.
std::shared_ptr<Object> makePlyShape(const Properties& props);

}  // namespace columba
