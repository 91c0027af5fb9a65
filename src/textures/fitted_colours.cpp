#include "textures/fitted_colours.h"

#include <tbb/parallel_for.h>

#include <algorithm>
#include <cstring>
#include <unordered_map>

namespace columba {

namespace {
// A colour's bits, so that equal colours share a fit.
struct ColourKey {
  uint32_t bits[3];
  bool operator==(const ColourKey& o) const { return std::memcmp(bits, o.bits, sizeof bits) == 0; }
};
struct ColourKeyHash {
  size_t operator()(const ColourKey& k) const {
    return (size_t(k.bits[0]) * 0x9E3779B97F4A7C15ull) ^ (size_t(k.bits[1]) * 0xC2B2AE3D27D4EB4Full) ^ k.bits[2];
  }
};
ColourKey keyOf(const Vec3& c) {
  ColourKey k;
  std::memcpy(&k.bits[0], &c.x, 4);
  std::memcpy(&k.bits[1], &c.y, 4);
  std::memcpy(&k.bits[2], &c.z, 4);
  return k;
}
}  // namespace

FittedColours fitColourSpectra(const std::vector<Vec3>& colours) {
  std::unordered_map<ColourKey, uint32_t, ColourKeyHash> indexOf;
  std::vector<Vec3> distinct;
  std::vector<uint32_t> colourIndex(colours.size());
  for (size_t i = 0; i < colours.size(); ++i) {
    auto [it, added] = indexOf.emplace(keyOf(colours[i]), uint32_t(distinct.size()));
    if (added) distinct.push_back(colours[i]);
    colourIndex[i] = it->second;
  }
  std::vector<RGBSpectrum> fitted(distinct.size());
  std::vector<float> fittedMean(distinct.size());
  tbb::parallel_for(size_t(0), distinct.size(), [&](size_t i) {
    const Vec3& c = distinct[i];
    fitted[i] = fitRGBSpectrum(c, std::max(c.x, std::max(c.y, c.z)) > 1.0f);
    fittedMean[i] = fitted[i].meanValue();
  });
  FittedColours result;
  result.spectra.resize(colours.size());
  double sum = 0;
  for (size_t i = 0; i < colours.size(); ++i) {
    result.spectra[i] = fitted[colourIndex[i]];
    sum += fittedMean[colourIndex[i]];
  }
  result.mean = colours.empty() ? 0.0f : float(sum / double(colours.size()));
  return result;
}

}  // namespace columba
