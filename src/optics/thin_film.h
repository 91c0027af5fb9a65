#pragma once
// Interference in a thin dielectric film (Airy summation of the multiply reflected waves).
//
// Layers: an incident medium n1, a film n2 of thickness d, a substrate n3. The film's round trip
// adds the phase delta = 4 pi n2 d cos(theta2) / lambda, and
//   r = (r12 + r23 e^{i delta}) / (1 + r12 r23 e^{i delta}),
//   t = t12 t23 e^{i delta / 2} / (1 + r12 r23 e^{i delta}),
// which for n3 = n1 is the form r = r12 + t12 r21 t21 e^{i delta} / (1 - r21^2 e^{i delta}) with
// t = t12 t21 / (1 - r21^2 e^{i delta}) up to the phase of t.
#include <complex>
#include "core/fast_math.h"
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
double thinFilmReflectance(double cosIncidence, double n1, double n2, double n3, double thicknessUm, double lambdaNm);
double thinFilmTransmittance(double cosIncidence, double n1, double n2, double n3, double thicknessUm, double lambdaNm);

// A film (index nFilm(lambda), optically denser than its surroundings) with the same medium on
// both sides, evaluated at a path's wavelengths: the barbule cortex in air. With a lossless film
// and equal media, R + T = 1 per polarisation. Real arithmetic only: from the Airy sum
// R = 2 R12 (1 - cos delta) / ((1 - R12)^2 + 2 R12 (1 - cos delta)) with the interface reflectance
// R12 = ((a - b) / (a + b))^2, per polarisation
//   R = B^2 S / (A^2 + B^2 S),  T = A^2 / (A^2 + B^2 S),  A = 2 a b,  B = a^2 - b^2,  S = sin^2(delta / 2),
// where a = c, b = q for s and a = eta c, b = q / eta for p, with c the incidence cosine, eta the
// relative index and q = eta cos(theta_film) = sqrt(eta^2 - 1 + c^2). So A = 2 c q for both,
// B_s = 1 - eta^2 is constant, and no interface Fresnel division is needed.
class FreeStandingFilm {
 public:
  FreeStandingFilm() = default;
  FreeStandingFilm(const RefractiveIndex& film, float nOutside, float thicknessUm, const Wavelengths& wl);

  struct Reflectance {
    Spectrum s, p;
  };
  // Intensity reflectance for light meeting the film with incidence cosine `cosIncidence` (>= 0).
  Reflectance reflectance(float cosIncidence) const;
  // Unpolarised transmittance of two crossings, 1/2 (T_s(cos1) T_s(cos2) + T_p(cos1) T_p(cos2)):
  // light entering the film at one angle and leaving it at another (one division for all four).
  Spectrum transmittanceProduct(float cos1, float cos2) const;
  // The same for four pairs of cosines, one per lane (a quadrature's nodes), weighted and summed
  // over the lanes: the sum at each of the path's wavelengths. On processors with AVX2 and FMA
  // both crossings of a wavelength are evaluated at once in eight lanes.
  Spectrum weightedTransmittanceProducts(FloatLanes weight, FloatLanes cos1, FloatLanes cos2) const;
  // Its two implementations (public so that tests compare them): four lanes on any x86-64, and
  // eight lanes, which needs a processor with AVX2 and FMA (hasAvx2()).
  Spectrum weightedTransmittanceProductsPortable(FloatLanes weight, FloatLanes cos1, FloatLanes cos2) const;
  __attribute__((target("avx2,fma"))) Spectrum weightedTransmittanceProductsAvx2(FloatLanes weight, FloatLanes cos1,
                                                                                 FloatLanes cos2) const;

  // At four incidence cosines, one per lane, averages over the path's wavelengths of the
  // reflectance (R_s + R_p) / 2 and of the transmittance of two crossings at the same angle
  // weighted per wavelength, w (T_s^2 + T_p^2) / 2. On processors with AVX2 and FMA two
  // wavelengths are evaluated at once in eight lanes.
  struct Averages {
    FloatLanes reflectance, weightedTransmittanceSqr;
  };
  Averages averagesOverWavelengths(FloatLanes cosIncidence, const Spectrum& transmittanceWeight) const;
  Averages averagesOverWavelengthsPortable(FloatLanes cosIncidence, const Spectrum& transmittanceWeight) const;
  __attribute__((target("avx2,fma"))) Averages averagesOverWavelengthsAvx2(FloatLanes cosIncidence,
                                                                           const Spectrum& transmittanceWeight) const;

 private:
  // The film's constants at the path's wavelengths, one per lane as in a Spectrum (the kernels
  // below work on the lanes themselves), or one wavelength in every lane.
  struct Medium {
    FloatLanes etaSqrMinusOne;  // eta^2 - 1, eta = nFilm / nOutside
    FloatLanes etaSqr, invEtaSqr;
    FloatLanes bsSqr;           // B_s^2 = (1 - eta^2)^2
    FloatLanes halfPhaseScale;  // delta / 2 = halfPhaseScale q: 2 pi nOutside d / lambda
  };
  // One wavelength's constants, for evaluating it in every lane.
  struct MediumAt {
    float etaSqrMinusOne, etaSqr, invEtaSqr, bsSqr, halfPhaseScale;
  };
  MediumAt mediumAt(int k) const {
    return {medium_.etaSqrMinusOne[k], medium_.etaSqr[k], medium_.invEtaSqr[k], medium_.bsSqr[k],
            medium_.halfPhaseScale[k]};
  }
  // A^2 and B^2 S of the two polarisations, per lane.
  template <typename Lanes>
  struct TermsOf {
    Lanes aSqr, sBSqrS, pBSqrS;
  };
  using Terms = TermsOf<FloatLanes>;
  // From the incidence cosines' squares, clamped to [1e-8, 1]: exactly grazing light would make
  // A = 0 and, where S = 0 too, the Airy sum 0/0. `m` is a Medium (a wavelength per lane) or a
  // MediumAt; Lanes is four or, in the AVX2 path, eight lanes (always inlined into its caller,
  // whose instruction set it then uses).
  template <typename M, typename Lanes>
  __attribute__((always_inline)) static TermsOf<Lanes> terms(const M& m, Lanes cSqr, Lanes qSqr, Lanes q);
  template <typename M>
  static Terms terms(const M& m, FloatLanes cSqr) {
    FloatLanes qSqr = m.etaSqrMinusOne + cSqr;  // the film is denser, so light always enters it
    return terms(m, cSqr, qSqr, sqrtLanes(qSqr));
  }
  template <typename Lanes>
  __attribute__((always_inline)) static Lanes clampedCosSqr(Lanes c) {
    c = c < 1e-4f ? 1e-4f + Lanes{} : c;
    c = c > 1.0f ? 1.0f + Lanes{} : c;
    return c * c;
  }
  static FloatLanes product(const Terms& a, const Terms& b);
  // R = (R_s + R_p) / 2 and (T_s^2 + T_p^2) / 2 from one crossing's terms, one division for both.
  template <typename Lanes>
  __attribute__((always_inline)) static void reflectanceAndTransmittanceSqr(const TermsOf<Lanes>& t, Lanes& r,
                                                                            Lanes& tSqr) {
    Lanes sDen = t.aSqr + t.sBSqrS, pDen = t.aSqr + t.pBSqrS;
    Lanes inv = 1.0f / (sDen * pDen);
    r = 0.5f * (t.sBSqrS * pDen + t.pBSqrS * sDen) * inv;
    Lanes ts = t.aSqr * pDen * inv, tp = t.aSqr * sDen * inv;
    tSqr = 0.5f * (ts * ts + tp * tp);
  }

  Medium medium_{};  // at the path's wavelengths
};

template <typename M, typename Lanes>
inline FreeStandingFilm::TermsOf<Lanes> FreeStandingFilm::terms(const M& m, Lanes cSqr, Lanes qSqr, Lanes q) {
  Lanes S = sinSqr(m.halfPhaseScale * q);
  Lanes aSqr = 4.0f * cSqr * qSqr;
  Lanes bp = m.etaSqr * cSqr - qSqr * m.invEtaSqr;
  return {aSqr, m.bsSqr * S, bp * bp * S};
}

inline FloatLanes FreeStandingFilm::product(const Terms& a, const Terms& b) {
  // 1/2 A1^2 A2^2 (1 / (sDen1 sDen2) + 1 / (pDen1 pDen2)) with den = A^2 + B^2 S; every den is at
  // least A^2 > 5e-8, so the product of the four stays a normal float.
  FloatLanes sProduct = (a.aSqr + a.sBSqrS) * (b.aSqr + b.sBSqrS);
  FloatLanes pProduct = (a.aSqr + a.pBSqrS) * (b.aSqr + b.pBSqrS);
  return (0.5f * a.aSqr * b.aSqr) * (sProduct + pProduct) / (sProduct * pProduct);
}

inline FreeStandingFilm::Reflectance FreeStandingFilm::reflectance(float cosIncidence) const {
  Terms t = terms(medium_, clampedCosSqr(cosIncidence + FloatLanes{}));
  // One division serves both polarisations.
  FloatLanes sDen = t.aSqr + t.sBSqrS, pDen = t.aSqr + t.pBSqrS;
  FloatLanes inv = 1.0f / (sDen * pDen);
  return {Spectrum(t.sBSqrS * pDen * inv), Spectrum(t.pBSqrS * sDen * inv)};
}

inline Spectrum FreeStandingFilm::transmittanceProduct(float cos1, float cos2) const {
  Terms first = terms(medium_, clampedCosSqr(cos1 + FloatLanes{}));
  Terms second = terms(medium_, clampedCosSqr(cos2 + FloatLanes{}));
  return Spectrum(product(first, second));
}

}  // namespace columba
