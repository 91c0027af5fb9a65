#pragma once
// Mitsuba's `obj` shape: a triangle mesh read from a Wavefront OBJ file (tinyobjloader).
//
// `v`, `vn`, `vt` and `f` statements are used; every number must be finite and within float
// range, every face corner's position, normal and texture index must exist. Triangles are kept,
// quads are split along their shorter diagonal and larger polygons are triangulated as fans
// around their first corner. Corners with the same position, texture and normal indices are one
// mesh vertex (as in Mitsuba), so faces share the smooth normals computed where the file has
// none. Every problem is an InputError naming the file and line, and for faces the face's
// number (counting from 1 in file order).
#include <memory>
#include <string>
#include "core/properties.h"
#include "shapes/triangle_mesh.h"

namespace columba {

MeshData readObjMesh(const std::string& path);

// <shape type="obj">: its parameters are in docs/reference/shapes.md.
std::shared_ptr<Object> makeObjShape(const Properties& props);

}  // namespace columba
