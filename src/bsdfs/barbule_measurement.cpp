#include "bsdfs/barbule_measurement.h"

#include <tbb/parallel_for.h>

#include "core/illuminant.h"


namespace columba {

namespace {
// Outgoing directions on an equal-area grid whose pole is the barbule axis (local y): the R
// lobe is narrow in the angle to that axis, so a fine grid in y resolves it.
constexpr int kAxisSteps = 600, kAzimuthSteps = 180;

Vec3 gridDirection(int i, int j) {
  float y = -1.0f + 2.0f * (i + 0.5f) / kAxisSteps;
  float psi = kTwoPi * (j + 0.5f) / kAzimuthSteps;
  float r = safeSqrt(1.0f - y * y);
  return {r * std::sin(psi), y, r * std::cos(psi)};
}

// Wavelengths in groups of four (the BSDF's evaluation width); the last group is padded by
// repeating its last wavelength, and `count` says how many entries are real.
struct WavelengthGroup {
  Wavelengths wl;
  int count;
};
std::vector<WavelengthGroup> wavelengthGroups(const std::vector<float>& lambdas) {
  std::vector<WavelengthGroup> groups;
  for (size_t k = 0; k < lambdas.size(); k += kSpectrumSamples) {
    std::array<float, kSpectrumSamples> l;
    for (int i = 0; i < kSpectrumSamples; ++i) l[i] = lambdas[std::min(k + i, lambdas.size() - 1)];
    groups.push_back({Wavelengths::fixed(l), int(std::min<size_t>(kSpectrumSamples, lambdas.size() - k))});
  }
  return groups;
}
}  // namespace

std::vector<float> visibleWavelengthGrid(float step) {
  std::vector<float> lambdas;
  for (float l = kLambdaMin; l <= kLambdaMax + 1e-3f; l += step) lambdas.push_back(l);
  return lambdas;
}

LobeReflectance lobeReflectance(const BarbuleBSDF& bsdf, const Vec3& omegaI, const std::vector<float>& lambdas) {
  std::vector<WavelengthGroup> groups = wavelengthGroups(lambdas);
  LobeReflectance result;
  result.lambdas = lambdas;
  result.reflection.assign(lambdas.size(), 0.0f);
  result.trt.assign(lambdas.size(), 0.0f);
  const double cellSolidAngle = (2.0 / kAxisSteps) * (2.0 * M_PI / kAzimuthSteps);
  BSDFContext ctx;
  tbb::parallel_for(size_t(0), groups.size(), [&](size_t g) {
    double r[kSpectrumSamples] = {}, t[kSpectrumSamples] = {};
    for (int i = 0; i < kAxisSteps; ++i)
      for (int j = 0; j < kAzimuthSteps; ++j) {
        Vec3 wo = gridDirection(i, j);
        BarbuleBSDF::Lobes lobes = bsdf.evalLobes(ctx, omegaI, wo, groups[g].wl);
        for (int k = 0; k < kSpectrumSamples; ++k) {
          r[k] += lobes.reflection[k] * std::abs(wo.z);
          t[k] += lobes.trt[k] * std::abs(wo.z);
        }
      }
    for (int k = 0; k < groups[g].count; ++k) {
      result.reflection[g * kSpectrumSamples + k] = float(r[k] * cellSolidAngle);
      result.trt[g * kSpectrumSamples + k] = float(t[k] * cellSolidAngle);
    }
  });
  return result;
}

Image scatterometerImage(const BarbuleBSDF& bsdf, const Vec3& omegaI, int resolution, int supersampling) {
  Image image(resolution, resolution);
  std::vector<WavelengthGroup> groups = wavelengthGroups(visibleWavelengthGrid(5.0f));
  const float dLambda = 5.0f;
  BSDFContext ctx;
  tbb::parallel_for(0, resolution, [&](int py) {
    for (int px = 0; px < resolution; ++px) {
      Vec3 xyz(0, 0, 0);
      for (int sy = 0; sy < supersampling; ++sy)
        for (int sx = 0; sx < supersampling; ++sx) {
          float x = 2.0f * (px + (sx + 0.5f) / supersampling) / resolution - 1.0f;
          float y = 2.0f * (py + (sy + 0.5f) / supersampling) / resolution - 1.0f;
          float r = std::sqrt(x * x + y * y);
          if (r >= 1.0f) continue;
          float theta = r * kHalfPi, phi = std::atan2(y, x);
          Vec3 wo(std::sin(theta) * std::cos(phi), std::sin(theta) * std::sin(phi), std::cos(theta));
          for (const WavelengthGroup& g : groups) {
            BarbuleBSDF::Lobes lobes = bsdf.evalLobes(ctx, omegaI, wo, g.wl);
            for (int k = 0; k < g.count; ++k)
              xyz += cieXYZ(g.wl[k]) * ((lobes.reflection[k] + lobes.trt[k]) * std::abs(wo.z) * d65(g.wl[k]) * dLambda);
          }
        }
      Vec3 rgb = xyzToLinearRGB(xyz / (cieYIntegral() * float(supersampling * supersampling)));
      float* p = image.pixel(px, py);
      p[0] = std::max(rgb.x, 0.0f);
      p[1] = std::max(rgb.y, 0.0f);
      p[2] = std::max(rgb.z, 0.0f);
    }
  });
  return image;
}

}  // namespace columba
