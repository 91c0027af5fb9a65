#pragma once
// Mitsuba's `serialized` shape: one triangle mesh of a Mitsuba serialized file.
//
// The file (little endian) holds meshes one after another, each a uint16 0x041C, a uint16
// version (3 or 4) and a zlib stream: uint32 flags, (version 4) the mesh's name ending in a NUL,
// uint64 vertex and triangle counts, then per vertex positions, and as the flags say normals,
// texture coordinates and colours (float, or double with flag 0x2000), then uint32 indices
// (uint64 above 2^32 vertices). The file ends with each mesh's byte offset (uint64 in version 4,
// uint32 in version 3) and a uint32 mesh count. Flag 0x0010 asks for face normals.
#include <memory>
#include <string>
#include "core/properties.h"
#include "shapes/triangle_mesh.h"

namespace columba {

struct SerializedMesh {
  MeshData mesh;
  bool faceNormals = false;  // the file's flag 0x0010
};

// Mesh number `shapeIndex` (from 0) of the file `name`, whose bytes are `bytes`. Every problem is
// an InputError naming the file, the mesh and what is wrong; counts are checked against what the
// compressed data can hold before anything is allocated.
SerializedMesh parseSerializedMesh(const std::string& bytes, int shapeIndex, const std::string& name);
SerializedMesh readSerializedMesh(const std::string& path, int shapeIndex);

// <shape type="serialized">: its parameters are in docs/reference/shapes.md.
std::shared_ptr<Object> makeSerializedShape(const Properties& props);

}  // namespace columba
