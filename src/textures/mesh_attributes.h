#pragma once
// Values a mesh file carries per vertex or per face besides its geometry (a PLY's vertex colours,
// a face's weight), under Mitsuba's names: "vertex_<name>" and "face_<name>". The mesh_attribute
// texture reads them at a hit: per-vertex values interpolated with the hit's barycentric
// coordinates, per-face values as they are.
#include <cstdint>
#include <string>
#include <vector>
#include "core/spectrum.h"
#include "core/vector.h"

namespace columba {

class MeshAttributes {
 public:
  struct Attribute {
    std::string name;                  // "vertex_color", "face_weight", ...
    int channels = 1;                  // 1 or 3
    std::vector<float> values;         // channels per vertex or per triangle
    std::vector<RGBSpectrum> spectra;  // per vertex or triangle, for 3-channel attributes (colours)
    // The mean over the file's vertices or faces, as a number (a colour's spectrum's mean over
    // the visible range): what a BSDF choosing between lobes with fixed probabilities weighs by.
    float mean = 0.0f;
    bool perVertex() const { return name.rfind("vertex_", 0) == 0; }
  };

  // Adds an attribute (its spectra are fitted here, one fit per distinct colour).
  // `triangles` is the mesh's index buffer, which per-vertex attributes are interpolated over.
  void add(std::string name, int channels, std::vector<float> values);
  void setTriangles(std::vector<uint32_t> indices) { indices_ = std::move(indices); }
  // Per-face values of a mesh whose polygons were split into triangles: `triangleFace[t]` is the
  // file's face that triangle t came from, so every face attribute gets one value per triangle.
  void expandFacesToTriangles(const std::vector<uint32_t>& triangleFace);

  bool empty() const { return attributes_.empty(); }
  // The attribute called `name`, or null.
  const Attribute* find(const std::string& name) const;
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
  std::vector<uint32_t> indices_;
};

}  // namespace columba
