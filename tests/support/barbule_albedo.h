#pragma once
// Independent quadratures of the barbule lobes' directional reflectance (albedo), shared by the
// BSDF's white furnace tests and the measurement tests.
#include <array>
#include <cmath>
#include <vector>
#include "barbule/normals.h"
#include "barbule/parameters.h"
#include "barbule/point_model.h"

namespace columba::testing {

struct LobeAlbedo {
  Spectrum reflection, trt;
};

// Integral over omega_o of each lobe's f |cos theta_o| (`lobes(omega_o)` giving the lobes for the
// light's omega_i `wi`), by the midpoint rule on an equal-area grid around the barbule axis, in
// double: fine in t . omega_o over the band the R lobe can reach (|t . (omega_i + omega_o)| <=
// 2 sin(thetaD)), `rRows` x `rColumns`, coarser for TRT over the whole sphere; over each of
// `regions` parts of the sphere, `regionOf(omega_o)` naming the part.
template <typename Lobes, typename RegionOf>
std::vector<LobeAlbedo> integrateLobeGrid(const Lobes& lobes, const Vec3& wi, int regions, const RegionOf& regionOf,
                                          int rRows = 1024, int rColumns = 2304) {
  std::vector<LobeAlbedo> out(static_cast<size_t>(regions));
  auto grid = [&](float yLo, float yHi, int rows, int columns, bool reflection) {
    // millions of terms: float sums would drift
    std::vector<std::array<double, kSpectrumSamples>> sum(size_t(regions), std::array<double, kSpectrumSamples>{});
    double cell = (yHi - yLo) / rows * (2.0 * M_PI / columns);
    for (int i = 0; i < rows; ++i)
      for (int j = 0; j < columns; ++j) {
        float y = yLo + (yHi - yLo) * (i + 0.5f) / rows, gamma = kTwoPi * (j + 0.5f) / columns;
        float r = safeSqrt(1.0f - y * y);
        Vec3 wo(r * std::sin(gamma), y, r * std::cos(gamma));
        BarbuleLobes f = lobes(wo);
        const Spectrum& lobe = reflection ? f.reflection : f.trt;
        std::array<double, kSpectrumSamples>& s = sum[size_t(regionOf(wo))];
        for (int k = 0; k < kSpectrumSamples; ++k) s[k] += double(lobe[k]) * std::abs(wo.z);
      }
    for (int region = 0; region < regions; ++region) {
      Spectrum& lobe = reflection ? out[size_t(region)].reflection : out[size_t(region)].trt;
      for (int k = 0; k < kSpectrumSamples; ++k) lobe[k] = float(sum[size_t(region)][k] * cell);
    }
  };
  float band = 2.0f * kSinBarbuleThetaD;
  grid(std::max(-wi.y - band, -1.0f), std::min(-wi.y + band, 1.0f), rRows, rColumns, true);
  grid(-1.0f, 1.0f, 160, 320, false);
  return out;
}

// r times the means over the visible normals of I_R (with the visibility and longitudinal
// shadowing toward the mirror direction) and of the TRT energy (integral over omega_o of I_TRT
// |cos theta_o| / pi on the normal's front side, visible from omega_o), from the film and the
// cross-section geometry directly rather than through the BSDF's lobes and their Jacobians; at
// the wavelengths `wl`.
LobeAlbedo visibleNormalMeans(const BarbuleParameters& p, const Vec3& wi, const Wavelengths& wl);

}  // namespace columba::testing
