#pragma once
// Interference in a thin dielectric film (Airy summation of the multiply reflected waves).
//
// Layers: an incident medium n1, a film n2 of thickness d, a substrate n3. The film's round trip
// adds the phase delta = 4 pi n2 d cos(theta2) / lambda, and
//   r = (r12 + r23 e^{i delta}) / (1 + r12 r23 e^{i delta}),
//   t = t12 t23 e^{i delta / 2} / (1 + r12 r23 e^{i delta}),
// which for n3 = n1 is the form r = r12 + t12 r21 t21 e^{i delta} / (1 - r21^2 e^{i delta}) with
// t = t12 t21 / (1 - r21^2 e^{i delta}) up to the phase of t.
#include <array>
#include <complex>
#if defined(__SSE__)
#include <xmmintrin.h>
#endif
#include "core/spectrum.h"
#include "optics/dispersion.h"

namespace columba {

struct ThinFilmAmplitudes {
  std::complex<double> rs, rp;  // reflected field over incident field, s and p polarisation
  std::complex<double> ts, tp;  // transmitted field (into the substrate) over incident field
  // Transmittance per polarisation is transmittanceFactor * |t|^2, the ratio of the beams'
  // normal energy flux n3 cos(theta3) / (n1 cos(theta1)); 0 when the substrate is reached only
  // by an evanescent wave.
  double transmittanceFactor = 0.0;
};

// `cosIncidence` in the incident medium (its sign is ignored), thickness in micrometres,
// wavelength in nanometres (in vacuum). Any real indices: total internal reflection in the film
// or at the substrate gives evanescent waves, handled by complex cosines.
ThinFilmAmplitudes thinFilmAmplitudes(double cosIncidence, double n1, double n2, double n3, double thicknessUm,
                                      double lambdaNm);

// Unpolarised intensity reflectance and transmittance of the same stack.
double thinFilmReflectance(double cosIncidence, double n1, double n2, double n3, double thicknessUm,
                           double lambdaNm);
double thinFilmTransmittance(double cosIncidence, double n1, double n2, double n3, double thicknessUm,
                             double lambdaNm);

// Four wavelengths' values in one SIMD register (GCC/Clang vector extension): the film is
// evaluated at every quadrature node of the barbule BSDF, so its arithmetic must not depend on
// the compiler choosing to vectorise a loop.
using SpectrumLanes = float __attribute__((vector_size(16)));
static_assert(kSpectrumSamples == 4, "one SIMD register per path spectrum");

inline SpectrumLanes toLanes(const std::array<float, kSpectrumSamples>& a) {
  return SpectrumLanes{a[0], a[1], a[2], a[3]};
}
inline Spectrum toSpectrum(SpectrumLanes v) {
  Spectrum s;
  for (int i = 0; i < kSpectrumSamples; ++i) s[i] = v[i];
  return s;
}

// A film (index nFilm(lambda), optically denser than its surroundings) with the same medium on
// both sides, evaluated at a path's wavelengths: the barbule cortex in air. With a lossless film
// and equal media, R + T = 1 per polarisation, so the transmittance is 1 - R. Real arithmetic only:
// for the interface reflectance R12 = r12^2, R = 2 R12 (1 - cos delta) / (1 + R12^2 - 2 R12 cos delta).
class FreeStandingFilm {
 public:
  FreeStandingFilm() = default;
  FreeStandingFilm(const CauchyIOR& film, float nOutside, float thicknessUm, const Wavelengths& wl);

  struct Reflectance {
    SpectrumLanes s, p;
  };
  // Intensity reflectance for light meeting the film with incidence cosine `cosIncidence` (>= 0).
  Reflectance reflectance(float cosIncidence) const;

 private:
  // Constants of the evaluation as full vectors, defined out of line: the arithmetic then reads
  // them as memory operands, where a visible constant is re-broadcast from a scalar at each use.
  struct Constants {
    SpectrumLanes one, two, invTwoPi, twoPi, round;
    SpectrumLanes cosTaylor[9];  // coefficients of y^16, y^14, ..., y^0 of cos(y)
  };
  static const Constants kConstants;

  // cos(x) for |x| up to a few hundred: reduce to [-pi, pi] and use the even Taylor polynomial of
  // degree 16 (error < 2e-7 there).
  static SpectrumLanes cosReduced(SpectrumLanes x) {
    const Constants& k = kConstants;
    SpectrumLanes turns = x * k.invTwoPi;
    SpectrumLanes whole = (turns + k.round) - k.round;  // rounds to nearest: 1.5 * 2^23
    SpectrumLanes y = (turns - whole) * k.twoPi;
    SpectrumLanes y2 = y * y;
    SpectrumLanes p = k.cosTaylor[0];
    for (int i = 1; i < 9; ++i) p = p * y2 + k.cosTaylor[i];
    return p;
  }
  static SpectrumLanes sqrtLanes(SpectrumLanes v) {
#if defined(__SSE__)
    return _mm_sqrt_ps(v);
#else
    return SpectrumLanes{std::sqrt(v[0]), std::sqrt(v[1]), std::sqrt(v[2]), std::sqrt(v[3])};
#endif
  }

  SpectrumLanes eta_{};         // nFilm / nOutside
  SpectrumLanes invEtaSqr_{};   // 1 / eta^2 (Snell's law for sin^2)
  SpectrumLanes phaseScale_{};  // 4 pi nFilm d / lambda: delta = phaseScale cos(theta2)
};

inline FreeStandingFilm::Reflectance FreeStandingFilm::reflectance(float cosIncidence) const {
  const SpectrumLanes kOne = kConstants.one, kTwo = kConstants.two;
  // Exactly grazing light would make both interface reflectances 1 and the Airy sum 0/0.
  float cScalar = clampf(cosIncidence, 1e-4f, 1.0f);
  SpectrumLanes c = cScalar + SpectrumLanes{}, sinSqr = (1.0f - cScalar * cScalar) + SpectrumLanes{};
  // The film is denser than its surroundings, so light always enters it (no critical angle).
  SpectrumLanes cosFilm = sqrtLanes(kOne - sinSqr * invEtaSqr_);
  SpectrumLanes etaCosFilm = eta_ * cosFilm, etaC = eta_ * c;
  // Interface reflectances; one division serves both polarisations.
  SpectrumLanes sDen = c + etaCosFilm, pDen = etaC + cosFilm;
  SpectrumLanes inv = kOne / (sDen * pDen);
  SpectrumLanes rs = (c - etaCosFilm) * pDen * inv, rp = (etaC - cosFilm) * sDen * inv;
  SpectrumLanes Rs = rs * rs, Rp = rp * rp;
  SpectrumLanes Ts = kOne - Rs, Tp = kOne - Rp;
  SpectrumLanes oneMinusCos = kOne - cosReduced(phaseScale_ * cosFilm);
  // 1 + R^2 - 2 R cos(delta) = (1 - R)^2 + 2 R (1 - cos(delta)) > 0.
  SpectrumLanes sNum = kTwo * Rs * oneMinusCos, pNum = kTwo * Rp * oneMinusCos;
  SpectrumLanes sDenFilm = Ts * Ts + sNum, pDenFilm = Tp * Tp + pNum;
  SpectrumLanes invFilm = kOne / (sDenFilm * pDenFilm);
  return {sNum * pDenFilm * invFilm, pNum * sDenFilm * invFilm};
}

}  // namespace columba
