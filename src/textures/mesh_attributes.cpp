#include "textures/mesh_attributes.h"

#include <stdexcept>

#include "core/name_table.h"
#include "textures/fitted_colours.h"

namespace columba {

MeshAttributeKey::MeshAttributeKey(std::string_view name) {
  static NameTable names;
  id_ = names.idOf(name);
}

void MeshAttributes::add(std::string name, int channels, std::vector<float> values) {
  if (channels != 1 && channels != 3) throw std::logic_error("a mesh attribute has 1 or 3 channels");
  const bool perVertex = name.rfind("vertex_", 0) == 0;
  if (!perVertex && name.rfind("face_", 0) != 0)
    throw std::logic_error("a mesh attribute's name starts with vertex_ or face_");
  const MeshAttributeKey key(name);
  Attribute a{std::move(name), key, perVertex, channels, std::move(values), {}, 0.0f};
  if (channels == 3) {
    std::vector<Vec3> colours(a.values.size() / 3);
    for (size_t i = 0; i < colours.size(); ++i)
      colours[i] = Vec3(a.values[3 * i], a.values[3 * i + 1], a.values[3 * i + 2]);
    FittedColours fitted = fitColourSpectra(colours);
    a.spectra = std::move(fitted.spectra);
    a.mean = fitted.mean;
  } else {
    double sum = 0;
    for (float v : a.values) sum += v;
    a.mean = a.values.empty() ? 0.0f : float(sum / double(a.values.size()));
  }
  attributes_.push_back(std::move(a));
}

void MeshAttributes::expandFacesToTriangles(const std::vector<uint32_t>& triangleFace) {
  for (Attribute& a : attributes_) {
    if (a.perVertex) continue;
    std::vector<float> values;
    std::vector<RGBSpectrum> spectra;
    values.reserve(triangleFace.size() * size_t(a.channels));
    for (uint32_t face : triangleFace) {
      for (int c = 0; c < a.channels; ++c) values.push_back(a.values[size_t(face) * size_t(a.channels) + size_t(c)]);
      if (!a.spectra.empty()) spectra.push_back(a.spectra[face]);
    }
    a.values = std::move(values);
    a.spectra = std::move(spectra);
  }
}

const MeshAttributes::Attribute* MeshAttributes::find(const MeshAttributeKey& key) const {
  for (const Attribute& a : attributes_)
    if (a.key == key) return &a;
  return nullptr;
}

std::string MeshAttributes::names() const {
  std::string list;
  for (const Attribute& a : attributes_) list += (list.empty() ? "" : ", ") + a.name;
  return list.empty() ? "none" : list;
}

int MeshAttributes::footprint(const Attribute& a, uint32_t triangle, Vec2 b, uint32_t element[3],
                              float weight[3]) const {
  if (!a.perVertex) {
    element[0] = triangle;
    weight[0] = 1.0f;
    return 1;
  }
  const uint32_t* idx = indices_ + 3 * size_t(triangle);
  element[0] = idx[0], element[1] = idx[1], element[2] = idx[2];
  weight[0] = 1.0f - b.x - b.y, weight[1] = b.x, weight[2] = b.y;
  return 3;
}

float MeshAttributes::numberOf(const Attribute& a, uint32_t element) const {
  const float* v = &a.values[size_t(element) * size_t(a.channels)];
  return a.channels == 1 ? v[0] : linearRGBToXYZ(Vec3(v[0], v[1], v[2])).y;
}

float MeshAttributes::evalFloat(const Attribute& a, uint32_t triangle, Vec2 b) const {
  uint32_t element[3];
  float weight[3];
  const int n = footprint(a, triangle, b, element, weight);
  float result = 0.0f;
  for (int k = 0; k < n; ++k) result += weight[k] * numberOf(a, element[k]);
  return result;
}

Spectrum MeshAttributes::evalSpectrum(const Attribute& a, uint32_t triangle, Vec2 b, const Wavelengths& wl) const {
  if (a.channels == 1) return Spectrum(evalFloat(a, triangle, b));
  uint32_t element[3];
  float weight[3];
  const int n = footprint(a, triangle, b, element, weight);
  Spectrum result(0.0f);
  for (int k = 0; k < n; ++k) {
    const RGBSpectrum& s = a.spectra[element[k]];
    for (int i = 0; i < kSpectrumSamples; ++i) result[i] += weight[k] * s.eval(wl[i]);
  }
  return result;
}

Vec3 MeshAttributes::evalTriple(const Attribute& a, uint32_t triangle, Vec2 b) const {
  uint32_t element[3];
  float weight[3];
  const int n = footprint(a, triangle, b, element, weight);
  Vec3 result(0, 0, 0);
  for (int k = 0; k < n; ++k) {
    const float* v = &a.values[size_t(element[k]) * size_t(a.channels)];
    result += (a.channels == 1 ? Vec3(v[0], v[0], v[0]) : Vec3(v[0], v[1], v[2])) * weight[k];
  }
  return result;
}

}  // namespace columba
