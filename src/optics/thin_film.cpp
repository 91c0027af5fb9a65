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

namespace {
constexpr SpectrumLanes lanes(float c) { return SpectrumLanes{c, c, c, c}; }
}  // namespace

const FreeStandingFilm::Constants FreeStandingFilm::kConstants = {lanes(1.0f / kPi), lanes(kPi), lanes(12582912.0f)};

FreeStandingFilm::FreeStandingFilm(const CauchyIOR& film, float nOutside, float thicknessUm,
                                   const Wavelengths& wl) {
  SpectrumLanes lambda = toLanes(wl.lambda);
  SpectrumLanes eta = (film.a + film.b / (lambda * lambda)) * (1.0f / nOutside);
  medium_.etaSqr = eta * eta;
  medium_.invEtaSqr = 1.0f / medium_.etaSqr;
  medium_.etaSqrMinusOne = medium_.etaSqr - 1.0f;
  medium_.bsSqr = medium_.etaSqrMinusOne * medium_.etaSqrMinusOne;
  // delta = 4 pi nFilm d cos(theta_film) / lambda and nFilm cos(theta_film) = nOutside q.
  medium_.halfPhaseScale = (2.0f * kPi * thicknessUm * 1000.0f * nOutside) / lambda;
}

}  // namespace columba
