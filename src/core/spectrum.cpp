#include "core/spectrum.h"

#include <algorithm>
#include <stdexcept>
#include "core/fast_math.h"
#include "core/illuminant.h"

namespace columba {

namespace {
// pbrt-v4's visible-wavelength density, 1/cosh^2(0.0072 (lambda - 538)), whose inverse CDF has a
// closed form. The table spares four atanh and cosh per camera sample.
const WavelengthTable& visibleTable() {
  static const WavelengthTable table(
      kLambdaMin, kLambdaMax, [](double u) { return 538.0 - 138.888889 * std::atanh(0.85691062 - 1.82750197 * u); });
  return table;
}

const WavelengthTable& rgbMatchingTable();
}  // namespace

const WavelengthTable& wavelengthTable(WavelengthDensity density) {
  return density == WavelengthDensity::Visible ? visibleTable() : rgbMatchingTable();
}

float WavelengthTable::pdf(float l) const {
  if (l < first() || l > last()) return 0.0f;
  int k = int(std::upper_bound(lambda_.begin(), lambda_.end(), l) - lambda_.begin()) - 1;
  return pdf_[std::clamp(k, 0, kSegments - 1)];
}

float wavelengthPdf(float lambda, WavelengthDensity density) { return wavelengthTable(density).pdf(lambda); }

float sampleWavelength(float u, WavelengthDensity density) {
  float pdf;
  return wavelengthTable(density).at(clampf(u, 0.0f, 1.0f) * WavelengthTable::kSegments, &pdf);
}

Wavelengths Wavelengths::sample(float u, WavelengthDensity density) { return sample(u, wavelengthTable(density)); }

Wavelengths Wavelengths::sample(float u, const WavelengthTable& t) {
  // The hero and three more at equal offsets in sample space, wrapped into [0, 1), in lanes:
  // which of them wrap depends on u, so branches would be mispredicted.
  FloatLanes ui = u + FloatLanes{0.0f, 0.25f, 0.5f, 0.75f};
  ui = ui >= 1.0f ? ui - 1.0f : ui;
  FloatLanes x = clampLanes(ui, 0.0f, 1.0f) * float(WavelengthTable::kSegments);
  Wavelengths wl;
  for (int i = 0; i < kSpectrumSamples; ++i) wl.lambda[i] = t.at(x[i], &wl.pdf[i]);
  return wl;
}

Wavelengths Wavelengths::fixed(std::array<float, kSpectrumSamples> l) {
  Wavelengths wl;
  wl.lambda = l;
  wl.pdf.fill(1.0f);
  return wl;
}

Vec3 cieXYZFit(float lambda);

namespace {
float piecewiseGaussian(float x, float mu, float sigmaLow, float sigmaHigh) {
  float t = (x - mu) / (x < mu ? sigmaLow : sigmaHigh);
  return std::exp(-0.5f * t * t);
}

// Table of the CMFs at 1 nm steps, used for integrals (fitting, normalisation).
struct CieTable {
  static constexpr int kCount = int(kLambdaMax - kLambdaMin) + 1;
  std::array<Vec3, kCount> xyz;
  float yIntegral = 0.0f;
  CieTable() {
    for (int i = 0; i < kCount; ++i) {
      xyz[i] = cieXYZFit(kLambdaMin + float(i));
      yIntegral += xyz[i].y;
    }
  }
};
const CieTable& cieTable() {
  static const CieTable table;
  return table;
}

// Linear interpolation in a table of values at whole nanometres from kLambdaMin to kLambdaMax,
// zero outside: the colour matching functions end there, and a bird observer's render draws
// wavelengths down to kSpectralMin.
template <typename T>
T interpolateNanometres(const std::array<T, CieTable::kCount>& table, float lambda) {
  if (!(lambda >= kLambdaMin && lambda <= kLambdaMax)) return T{};
  float x = clampf(lambda - kLambdaMin, 0.0f, float(CieTable::kCount - 1));
  int i = std::min(int(x), CieTable::kCount - 2);
  float f = x - float(i);
  return table[i] * (1.0f - f) + table[i + 1] * f;
}

// CIE XYZ to linear sRGB/Rec.709 (IEC 61966-2-1), without white balance: D65 maps to (1, 1, 1).
Vec3 xyzToRec709(const Vec3& c) {
  return {3.2404542f * c.x - 1.5371385f * c.y - 0.4985314f * c.z,
          -0.9692660f * c.x + 1.8760108f * c.y + 0.0415560f * c.z,
          0.0556434f * c.x - 0.2040259f * c.y + 1.0572252f * c.z};
}

float sigmoid(float x) { return 0.5f + x / (2.0f * std::sqrt(1.0f + x * x)); }
float normalisedLambda(float lambda) { return (lambda - kLambdaMin) / (kLambdaMax - kLambdaMin); }

// What each whole nanometre of a reflectance lit by D65 adds to its linear RGB (Jakob & Hanika's
// and Mitsuba's definition of a reflectance's colour), with its normalised wavelength.
struct ReflectanceRGBWeights {
  std::array<std::array<double, 3>, CieTable::kCount> rgb;
  std::array<double, CieTable::kCount> x;
  ReflectanceRGBWeights() {
    const CieTable& t = cieTable();
    for (int i = 0; i < CieTable::kCount; ++i) {
      const float lambda = kLambdaMin + float(i);
      const Vec3 c = xyzToLinearRGB(t.xyz[i] * (d65(lambda) / t.yIntegral));
      rgb[i] = {c.x, c.y, c.z};
      x[i] = normalisedLambda(lambda);
    }
  }
};

const ReflectanceRGBWeights& reflectanceRGBWeights() {
  static const ReflectanceRGBWeights weights;
  return weights;
}
}  // namespace

// Gauss-Newton steps with a fixed Levenberg damping, each clamped, for at most 60 iterations (every
// node of the table of fits converges: tests/core/test_rgb_spectrum_table.cpp). The colour and its
// derivatives in the coefficients (ds/dt = (1 + t^2)^(-3/2) / 2, times x^2, x, 1) come from one
// pass over the wavelengths.
std::array<float, 3> fitSigmoidCoefficients(const Vec3& target, const std::array<float, 3>& start) {
  const ReflectanceRGBWeights& w = reflectanceRGBWeights();
  std::array<double, 3> c{start[0], start[1], start[2]};
  for (int iter = 0; iter < 60; ++iter) {
    double rgb[3] = {0, 0, 0}, J[3][3] = {};
    for (int i = 0; i < CieTable::kCount; ++i) {
      const double x = w.x[i], t = (c[0] * x + c[1]) * x + c[2];
      const double q = 1.0 / std::sqrt(1.0 + t * t);
      const double value = 0.5 + 0.5 * t * q, slope = 0.5 * q * q * q;
      const double dc[3] = {slope * x * x, slope * x, slope};
      for (int k = 0; k < 3; ++k) {
        rgb[k] += w.rgb[i][k] * value;
        for (int j = 0; j < 3; ++j) J[k][j] += w.rgb[i][k] * dc[j];
      }
    }
    const double r[3] = {rgb[0] - target.x, rgb[1] - target.y, rgb[2] - target.z};
    if (std::sqrt(r[0] * r[0] + r[1] * r[1] + r[2] * r[2]) < 1e-5) break;
    // Solve (J^T J + damping) dc = -J^T r.
    double A[3][3], g[3];
    for (int a = 0; a < 3; ++a) {
      g[a] = 0;
      for (int i = 0; i < 3; ++i) g[a] -= J[i][a] * r[i];
      for (int b = 0; b < 3; ++b) {
        A[a][b] = 0;
        for (int i = 0; i < 3; ++i) A[a][b] += J[i][a] * J[i][b];
      }
      A[a][a] += 1e-9 + 1e-4 * A[a][a];
    }
    // Cramer's rule on the 3x3 system.
    auto det3 = [](double M[3][3]) {
      return M[0][0] * (M[1][1] * M[2][2] - M[1][2] * M[2][1]) - M[0][1] * (M[1][0] * M[2][2] - M[1][2] * M[2][0]) +
             M[0][2] * (M[1][0] * M[2][1] - M[1][1] * M[2][0]);
    };
    double d = det3(A);
    if (d == 0.0) break;
    for (int j = 0; j < 3; ++j) {
      double Mj[3][3];
      for (int a = 0; a < 3; ++a)
        for (int b = 0; b < 3; ++b) Mj[a][b] = (b == j) ? g[a] : A[a][b];
      c[j] += std::clamp(det3(Mj) / d, -50.0, 50.0);
    }
  }
  return {float(c[0]), float(c[1]), float(c[2])};
}

Vec3 cieXYZ(float lambda) {
  // Linear interpolation in the 1 nm table: the analytic fit costs seven exponentials.
  return interpolateNanometres(cieTable().xyz, lambda);
}

Vec3 cieXYZFit(float l) {
  float x = 1.056f * piecewiseGaussian(l, 599.8f, 37.9f, 31.0f) + 0.362f * piecewiseGaussian(l, 442.0f, 16.0f, 26.7f) -
            0.065f * piecewiseGaussian(l, 501.1f, 20.4f, 26.2f);
  float y = 0.821f * piecewiseGaussian(l, 568.8f, 46.9f, 40.5f) + 0.286f * piecewiseGaussian(l, 530.9f, 16.3f, 31.1f);
  float z = 1.217f * piecewiseGaussian(l, 437.0f, 11.8f, 36.0f) + 0.681f * piecewiseGaussian(l, 459.0f, 26.0f, 13.8f);
  return {x, y, z};
}

float cieYIntegral() { return cieTable().yIntegral; }

Vec3 xyzToLinearRGB(const Vec3& xyz) { return xyzToRec709(xyz); }

Vec3 linearRGBToXYZ(const Vec3& c) {
  return {0.4124564f * c.x + 0.3575761f * c.y + 0.1804375f * c.z,
          0.2126729f * c.x + 0.7151522f * c.y + 0.0721750f * c.z,
          0.0193339f * c.x + 0.1191920f * c.y + 0.9503041f * c.z};
}

namespace {
// The colour-matching functions taken to linear RGB and divided by the Y integral, at the
// CIE table's 1 nm steps: the conversion is linear, so it is applied once here instead of per
// camera sample.
struct RgbMatchingFunctions {
  std::array<FloatLanes, CieTable::kCount> rgb;  // r, g, b and a zero lane: one register per entry
  RgbMatchingFunctions() {
    const CieTable& t = cieTable();
    for (int i = 0; i < CieTable::kCount; ++i) {
      Vec3 c = xyzToLinearRGB(t.xyz[i] / t.yIntegral);
      rgb[i] = FloatLanes{c.x, c.y, c.z, 0.0f};
    }
  }
};
const RgbMatchingFunctions& rgbMatchingFunctions() {
  static const RgbMatchingFunctions functions;
  return functions;
}

// The density that follows what an RGB image records: |r| + |g| + |b| of the linear-sRGB colour
// matching functions (linear between whole nanometres, as they are interpolated), plus 1 % of its
// peak so that no wavelength is left out. pbrt's visible density follows luminance alone and draws
// few blue wavelengths (compared in docs/performance.md, "Sample patterns and wavelengths").
const WavelengthTable& rgbMatchingTable() {
  static const WavelengthTable table = [] {
    const RgbMatchingFunctions& f = rgbMatchingFunctions();
    std::array<double, CieTable::kCount> density;
    for (int i = 0; i < CieTable::kCount; ++i) {
      FloatLanes c = f.rgb[i];
      density[i] = std::abs(c[0]) + std::abs(c[1]) + std::abs(c[2]);
    }
    double floor = 0.01 * *std::max_element(density.begin(), density.end());
    for (double& d : density) d += floor;
    return makeWavelengthTable(kLambdaMin, std::vector<double>(density.begin(), density.end()));
  }();
  return table;
}
}  // namespace

WavelengthTable makeWavelengthTable(float firstNm, const std::vector<double>& density) {
  const int count = int(density.size());
  if (count < 2) throw std::invalid_argument("a wavelength density needs at least two values");
  // The CDF at whole nanometres (trapezoids are exact for the linear pieces), inverted within
  // each piece by solving its quadratic.
  std::vector<double> cdf(density.size(), 0.0);
  for (int i = 1; i < count; ++i) cdf[i] = cdf[i - 1] + 0.5 * (density[i - 1] + density[i]);
  const double total = cdf.back();
  return WavelengthTable(firstNm, firstNm + float(count - 1), [&](double u) {
    double target = u * total;
    int i = int(std::upper_bound(cdf.begin(), cdf.end(), target) - cdf.begin()) - 1;
    i = std::clamp(i, 0, count - 2);
    double d0 = density[i], slope = density[i + 1] - d0, rest = target - cdf[i];
    // d0 x + slope x^2 / 2 = rest on x in [0, 1].
    double x = std::abs(slope) > 1e-12 ? (std::sqrt(d0 * d0 + 2.0 * slope * rest) - d0) / slope : rest / d0;
    return double(firstNm) + double(i) + std::clamp(x, 0.0, 1.0);
  });
}

Vec3 spectrumToRGB(const Spectrum& s, const Wavelengths& wl) {
  const RgbMatchingFunctions& t = rgbMatchingFunctions();
  // Per wavelength: the weight s / pdf (0 where the pdf is), in lanes.
  FloatLanes pdf{wl.pdf[0], wl.pdf[1], wl.pdf[2], wl.pdf[3]};
  FloatLanes weight = pdf > 0.0f ? s.lanes / pdf : FloatLanes{};
  FloatLanes rgb{};
  for (int i = 0; i < kSpectrumSamples; ++i) rgb += interpolateNanometres(t.rgb, wl.lambda[i]) * weight[i];
  rgb *= 1.0f / kSpectrumSamples;
  return {rgb[0], rgb[1], rgb[2]};
}

SpectralDistribution SpectralDistribution::constant(float value) {
  SpectralDistribution d;
  d.kind_ = Kind::Constant;
  d.value_ = value;
  return d;
}

SpectralDistribution SpectralDistribution::piecewiseLinear(std::vector<float> lambdas, std::vector<float> values) {
  if (lambdas.empty() || lambdas.size() != values.size())
    throw std::invalid_argument("a spectrum needs matching, non-empty wavelength and value lists");
  for (size_t i = 1; i < lambdas.size(); ++i)
    if (!(lambdas[i] > lambdas[i - 1])) throw std::invalid_argument("spectrum wavelengths must increase");
  SpectralDistribution d;
  d.kind_ = Kind::Piecewise;
  d.lambdas_ = std::move(lambdas);
  d.values_ = std::move(values);
  return d;
}

float RGBSpectrum::eval(float lambda) const {
  float x = normalisedLambda(lambda);
  return scale * sigmoid((coeffs[0] * x + coeffs[1]) * x + coeffs[2]);
}

RGBSpectrum fitRGBSpectrum(const Vec3& rgbIn, bool unbounded) {
  Vec3 rgb = unbounded ? maxv(rgbIn, Vec3(0, 0, 0)) : minv(maxv(rgbIn, Vec3(0, 0, 0)), Vec3(1, 1, 1));
  // s(0) = 1/2: a grey needs no fit.
  if (rgb.x == rgb.y && rgb.y == rgb.z) return RGBSpectrum{{0.0f, 0.0f, 0.0f}, 2.0f * rgb.x};
  float m = std::max(rgb.x, std::max(rgb.y, rgb.z));
  float scale = unbounded ? 2.0f * m : 1.0f;
  return RGBSpectrum{fitSigmoidCoefficients(rgb / scale), scale};
}

SpectralDistribution SpectralDistribution::fromRGB(const Vec3& rgbIn, bool unbounded) {
  Vec3 rgb = unbounded ? maxv(rgbIn, Vec3(0, 0, 0)) : minv(maxv(rgbIn, Vec3(0, 0, 0)), Vec3(1, 1, 1));
  if (rgb.x == rgb.y && rgb.y == rgb.z) return constant(rgb.x);
  SpectralDistribution d;
  d.kind_ = Kind::Sigmoid;
  d.rgb_ = fitRGBSpectrum(rgb, unbounded);
  return d;
}

SpectralDistribution SpectralDistribution::timesD65() const {
  SpectralDistribution d = *this;
  d.timesD65_ = true;
  return d;
}

float SpectralDistribution::eval(float lambda) const {
  float value = evalShape(lambda);
  return timesD65_ ? value * d65(lambda) : value;
}

Spectrum SpectralDistribution::sample(const Wavelengths& wl) const {
  Spectrum s;
  for (int i = 0; i < kSpectrumSamples; ++i) s[i] = evalShape(wl[i]);
  return timesD65_ ? s * d65(wl) : s;
}

float SpectralDistribution::evalShape(float lambda) const {
  switch (kind_) {
    case Kind::Constant:
      return value_;
    case Kind::Piecewise: {
      if (lambda <= lambdas_.front()) return values_.front();
      if (lambda >= lambdas_.back()) return values_.back();
      size_t i = size_t(std::upper_bound(lambdas_.begin(), lambdas_.end(), lambda) - lambdas_.begin()) - 1;
      float t = (lambda - lambdas_[i]) / (lambdas_[i + 1] - lambdas_[i]);
      return lerp(t, values_[i], values_[i + 1]);
    }
    case Kind::Sigmoid:
      return rgb_.eval(lambda);
  }
  return 0.0f;
}

namespace {
// The mean of `spectrum` over the visible range, at 1 nm steps.
template <typename Distribution>
float meanOverVisible(const Distribution& spectrum) {
  double s = 0;
  for (int i = 0; i < CieTable::kCount; ++i) s += spectrum.eval(kLambdaMin + float(i));
  return float(s / CieTable::kCount);
}
}  // namespace

float RGBSpectrum::meanValue() const { return meanOverVisible(*this); }

float RGBSpectrum::maxValue() const {
  // The sigmoid grows with its argument, so its largest value is at the quadratic's largest: at an
  // end of the range or at the quadratic's vertex within it.
  const float lo = normalisedLambda(kSpectralMin), hi = normalisedLambda(kLambdaMax);
  auto quadratic = [&](float x) { return (coeffs[0] * x + coeffs[1]) * x + coeffs[2]; };
  float largest = std::max(quadratic(lo), quadratic(hi));
  if (coeffs[0] != 0.0f) {
    const float vertex = -coeffs[1] / (2.0f * coeffs[0]);
    if (vertex > lo && vertex < hi) largest = std::max(largest, quadratic(vertex));
  }
  return scale * sigmoid(largest);
}

float SpectralDistribution::meanValue() const {
  if (kind_ == Kind::Constant && !timesD65_) return value_;
  return meanOverVisible(*this);
}

float SpectralDistribution::maxValue() const {
  if (isConstant()) return value_;
  float largest = eval(kLambdaMax);
  for (float lambda = kSpectralMin; lambda < kLambdaMax; lambda += 1.0f) largest = std::max(largest, eval(lambda));
  for (float lambda : lambdas_)
    if (lambda >= kSpectralMin && lambda <= kLambdaMax) largest = std::max(largest, eval(lambda));
  return largest;
}

float SpectralDistribution::luminance() const {
  if (isConstant()) return value_;
  const CieTable& t = cieTable();
  double reflected = 0, white = 0;
  for (int i = 0; i < CieTable::kCount; ++i) {
    const float lambda = kLambdaMin + float(i);
    const double weight = double(d65(lambda)) * t.xyz[i].y;
    reflected += weight * eval(lambda);
    white += weight;
  }
  return float(reflected / white);
}

}  // namespace columba
