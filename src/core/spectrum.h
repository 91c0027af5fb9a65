#pragma once
// Spectral quantities carried along a path: 4 wavelengths (hero + 3 rotations) and values there.
#include <algorithm>
#include <array>
#include <vector>
#include "core/fast_math.h"
#include "core/vector.h"

namespace columba {

inline constexpr int kSpectrumSamples = 4;
inline constexpr float kLambdaMin = 360.0f;
inline constexpr float kLambdaMax = 830.0f;
// The shortest wavelength Columba models: birds see from 300 nm. Human colour (RGB images, the CIE
// 1931 observer) stays within kLambdaMin-kLambdaMax; spectra, the barbule model, measured spectra
// and bird observers reach down to here (docs/vision.md, "Below 360 nm").
inline constexpr float kSpectralMin = 300.0f;

// Values of a quantity at the path's wavelengths, one per SIMD lane: arithmetic on a spectrum is
// one vector instruction.
struct Spectrum {
  static_assert(kSpectrumSamples == kLaneCount, "one SIMD register per spectrum");
  FloatLanes lanes{};
  Spectrum() = default;
  explicit Spectrum(float c) : lanes{c, c, c, c} {}
  explicit Spectrum(FloatLanes l) : lanes(l) {}
  float operator[](int i) const { return lanes[i]; }
  // Through the address: Clang binds no reference to a vector element (vector types alias their
  // element type).
  float& operator[](int i) { return reinterpret_cast<float*>(&lanes)[i]; }
#define COLUMBA_SPECTRUM_OP(op)                                                        \
  Spectrum operator op(const Spectrum& o) const { return Spectrum(lanes op o.lanes); } \
  Spectrum operator op(float s) const { return Spectrum(lanes op s); }                 \
  Spectrum& operator op##=(const Spectrum& o) {                                        \
    lanes op## = o.lanes;                                                              \
    return *this;                                                                      \
  }                                                                                    \
  Spectrum& operator op##=(float s) {                                                  \
    lanes op## = s;                                                                    \
    return *this;                                                                      \
  }                                                                                    \
  friend Spectrum operator op(float s, const Spectrum& a) { return Spectrum(s op a.lanes); }
  COLUMBA_SPECTRUM_OP(+)
  COLUMBA_SPECTRUM_OP(-)
  COLUMBA_SPECTRUM_OP(*)
  COLUMBA_SPECTRUM_OP(/)
#undef COLUMBA_SPECTRUM_OP
  float average() const {
    float s = 0;
    for (int i = 0; i < kSpectrumSamples; ++i) s += lanes[i];
    return s / kSpectrumSamples;
  }
  float maxValue() const {
    float m = lanes[0];
    for (int i = 1; i < kSpectrumSamples; ++i) m = std::max(m, lanes[i]);
    return m;
  }
  bool isZero() const {
    for (int i = 0; i < kSpectrumSamples; ++i)
      if (lanes[i] != 0.0f) return false;
    return true;
  }
  bool isFinite() const {
    for (int i = 0; i < kSpectrumSamples; ++i)
      if (!std::isfinite(lanes[i])) return false;
    return true;
  }
};

// The densities a path's wavelengths are drawn from.
//   RGBMatching: in proportion to |r| + |g| + |b| of the linear-sRGB colour matching functions
//                (plus 1 % of the peak): what an RGB image records, blue included;
//   Visible:     pbrt-v4's visible-wavelength density, which follows the eye's luminance
//                sensitivity and keeps more of the range's ends: for spectral output, whose bins
//                span the whole range.
enum class WavelengthDensity { RGBMatching, Visible };

// A wavelength density on [first, last] nm, sampled through a table of its inverse CDF: the
// wavelength is interpolated linearly within 1/1024 of the CDF, so the density actually drawn is
// constant per table segment, and that density is what `pdf` reports. The two densities above have
// tables of their own; an observer's film makes one that follows its cones (makeWavelengthTable).
class WavelengthTable {
 public:
  static constexpr int kSegments = 1024;
  // From the wavelengths at CDF = k / kSegments (the ends are set here).
  template <typename InverseCDF>
  WavelengthTable(float first, float last, const InverseCDF& inverse) {
    for (int k = 1; k < kSegments; ++k)
      lambda_[k] = float(std::clamp(inverse(double(k) / kSegments), double(first), double(last)));
    lambda_.front() = first;
    lambda_.back() = last;
    for (int k = 0; k < kSegments; ++k) pdf_[k] = 1.0f / (kSegments * (lambda_[k + 1] - lambda_[k]));
  }
  // Wavelength at position x = u kSegments of the table (u in [0, 1]), and the density it is drawn with.
  float at(float x, float* density) const {
    int k = std::min(int(x), kSegments - 1);
    *density = pdf_[k];
    return lerp(x - float(k), lambda_[k], lambda_[k + 1]);
  }
  float pdf(float lambda) const;
  float first() const { return lambda_.front(); }
  float last() const { return lambda_.back(); }

 private:
  std::array<float, kSegments + 1> lambda_;
  std::array<float, kSegments> pdf_;  // density within each segment
};
// The table of a density given at whole nanometres firstNm, firstNm + 1, ... and linear between
// them (it needs no normalisation; every value must be positive).
WavelengthTable makeWavelengthTable(float firstNm, const std::vector<double>& densityPerNm);

// The wavelengths (nm) a path carries and the density each was drawn with.
struct Wavelengths {
  std::array<float, kSpectrumSamples> lambda{};
  std::array<float, kSpectrumSamples> pdf{};
  float operator[](int i) const { return lambda[i]; }

  // Hero wavelength from `u`, the others at equal offsets in sample space.
  static Wavelengths sample(float u, WavelengthDensity density);
  static Wavelengths sample(float u, const WavelengthTable& table);
  // Fixed wavelengths with unit pdf, for tests and plots.
  static Wavelengths fixed(std::array<float, kSpectrumSamples> l);
};
// The density a wavelength is drawn with (the table's, constant over 1/1024 of the CDF), and one
// wavelength drawn by inverting the CDF.
float wavelengthPdf(float lambda, WavelengthDensity density);
const WavelengthTable& wavelengthTable(WavelengthDensity density);
float sampleWavelength(float u, WavelengthDensity density);

// CIE 1931 2-degree colour matching functions (multi-lobe fit of Wyman, Sloan & Shirley 2013),
// evaluated exactly by cieXYZFit and from a 1 nm table by cieXYZ.
Vec3 cieXYZFit(float lambda);
Vec3 cieXYZ(float lambda);
// Integral of ybar over [360, 830] nm, so that a flat spectrum of 1 has Y = 1.
float cieYIntegral();

// Linear Rec.709/sRGB primaries with the plain matrix (no white balance, as Mitsuba): D65 is
// (1, 1, 1) and a flat (equal-energy) spectrum is slightly pink.
Vec3 xyzToLinearRGB(const Vec3& xyz);
// Its inverse; the y of the result is the colour's luminance.
Vec3 linearRGBToXYZ(const Vec3& rgb);
// Monte Carlo estimate of a spectrum's linear RGB from its values at `wl`.
Vec3 spectrumToRGB(const Spectrum& s, const Wavelengths& wl);

// The smooth spectrum of an RGB colour (Jakob & Hanika 2019): scale * s(c0 x^2 + c1 x + c2), with x
// the wavelength normalised to [0, 1] over the visible range and s(t) = 1/2 + t / (2 sqrt(1 + t^2)).
// Small (16 bytes) so that a texture can keep one per texel.
struct RGBSpectrum {
  std::array<float, 3> coeffs{};
  float scale = 0.0f;
  float eval(float lambda) const;
  // Mean over the visible range, as SpectralDistribution::meanValue.
  float meanValue() const;
  // The largest value over kSpectralMin-kLambdaMax (a bound a medium's majorant can use).
  float maxValue() const;
};
// The spectrum whose colour under D65 is `rgb`, fitted here. `unbounded` allows values above 1
// (fitted at half the largest component and scaled back, as pbrt-v4 does); otherwise rgb is clamped
// to [0, 1]. A grey colour is exactly constant.
RGBSpectrum fitRGBSpectrum(const Vec3& rgb, bool unbounded);
// The coefficients of the sigmoid polynomial whose colour under D65 is `rgb` (each component in
// [0, 1]), fitted from `start`: from a nearby colour's coefficients it takes a few steps.
std::array<float, 3> fitSigmoidCoefficients(const Vec3& rgb, const std::array<float, 3>& start = {});

// A spectral distribution given in a scene: constant, piecewise linear, or upsampled RGB.
class SpectralDistribution {
 public:
  SpectralDistribution() = default;
  static SpectralDistribution constant(float value);
  // Piecewise-linear through (lambda, value) pairs sorted by lambda; constant beyond the ends.
  static SpectralDistribution piecewiseLinear(std::vector<float> lambdas, std::vector<float> values);
  // A smooth spectrum whose colour under D65 is `rgb` (Jakob & Hanika 2019 sigmoid-polynomial,
  // fitted here). `unbounded` allows values above 1; otherwise rgb is clamped to [0, 1].
  static SpectralDistribution fromRGB(const Vec3& rgb, bool unbounded);
  // This distribution times D65 (luminance 1): how a single value or an RGB colour given for an
  // emitter becomes an illuminant.
  SpectralDistribution timesD65() const;

  float eval(float lambda) const;
  // A single value at every wavelength.
  bool isConstant() const { return kind_ == Kind::Constant && !timesD65_; }
  Spectrum sample(const Wavelengths& wl) const;
  // Mean over the visible range, for light selection and diagnostics.
  float meanValue() const;
  // The largest value over kSpectralMin-kLambdaMax (at every nm and every tabulated wavelength).
  float maxValue() const;
  // Luminance as a reflectance under D65, relative to a white reflector: the value of a constant,
  // the luminance Y of the colour an RGB spectrum was fitted to.
  float luminance() const;

 private:
  float evalShape(float lambda) const;  // eval without the illuminant

  enum class Kind { Constant, Piecewise, Sigmoid } kind_ = Kind::Constant;
  bool timesD65_ = false;
  float value_ = 0.0f;  // for Kind::Constant
  std::vector<float> lambdas_, values_;
  RGBSpectrum rgb_;  // for Kind::Sigmoid
};

}  // namespace columba
