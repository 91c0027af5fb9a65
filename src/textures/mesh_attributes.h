#pragma once
// Values a mesh file carries per vertex or per face besides its geometry (a PLY's vertex colours,
// a face's weight), under Mitsuba's names: "vertex_<name>" and "face_<name>". The mesh_attribute
// texture reads them at a hit: per-vertex values interpolated with the hit's barycentric
// coordinates, per-face values as they are.
#include <cstdint>
#include <string>
#include <string_view>
#include <vector>
#include "core/spectrum.h"
#include "core/vector.h"

namespace columba {

// A mesh attribute's name ("vertex_color") resolved once to a number, the same for every mesh and
// texture of the program: a texture finds its attribute at each hit by comparing numbers.
class MeshAttributeKey {
 public:
  explicit MeshAttributeKey(std::string_view name);
  bool operator==(const MeshAttributeKey& o) const { return id_ == o.id_; }

 private:
  int id_;
};

class MeshAttributes {
 public:
  struct Attribute {
    std::string name;  // "vertex_color", "face_weight", ...
    MeshAttributeKey key;
    bool perVertex;                    // a "vertex_" attribute, else a "face_" one
    int channels = 1;                  // 1 or 3
    std::vector<float> values;         // channels per vertex or per triangle
    std::vector<RGBSpectrum> spectra;  // per vertex or triangle, for 3-channel attributes (colours)
    // The mean over the file's vertices or faces, as a number (a colour's spectrum's mean over
    // the visible range): what a BSDF choosing between lobes with fixed probabilities weighs by.
    float mean = 0.0f;
  };

  // Adds an attribute named "vertex_..." or "face_..."; a 3-channel one is a colour, whose spectra
  // are fitted here (one fit per distinct colour).
  void add(std::string name, int channels, std::vector<float> values);
  // The mesh's index buffer (3 per triangle), which per-vertex attributes are interpolated over;
  // the mesh that owns both keeps it alive.
  void setTriangles(const std::vector<uint32_t>& indices) { indices_ = indices.data(); }
  // Per-face values of a mesh whose polygons were split into triangles: `triangleFace[t]` is the
  // file's face that triangle t came from, so every face attribute gets one value per triangle.
  void expandFacesToTriangles(const std::vector<uint32_t>& triangleFace);

  bool empty() const { return attributes_.empty(); }
  // The attribute of that name, or null.
  const Attribute* find(const MeshAttributeKey& key) const;
  // The names held, for error messages ("vertex_color, face_weight", or "none").
  std::string names() const;

  // Value of `a` in triangle `triangle` at barycentric coordinates `b` (the weights of the
  // triangle's second and third vertex): as a number (1-channel values, or a colour's luminance
  // Y), and as a spectrum at the path's wavelengths (a number is constant over wavelength).
  float evalFloat(const Attribute& a, uint32_t triangle, Vec2 b) const;
  Spectrum evalSpectrum(const Attribute& a, uint32_t triangle, Vec2 b, const Wavelengths& wl) const;
  // The values as stored, interpolated (a 1-channel value repeated three times).
  Vec3 evalTriple(const Attribute& a, uint32_t triangle, Vec2 b) const;

 private:
  // The elements (vertices or triangles) a point of `triangle` reads and their weights.
  int footprint(const Attribute& a, uint32_t triangle, Vec2 b, uint32_t element[3], float weight[3]) const;
  float numberOf(const Attribute& a, uint32_t element) const;

  std::vector<Attribute> attributes_;
  const uint32_t* indices_ = nullptr;
};

}  // namespace columba
