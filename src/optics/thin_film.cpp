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

// cos(x) for |x| up to a few hundred, branch-free so loops over wavelengths vectorise: reduce to
// [-pi, pi] and use the even Taylor polynomial of degree 16 (error < 2e-7 there).
inline float cosReduced(float x) {
  constexpr float kRound = 12582912.0f;  // 1.5 * 2^23: adding and subtracting it rounds to nearest
  float turns = x * (1.0f / kTwoPi);
  float k = (turns + kRound) - kRound;
  float y = (turns - k) * kTwoPi;
  float y2 = y * y;
  float p = 1.0f / 20922789888000.0f;  // 1/16!
  p = p * y2 - 1.0f / 87178291200.0f;
  p = p * y2 + 1.0f / 479001600.0f;
  p = p * y2 - 1.0f / 3628800.0f;
  p = p * y2 + 1.0f / 40320.0f;
  p = p * y2 - 1.0f / 720.0f;
  p = p * y2 + 1.0f / 24.0f;
  p = p * y2 - 0.5f;
  return p * y2 + 1.0f;
}

}  // namespace

ThinFilmAmplitudes thinFilmAmplitudes(double cosIncidence, double n1, double n2, double n3, double thicknessUm,
                                      double lambdaNm) {
  double c1 = std::min(std::abs(cosIncidence), 1.0);
  double nSin = n1 * std::sqrt(std::max(0.0, 1.0 - c1 * c1));
  Complex cos1(c1, 0.0), cos2 = cosineIn(n2, nSin), cos3 = cosineIn(n3, nSin);
  Interface top = fresnel(n1, cos1, n2, cos2), bottom = fresnel(n2, cos2, n3, cos3);

  Complex delta = 4.0 * M_PI * n2 * (thicknessUm * 1000.0) * cos2 / lambdaNm;
  Complex roundTrip = std::exp(Complex(0.0, 1.0) * delta), halfTrip = std::exp(Complex(0.0, 0.5) * delta);

  ThinFilmAmplitudes a;
  a.rs = (top.rs + bottom.rs * roundTrip) / (1.0 + top.rs * bottom.rs * roundTrip);
  a.rp = (top.rp + bottom.rp * roundTrip) / (1.0 + top.rp * bottom.rp * roundTrip);
  a.ts = top.ts * bottom.ts * halfTrip / (1.0 + top.rs * bottom.rs * roundTrip);
  a.tp = top.tp * bottom.tp * halfTrip / (1.0 + top.rp * bottom.rp * roundTrip);
  a.transmittanceFactor = c1 > 0.0 ? std::max(0.0, (n3 * cos3).real()) / (n1 * c1) : 0.0;
  return a;
}

double thinFilmReflectance(double cosIncidence, double n1, double n2, double n3, double thicknessUm,
                           double lambdaNm) {
  ThinFilmAmplitudes a = thinFilmAmplitudes(cosIncidence, n1, n2, n3, thicknessUm, lambdaNm);
  return 0.5 * (std::norm(a.rs) + std::norm(a.rp));
}

double thinFilmTransmittance(double cosIncidence, double n1, double n2, double n3, double thicknessUm,
                             double lambdaNm) {
  ThinFilmAmplitudes a = thinFilmAmplitudes(cosIncidence, n1, n2, n3, thicknessUm, lambdaNm);
  return 0.5 * a.transmittanceFactor * (std::norm(a.ts) + std::norm(a.tp));
}

FreeStandingFilm::FreeStandingFilm(const CauchyIOR& film, float nOutside, float thicknessUm,
                                   const Wavelengths& wl) {
  for (int i = 0; i < kSpectrumSamples; ++i) {
    float nFilm = film(wl[i]);
    eta_[i] = nFilm / nOutside;
    invEtaSqr_[i] = 1.0f / (eta_[i] * eta_[i]);
    phaseScale_[i] = 4.0f * kPi * nFilm * (thicknessUm * 1000.0f) / wl[i];
  }
}

FreeStandingFilm::Reflectance FreeStandingFilm::reflectance(float cosIncidence) const {
  Reflectance out;
  // Exactly grazing light would make both interface reflectances 1 and the Airy sum 0/0.
  float c = clampf(cosIncidence, 1e-4f, 1.0f), sinSqr = 1.0f - c * c;
  for (int i = 0; i < kSpectrumSamples; ++i) {
    // The film is denser than its surroundings, so light always enters it (no critical angle).
    float cosFilm = std::sqrt(1.0f - sinSqr * invEtaSqr_[i]);
    float etaCosFilm = eta_[i] * cosFilm, etaC = eta_[i] * c;
    // Interface reflectances R and, without cancellation near grazing, 1 - R = 4 c eta cos2 / den^2;
    // one division serves both polarisations.
    float sDen = c + etaCosFilm, pDen = etaC + cosFilm;
    float inv = 1.0f / (sDen * pDen);
    float rs = (c - etaCosFilm) * pDen * inv, rp = (etaC - cosFilm) * sDen * inv;
    float Rs = rs * rs, Rp = rp * rp;
    float fourProduct = 4.0f * etaC * cosFilm * inv * inv;
    float Ts = fourProduct * pDen * pDen, Tp = fourProduct * sDen * sDen;
    float oneMinusCos = 1.0f - cosReduced(phaseScale_[i] * cosFilm);
    // 1 + R^2 - 2 R cos(delta) = (1 - R)^2 + 2 R (1 - cos(delta)) > 0.
    float sNum = 2.0f * Rs * oneMinusCos, pNum = 2.0f * Rp * oneMinusCos;
    float sDenFilm = Ts * Ts + sNum, pDenFilm = Tp * Tp + pNum;
    float invFilm = 1.0f / (sDenFilm * pDenFilm);
    out.s[i] = sNum * pDenFilm * invFilm;
    out.p[i] = pNum * sDenFilm * invFilm;
  }
  return out;
}

}  // namespace columba
