#include "core/rgb_spectrum_table.h"

#include <tbb/parallel_for.h>
#include <tbb/task_arena.h>

#include <algorithm>
#include <vector>

namespace columba {

namespace {
constexpr int kNodes = 64;

// Coefficients at ratios (a, b) = (j, k) / (kNodes - 1) of the two other channels to the largest,
// for each largest channel.
struct RatioTable {
  std::vector<std::array<float, 3>> coefficients = std::vector<std::array<float, 3>>(3 * kNodes * kNodes);
  std::array<float, 3>& at(int channel, int j, int k) { return coefficients[(channel * kNodes + k) * kNodes + j]; }
  const std::array<float, 3>& at(int channel, int j, int k) const {
    return coefficients[(channel * kNodes + k) * kNodes + j];
  }

  RatioTable() {
    // Each channel's table is walked from grey (a = b = 1, fitted from all coefficients zero)
    // outwards, every fit starting from a neighbour's coefficients: saturated colours are far from
    // grey's.
    // The first lookup may come from inside a parallel loop (tabulatedRGBSpectra's): isolated,
    // this thread runs only the three channels' tasks while it builds the table, never one of that
    // loop's, which would look the table up again while its construction is under way.
    tbb::this_task_arena::isolate([&] {
      tbb::parallel_for(0, 3, [&](int channel) {
        auto colour = [channel](int j, int k) {
          Vec3 c;
          c[channel] = 0.5f;
          c[(channel + 1) % 3] = 0.5f * float(j) / float(kNodes - 1);
          c[(channel + 2) % 3] = 0.5f * float(k) / float(kNodes - 1);
          return c;
        };
        for (int k = kNodes - 1; k >= 0; --k) {
          std::array<float, 3> start = k == kNodes - 1 ? std::array<float, 3>{} : at(channel, kNodes - 1, k + 1);
          for (int j = kNodes - 1; j >= 0; --j) {
            start = fitSigmoidCoefficients(colour(j, k), start);
            at(channel, j, k) = start;
          }
        }
      });
    });
  }
};

const RatioTable& ratioTable() {
  static const RatioTable table;
  return table;
}
}  // namespace

RGBSpectrum tabulatedRGBSpectrum(const Vec3& rgbIn) {
  const Vec3 rgb = maxv(rgbIn, Vec3(0, 0, 0));
  const int channel = rgb.x >= rgb.y && rgb.x >= rgb.z ? 0 : (rgb.y >= rgb.z ? 1 : 2);
  const float m = rgb[channel];
  if (!(m > 0.0f)) return RGBSpectrum{{0.0f, 0.0f, 0.0f}, 0.0f};
  const float a = clampf(rgb[(channel + 1) % 3] / m, 0.0f, 1.0f) * float(kNodes - 1);
  const float b = clampf(rgb[(channel + 2) % 3] / m, 0.0f, 1.0f) * float(kNodes - 1);
  const int j = std::min(int(a), kNodes - 2), k = std::min(int(b), kNodes - 2);
  const float fa = a - float(j), fb = b - float(k);
  const RatioTable& t = ratioTable();
  RGBSpectrum s;
  for (int i = 0; i < 3; ++i)
    s.coeffs[i] = (1.0f - fb) * ((1.0f - fa) * t.at(channel, j, k)[i] + fa * t.at(channel, j + 1, k)[i]) +
                  fb * ((1.0f - fa) * t.at(channel, j, k + 1)[i] + fa * t.at(channel, j + 1, k + 1)[i]);
  s.scale = 2.0f * m;
  return s;
}

std::vector<RGBSpectrum> tabulatedRGBSpectra(const float* rgb, size_t count) {
  std::vector<RGBSpectrum> spectra(count);
  tbb::parallel_for(size_t(0), count, [&](size_t i) {
    spectra[i] = tabulatedRGBSpectrum(Vec3(rgb[3 * i], rgb[3 * i + 1], rgb[3 * i + 2]));
  });
  return spectra;
}

}  // namespace columba
