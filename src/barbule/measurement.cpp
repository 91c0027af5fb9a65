#include "barbule/measurement.h"

#include <tbb/parallel_for.h>

#include <optional>

#include "barbule/normals.h"
#include "core/gauss_legendre.h"
#include "core/illuminant.h"

namespace columba {

namespace {
// TRT's outgoing directions: the midpoint rule on an equal-area grid whose pole is the barbule axis
// (local y). TRT is smooth in omega_o (its lit offsets change continuously with it), and against a
// grid four times finer each way it agrees to 1e-5 (tests/barbule/test_measurement.cpp).
constexpr int kAxisSteps = 240, kAzimuthSteps = 240;

Vec3 gridDirection(int i, int j) {
  float y = -1.0f + 2.0f * (i + 0.5f) / kAxisSteps;
  float psi = kTwoPi * (j + 0.5f) / kAzimuthSteps;
  float r = safeSqrt(1.0f - y * y);
  return {r * std::sin(psi), y, r * std::cos(psi)};
}

// R integrated over its half vector m = (cos(theta) sin(gamma), sin(theta), cos(theta) cos(gamma))
// instead of omega_o (docs/model.md, "Measurements"): with dm = d(sin theta) dgamma and
// d omega_o = 4 (omega_i . m) dm, the albedo is the integral of f_R |cos theta_o| 4 (omega_i . m)
// over |theta| < thetaD, where the normals lie, and every in-plane angle gamma. Across theta the
// integrand is smooth (Gauss-Legendre); along gamma it jumps where the reflective arc or the
// visibility ends and, on a superellipse, is singular at a flat side's normal, so gamma is divided
// adaptively: the piece whose one-rule value and two-halves value differ most is halved until the
// differences sum to less than kTolerance of the albedo at each wavelength.
constexpr int kThetaNodes = 6, kGammaNodes = 6, kInitialPieces = 32, kMaxPieces = 4096;
constexpr double kTolerance = 1e-4, kAbsoluteTolerance = 1e-7;
// Below this width (radians) a piece is not halved. A superellipse's flat side (p > 2) makes R
// singular at its normal, like |gamma - gamma_face|^-(p-2)/(p-1); pieces of this width bound how
// much of that peak is missed (0.2 % of R at p 3 with the light in the plane across the barbules,
// docs/model.md), and keep the nodes few there, where a float half vector rounding onto the side's
// normal exactly would meet the curvature radius's cap of 1e12.
constexpr double kMinPieceWidth = 3e-5;

using LaneSums = std::array<double, kSpectrumSamples>;

class HalfVectorQuadrature {
 public:
  HalfVectorQuadrature(const BarbuleLobeSource& model, const Vec3& omegaI, const Wavelengths& wl)
      : model_(model), wi_(omegaI), wl_(wl), theta_(gaussLegendre(kThetaNodes)), gamma_(gaussLegendre(kGammaNodes)) {}

  LaneSums reflectance() const {
    std::vector<Piece> pieces;
    for (int p = 0; p < kInitialPieces; ++p) {
      const double lo = kPiDouble * (2.0 * p / kInitialPieces - 1.0),
                   hi = kPiDouble * (2.0 * (p + 1) / kInitialPieces - 1.0);
      pieces.push_back(piece(lo, hi, rule(lo, hi)));
    }
    while (pieces.size() < size_t(kMaxPieces)) {
      // Pieces at the narrowest width keep their difference: no finer piece would lower it.
      LaneSums total{}, error{};
      for (const Piece& p : pieces)
        for (int k = 0; k < kSpectrumSamples; ++k) {
          total[k] += p.halves()[k];
          if (p.splittable()) error[k] += p.error(k);
        }
      int lane = 0;
      double worstRatio = 0.0;
      for (int k = 0; k < kSpectrumSamples; ++k) {
        const double ratio = error[k] / (kTolerance * std::abs(total[k]) + kAbsoluteTolerance);
        if (ratio > worstRatio) lane = k, worstRatio = ratio;
      }
      if (worstRatio <= 1.0) break;
      size_t worst = 0;
      for (size_t i = 1; i < pieces.size(); ++i)
        if (pieces[i].splittable() &&
            (!pieces[worst].splittable() || pieces[i].error(lane) > pieces[worst].error(lane)))
          worst = i;
      const Piece split = pieces[worst];
      const double mid = 0.5 * (split.lo + split.hi);
      pieces[worst] = piece(split.lo, mid, split.left);
      pieces.push_back(piece(mid, split.hi, split.right));
    }
    LaneSums total{};
    for (const Piece& p : pieces)
      for (int k = 0; k < kSpectrumSamples; ++k) total[k] += p.halves()[k];
    return total;
  }

 private:
  // A piece of gamma: its rule's value and its two halves'.
  struct Piece {
    double lo, hi;
    LaneSums whole, left, right;
    LaneSums halves() const {
      LaneSums s;
      for (int k = 0; k < kSpectrumSamples; ++k) s[k] = left[k] + right[k];
      return s;
    }
    double error(int k) const { return std::abs(whole[k] - left[k] - right[k]); }
    bool splittable() const { return hi - lo > kMinPieceWidth; }
  };
  Piece piece(double lo, double hi, const LaneSums& whole) const {
    const double mid = 0.5 * (lo + hi);
    return {lo, hi, whole, rule(lo, mid), rule(mid, hi)};
  }
  LaneSums rule(double lo, double hi) const {
    LaneSums sum{};
    for (size_t j = 0; j < gamma_.nodes.size(); ++j) {
      const LaneSums c = column(lo + (hi - lo) * gamma_.nodes[j]);
      for (int k = 0; k < kSpectrumSamples; ++k) sum[k] += gamma_.weights[j] * (hi - lo) * c[k];
    }
    return sum;
  }
  // The integral over sin(theta) of f_R |cos theta_o| 4 (omega_i . m) at the in-plane angle gamma.
  LaneSums column(double gamma) const {
    static constexpr double kSinThetaD = constexprSin(kBarbuleThetaDInDouble);
    LaneSums sum{};
    for (size_t j = 0; j < theta_.nodes.size(); ++j) {
      const double s = kSinThetaD * (2.0 * theta_.nodes[j] - 1.0), c = std::sqrt(1.0 - s * s);
      const double mx = c * std::sin(gamma), my = s, mz = c * std::cos(gamma);
      const double cosI = wi_.x * mx + wi_.y * my + wi_.z * mz;
      if (!(cosI > 0.0)) continue;
      const Vec3 wo(float(2.0 * cosI * mx - wi_.x), float(2.0 * cosI * my - wi_.y), float(2.0 * cosI * mz - wi_.z));
      const Spectrum f = model_.lobes(wi_, wo, wl_).reflection;
      const double weight = theta_.weights[j] * 2.0 * kSinThetaD * 4.0 * cosI * std::abs(wo.z);
      for (int k = 0; k < kSpectrumSamples; ++k) sum[k] += weight * f[k];
    }
    return sum;
  }

  const BarbuleLobeSource& model_;
  Vec3 wi_;
  Wavelengths wl_;
  GaussLegendreRule theta_, gamma_;
};

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

// The direction of sub-pixel (sx, sy) of pixel (px, py) on the scatterometer's image disk, as the
// `bsdfvisualizer` sensor maps it (v grows downward with the row); nullopt outside the disk.
std::optional<Vec3> scatterometerDirection(int px, int py, int sx, int sy, int resolution, int supersampling) {
  float u = 2.0f * (px + (sx + 0.5f) / supersampling) / resolution - 1.0f;
  float v = 2.0f * (py + (sy + 0.5f) / supersampling) / resolution - 1.0f;
  float r = std::sqrt(u * u + v * v);
  if (r >= 1.0f) return std::nullopt;
  return directionFromAngles(r * kHalfPi, std::atan2(v, u));
}

Spectrum total(const BarbuleLobes& lobes) { return lobes.reflection + lobes.trt; }
}  // namespace

std::vector<float> wavelengthGrid(float first, float step) {
  std::vector<float> lambdas;
  for (float l = first; l <= kLambdaMax + 1e-3f; l += step) lambdas.push_back(l);
  return lambdas;
}

LobeSpectra lobeReflectance(const BarbuleLobeSource& model, const Vec3& omegaI, const std::vector<float>& lambdas) {
  std::vector<WavelengthGroup> groups = wavelengthGroups(lambdas);
  LobeSpectra result;
  result.lambdas = lambdas;
  result.reflection.assign(lambdas.size(), 0.0f);
  result.trt.assign(lambdas.size(), 0.0f);
  const double cellSolidAngle = (2.0 / kAxisSteps) * (2.0 * kPiDouble / kAzimuthSteps);
  tbb::parallel_for(size_t(0), groups.size(), [&](size_t g) {
    const LaneSums r = HalfVectorQuadrature(model, omegaI, groups[g].wl).reflectance();
    double t[kSpectrumSamples] = {};
    for (int i = 0; i < kAxisSteps; ++i)
      for (int j = 0; j < kAzimuthSteps; ++j) {
        Vec3 wo = gridDirection(i, j);
        Spectrum trt = model.lobes(omegaI, wo, groups[g].wl).trt;
        for (int k = 0; k < kSpectrumSamples; ++k) t[k] += trt[k] * std::abs(wo.z);
      }
    for (int k = 0; k < groups[g].count; ++k) {
      result.reflection[g * kSpectrumSamples + k] = float(r[k]);
      result.trt[g * kSpectrumSamples + k] = float(t[k] * cellSolidAngle);
    }
  });
  return result;
}

std::vector<float> peakWavelengths(const std::vector<float>& lambdas, const std::vector<float>& values) {
  std::vector<float> peaks;
  for (size_t i = 1; i + 1 < values.size(); ++i)
    if (values[i] > values[i - 1] && values[i] >= values[i + 1]) peaks.push_back(lambdas[i]);
  return peaks;
}

Vec3 directionFromAngles(float theta, float phi) {
  return {std::sin(theta) * std::cos(phi), std::sin(theta) * std::sin(phi), std::cos(theta)};
}

LobeSpectra specularSpectra(const BarbuleLobeSource& model, const Vec3& omegaI, const std::vector<float>& lambdas) {
  LobeSpectra result;
  result.lambdas = lambdas;
  result.reflection.resize(lambdas.size());
  result.trt.resize(lambdas.size());
  const Vec3 mirror(-omegaI.x, -omegaI.y, omegaI.z);
  std::vector<WavelengthGroup> groups = wavelengthGroups(lambdas);
  for (size_t k = 0; k < groups.size(); ++k) {
    BarbuleLobes lobes = model.lobes(omegaI, mirror, groups[k].wl);
    for (int i = 0; i < groups[k].count; ++i) {
      result.reflection[k * kSpectrumSamples + i] = kPi * lobes.reflection[i];
      result.trt[k * kSpectrumSamples + i] = kPi * lobes.trt[i];
    }
  }
  return result;
}

PlaneSlice planeSlice(const BarbuleLobeSource& model, const Vec3& omegaI, float phi, const std::vector<float>& thetaO,
                      const std::vector<float>& lambdas) {
  PlaneSlice slice{thetaO, lambdas, std::vector<std::vector<float>>(thetaO.size(), std::vector<float>(lambdas.size()))};
  std::vector<WavelengthGroup> groups = wavelengthGroups(lambdas);
  tbb::parallel_for(size_t(0), thetaO.size(), [&](size_t a) {
    // Signed angles: positive toward the light's azimuth, so the mirror direction is at -theta_i.
    Vec3 wo = directionFromAngles(std::abs(thetaO[a]), thetaO[a] >= 0.0f ? phi : phi + kPi);
    for (size_t k = 0; k < groups.size(); ++k) {
      BarbuleLobes lobes = model.lobes(omegaI, wo, groups[k].wl);
      for (int i = 0; i < groups[k].count; ++i)
        slice.values[a][k * kSpectrumSamples + i] = (lobes.reflection[i] + lobes.trt[i]) * std::abs(wo.z);
    }
  });
  return slice;
}

std::vector<Vec3> sliceRGB(const PlaneSlice& slice) {
  std::vector<Vec3> rgb;
  const size_t n = slice.lambdas.size();
  const float step = n > 1 ? (slice.lambdas.back() - slice.lambdas.front()) / float(n - 1) : 1.0f;
  for (const std::vector<float>& column : slice.values) {
    Vec3 xyz(0, 0, 0);
    for (size_t i = 0; i < n; ++i) xyz += cieXYZ(slice.lambdas[i]) * (column[i] * d65(slice.lambdas[i]) * step);
    rgb.push_back(xyzToLinearRGB(xyz / cieYIntegral()));
  }
  return rgb;
}

SpectralBands spectralScatterometerBands(const BarbuleLobeSource& model, const Vec3& omegaI, int resolution, int bins,
                                         float lambdaMin, float lambdaMax, int supersampling) {
  // Each bin is averaged over four wavelengths at the centres of its quarters.
  const float binWidth = (lambdaMax - lambdaMin) / float(bins);
  SpectralBands image{{}, std::vector<float>(size_t(resolution) * resolution * bins, 0.0f)};
  std::vector<Wavelengths> binWavelengths;
  for (int b = 0; b < bins; ++b) {
    float lo = lambdaMin + b * binWidth;
    image.centres.push_back(lo + 0.5f * binWidth);
    std::array<float, kSpectrumSamples> l;
    for (int i = 0; i < kSpectrumSamples; ++i) l[i] = lo + (i + 0.5f) * binWidth / kSpectrumSamples;
    binWavelengths.push_back(Wavelengths::fixed(l));
  }
  tbb::parallel_for(0, resolution, [&](int py) {
    for (int px = 0; px < resolution; ++px) {
      float* out = &image.values[(size_t(py) * resolution + px) * bins];
      for (int sy = 0; sy < supersampling; ++sy)
        for (int sx = 0; sx < supersampling; ++sx) {
          std::optional<Vec3> wo = scatterometerDirection(px, py, sx, sy, resolution, supersampling);
          if (!wo) continue;
          for (int b = 0; b < bins; ++b) {
            Spectrum f = total(model.lobes(omegaI, *wo, binWavelengths[b]));
            out[b] += f.average() * std::abs(wo->z) / float(supersampling * supersampling);
          }
        }
    }
  });
  return image;
}

Image scatterometerImage(const BarbuleLobeSource& model, const Vec3& omegaI, int resolution, int supersampling) {
  Image image(resolution, resolution);
  std::vector<WavelengthGroup> groups = wavelengthGroups(wavelengthGrid(kLambdaMin, 5.0f));
  const float dLambda = 5.0f;
  tbb::parallel_for(0, resolution, [&](int py) {
    for (int px = 0; px < resolution; ++px) {
      Vec3 xyz(0, 0, 0);
      for (int sy = 0; sy < supersampling; ++sy)
        for (int sx = 0; sx < supersampling; ++sx) {
          std::optional<Vec3> wo = scatterometerDirection(px, py, sx, sy, resolution, supersampling);
          if (!wo) continue;
          for (const WavelengthGroup& g : groups) {
            BarbuleLobes lobes = model.lobes(omegaI, *wo, g.wl);
            for (int k = 0; k < g.count; ++k)
              xyz +=
                  cieXYZ(g.wl[k]) * ((lobes.reflection[k] + lobes.trt[k]) * std::abs(wo->z) * d65(g.wl[k]) * dLambda);
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
