#pragma once
// Spectral quantities carried along a path: 4 wavelengths (hero + 3 rotations) and values there.
#include <array>
#include <vector>
#include "core/math.h"
#include "core/vector.h"

namespace columba {

inline constexpr int kSpectrumSamples = 4;
inline constexpr float kLambdaMin = 360.0f;
inline constexpr float kLambdaMax = 830.0f;

// Values of a quantity at the path's wavelengths.
struct Spectrum {
  std::array<float, kSpectrumSamples> v{};
  Spectrum() = default;
  explicit Spectrum(float c) { v.fill(c); }
  float operator[](int i) const { return v[i]; }
  float& operator[](int i) { return v[i]; }
#define COLUMBA_SPECTRUM_OP(op)                                                                  \
  Spectrum operator op(const Spectrum& o) const { Spectrum r; for (int i = 0; i < kSpectrumSamples; ++i) r.v[i] = v[i] op o.v[i]; return r; } \
  Spectrum operator op(float s) const { Spectrum r; for (int i = 0; i < kSpectrumSamples; ++i) r.v[i] = v[i] op s; return r; } \
  Spectrum& operator op##=(const Spectrum& o) { for (int i = 0; i < kSpectrumSamples; ++i) v[i] op##= o.v[i]; return *this; } \
  Spectrum& operator op##=(float s) { for (int i = 0; i < kSpectrumSamples; ++i) v[i] op##= s; return *this; }
  COLUMBA_SPECTRUM_OP(+)
  COLUMBA_SPECTRUM_OP(-)
  COLUMBA_SPECTRUM_OP(*)
  COLUMBA_SPECTRUM_OP(/)
#undef COLUMBA_SPECTRUM_OP
  float average() const { float s = 0; for (float x : v) s += x; return s / kSpectrumSamples; }
  float maxValue() const { float m = v[0]; for (float x : v) m = std::max(m, x); return m; }
  bool isZero() const { for (float x : v) if (x != 0.0f) return false; return true; }
  bool isFinite() const { for (float x : v) if (!std::isfinite(x)) return false; return true; }
};
inline Spectrum operator*(float s, const Spectrum& a) { return a * s; }

// The wavelengths (nm) a path carries and the density each was drawn with.
struct Wavelengths {
  std::array<float, kSpectrumSamples> lambda{};
  std::array<float, kSpectrumSamples> pdf{};
  float operator[](int i) const { return lambda[i]; }

  // Hero wavelength from `u`, the others at equal offsets in sample space (pbrt-v4's
  // visible-wavelength density, which follows the eye's sensitivity).
  static Wavelengths sampleVisible(float u);
  // Fixed wavelengths with unit pdf, for tests and plots.
  static Wavelengths fixed(std::array<float, kSpectrumSamples> l);
};
float visibleWavelengthPdf(float lambda);
float sampleVisibleWavelength(float u);

// CIE 1931 2-degree colour matching functions (multi-lobe fit of Wyman, Sloan & Shirley 2013),
// evaluated exactly by cieXYZFit and from a 1 nm table by cieXYZ.
Vec3 cieXYZFit(float lambda);
Vec3 cieXYZ(float lambda);
// Integral of ybar over [360, 830] nm, so that a flat spectrum of 1 has Y = 1.
float cieYIntegral();

// Linear Rec.709/sRGB primaries with the plain matrix (no white balance, as Mitsuba): D65 is
// (1, 1, 1) and a flat (equal-energy) spectrum is slightly pink.
Vec3 xyzToLinearRGB(const Vec3& xyz);
// Monte Carlo estimate of a spectrum's linear RGB from its values at `wl`.
Vec3 spectrumToRGB(const Spectrum& s, const Wavelengths& wl);

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
  Spectrum sample(const Wavelengths& wl) const {
    Spectrum s;
    for (int i = 0; i < kSpectrumSamples; ++i) s[i] = eval(wl[i]);
    return s;
  }
  // Mean over the visible range, for light selection and diagnostics.
  float meanValue() const;

 private:
  float evalShape(float lambda) const;  // eval without the illuminant

  enum class Kind { Constant, Piecewise, Sigmoid } kind_ = Kind::Constant;
  bool timesD65_ = false;
  float value_ = 0.0f;                 // constant value, or the sigmoid's scale
  std::vector<float> lambdas_, values_;
  std::array<float, 3> coeffs_{};      // sigmoid polynomial in normalised wavelength
};

}  // namespace columba
