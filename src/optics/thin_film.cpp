#include "optics/thin_film.h"

#include <cmath>

namespace columba {

namespace {

using Complex = std::complex<double>;

// Cosine of the angle in a medium of index n for light with invariant n1 sin(theta1) = nSin;
// imaginary (positive imaginary part: decaying) beyond the critical angle.
Complex cosineIn(double n, double nSin) {
  Complex c = std::sqrt(Complex(1.0 - (nSin / n) * (nSin / n), 0.0));
  return c.imag() < 0.0 ? -c : c;
}

struct Interface {
  Complex rs, rp, ts, tp;
};

// Fresnel amplitudes from medium i into medium j (field ratios).
Interface fresnel(double ni, Complex ci, double nj, Complex cj) {
  Interface f;
  Complex sDen = ni * ci + nj * cj, pDen = nj * ci + ni * cj;
  f.rs = (ni * ci - nj * cj) / sDen;
  f.rp = (nj * ci - ni * cj) / pDen;
  f.ts = 2.0 * ni * ci / sDen;
  f.tp = 2.0 * ni * ci / pDen;
  return f;
}

}  // namespace

ThinFilmAmplitudes thinFilmAmplitudes(double cosIncidence, double n1, double n2, double n3, double thicknessUm,
                                      double lambdaNm) {
  double c1 = std::min(std::abs(cosIncidence), 1.0);
  double nSin = n1 * std::sqrt(std::max(0.0, 1.0 - c1 * c1));
  Complex cos1(c1, 0.0), cos2 = cosineIn(n2, nSin), cos3 = cosineIn(n3, nSin);
  Interface top = fresnel(n1, cos1, n2, cos2), bottom = fresnel(n2, cos2, n3, cos3);

  Complex delta = 4.0 * kPiDouble * n2 * (thicknessUm * 1000.0) * cos2 / lambdaNm;
  Complex roundTrip = std::exp(Complex(0.0, 1.0) * delta), halfTrip = std::exp(Complex(0.0, 0.5) * delta);

  ThinFilmAmplitudes a;
  a.rs = (top.rs + bottom.rs * roundTrip) / (1.0 + top.rs * bottom.rs * roundTrip);
  a.rp = (top.rp + bottom.rp * roundTrip) / (1.0 + top.rp * bottom.rp * roundTrip);
  a.ts = top.ts * bottom.ts * halfTrip / (1.0 + top.rs * bottom.rs * roundTrip);
  a.tp = top.tp * bottom.tp * halfTrip / (1.0 + top.rp * bottom.rp * roundTrip);
  a.transmittanceFactor = c1 > 0.0 ? std::max(0.0, (n3 * cos3).real()) / (n1 * c1) : 0.0;
  return a;
}

double thinFilmReflectance(double cosIncidence, double n1, double n2, double n3, double thicknessUm, double lambdaNm) {
  ThinFilmAmplitudes a = thinFilmAmplitudes(cosIncidence, n1, n2, n3, thicknessUm, lambdaNm);
  return 0.5 * (std::norm(a.rs) + std::norm(a.rp));
}

double thinFilmTransmittance(double cosIncidence, double n1, double n2, double n3, double thicknessUm,
                             double lambdaNm) {
  ThinFilmAmplitudes a = thinFilmAmplitudes(cosIncidence, n1, n2, n3, thicknessUm, lambdaNm);
  return 0.5 * a.transmittanceFactor * (std::norm(a.ts) + std::norm(a.tp));
}

FreeStandingFilm::FreeStandingFilm(const RefractiveIndex& film, float nOutside, float thicknessUm,
                                   const Wavelengths& wl) {
  FloatLanes lambda{wl[0], wl[1], wl[2], wl[3]}, nFilm;
  for (int k = 0; k < kSpectrumSamples; ++k) nFilm[k] = film(wl[k]);
  FloatLanes eta = nFilm * (1.0f / nOutside);
  medium_.etaSqr = eta * eta;
  medium_.invEtaSqr = 1.0f / medium_.etaSqr;
  medium_.etaSqrMinusOne = medium_.etaSqr - 1.0f;
  medium_.bsSqr = medium_.etaSqrMinusOne * medium_.etaSqrMinusOne;
  // delta = 4 pi nFilm d cos(theta_film) / lambda and nFilm cos(theta_film) = nOutside q.
  medium_.halfPhaseScale = (2.0f * kPi * thicknessUm * 1000.0f * nOutside) / lambda;
}

Spectrum FreeStandingFilm::weightedTransmittanceProducts(FloatLanes weight, FloatLanes cos1, FloatLanes cos2) const {
  return hasAvx2() ? weightedTransmittanceProductsAvx2(weight, cos1, cos2)
                   : weightedTransmittanceProductsPortable(weight, cos1, cos2);
}

Spectrum FreeStandingFilm::weightedTransmittanceProductsPortable(FloatLanes weight, FloatLanes cos1,
                                                                 FloatLanes cos2) const {
  // A wavelength at a time, the four pairs in lanes.
  FloatLanes cSqr1 = clampedCosSqr(cos1), cSqr2 = clampedCosSqr(cos2);
  FloatLanes perWavelength[kSpectrumSamples];
  for (int k = 0; k < kSpectrumSamples; ++k) {
    MediumAt m = mediumAt(k);
    perWavelength[k] = weight * product(terms(m, cSqr1), terms(m, cSqr2));
  }
  return Spectrum(laneSums(perWavelength[0], perWavelength[1], perWavelength[2], perWavelength[3]));
}

__attribute__((target("avx2,fma"))) Spectrum FreeStandingFilm::weightedTransmittanceProductsAvx2(
    FloatLanes weight, FloatLanes cos1, FloatLanes cos2) const {
  // A wavelength at a time, both crossings of the four pairs in eight lanes: cos1 low, cos2 high.
  FloatLanes8 cSqr = clampedCosSqr(joinLanes(cos1, cos2));
  FloatLanes perWavelength[kSpectrumSamples];
  for (int k = 0; k < kSpectrumSamples; ++k) {
    MediumAt m = mediumAt(k);
    FloatLanes8 qSqr = m.etaSqrMinusOne + cSqr;
    TermsOf<FloatLanes8> t = terms(m, cSqr, qSqr, sqrtLanes(qSqr));
    Terms first{lowLanes(t.aSqr), lowLanes(t.sBSqrS), lowLanes(t.pBSqrS)};
    Terms second{highLanes(t.aSqr), highLanes(t.sBSqrS), highLanes(t.pBSqrS)};
    perWavelength[k] = weight * product(first, second);
  }
  return Spectrum(laneSums(perWavelength[0], perWavelength[1], perWavelength[2], perWavelength[3]));
}

FreeStandingFilm::Averages FreeStandingFilm::averagesOverWavelengths(FloatLanes cosIncidence,
                                                                     const Spectrum& transmittanceWeight) const {
  return hasAvx2() ? averagesOverWavelengthsAvx2(cosIncidence, transmittanceWeight)
                   : averagesOverWavelengthsPortable(cosIncidence, transmittanceWeight);
}

FreeStandingFilm::Averages FreeStandingFilm::averagesOverWavelengthsPortable(
    FloatLanes cosIncidence, const Spectrum& transmittanceWeight) const {
  // A wavelength at a time, the four cosines in lanes.
  FloatLanes cSqr = clampedCosSqr(cosIncidence);
  Averages sum{};
  for (int k = 0; k < kSpectrumSamples; ++k) {
    FloatLanes r, tSqr;
    reflectanceAndTransmittanceSqr(terms(mediumAt(k), cSqr), r, tSqr);
    sum.reflectance += r;
    sum.weightedTransmittanceSqr += transmittanceWeight[k] * tSqr;
  }
  const float mean = 1.0f / float(kSpectrumSamples);
  return {sum.reflectance * mean, sum.weightedTransmittanceSqr * mean};
}

namespace {
// Lane k of `v` in the low four lanes and lane k + 1 in the high four.
__attribute__((target("avx2,fma"), always_inline)) inline FloatLanes8 pairOf(FloatLanes v, int k) {
  return FloatLanes8{v[k], v[k], v[k], v[k], v[k + 1], v[k + 1], v[k + 1], v[k + 1]};
}
}  // namespace

__attribute__((target("avx2,fma"))) FreeStandingFilm::Averages FreeStandingFilm::averagesOverWavelengthsAvx2(
    FloatLanes cosIncidence, const Spectrum& transmittanceWeight) const {
  // Two wavelengths at a time: wavelength k in the low four lanes, k + 1 in the high four.
  struct MediumPair {
    FloatLanes8 etaSqr, invEtaSqr, bsSqr, halfPhaseScale;
  };
  static_assert(kSpectrumSamples % 2 == 0);
  FloatLanes8 cSqr = clampedCosSqr(joinLanes(cosIncidence, cosIncidence));
  FloatLanes8 reflectance{}, weightedTSqr{};
  for (int k = 0; k < kSpectrumSamples; k += 2) {
    MediumPair m{pairOf(medium_.etaSqr, k), pairOf(medium_.invEtaSqr, k), pairOf(medium_.bsSqr, k),
                 pairOf(medium_.halfPhaseScale, k)};
    FloatLanes8 qSqr = pairOf(medium_.etaSqrMinusOne, k) + cSqr;
    FloatLanes8 r, tSqr;
    reflectanceAndTransmittanceSqr(terms(m, cSqr, qSqr, sqrtLanes(qSqr)), r, tSqr);
    reflectance += r;
    weightedTSqr += pairOf(transmittanceWeight.lanes, k) * tSqr;
  }
  const float mean = 1.0f / float(kSpectrumSamples);
  return {(lowLanes(reflectance) + highLanes(reflectance)) * mean,
          (lowLanes(weightedTSqr) + highLanes(weightedTSqr)) * mean};
}

}  // namespace columba
