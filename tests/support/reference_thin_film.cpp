#include "support/reference_thin_film.h"

#include <algorithm>
#include <cmath>
#include <utility>

namespace columba::reference {

double keratinIndex(double lambdaNm) { return 1.532 + 5890.0 / (lambdaNm * lambdaNm); }

Interface fresnelInterface(double ni, Complex ci, double nj, Complex cj) {
  Interface f;
  f.rs = (ni * ci - nj * cj) / (ni * ci + nj * cj);
  f.rp = (nj * ci - ni * cj) / (nj * ci + ni * cj);
  f.ts = 2.0 * ni * ci / (ni * ci + nj * cj);
  f.tp = 2.0 * ni * ci / (nj * ci + ni * cj);
  return f;
}

Complex cosineInMedium(double n, double nSin) {
  double sinSqr = (nSin / n) * (nSin / n);
  Complex c = std::sqrt(Complex(1.0 - sinSqr, 0.0));
  return c.imag() < 0.0 ? -c : c;
}

namespace {

struct Stack {
  Complex cos1, cos2, cos3;
  Interface top, bottom, topUp;  // 1 -> 2, 2 -> 3, and 2 -> 1 for the partial waves
  Complex phase;
};

Stack stack(double cosIncidence, double n1, double n2, double n3, double thicknessUm, double lambdaNm,
            double phaseScale) {
  Stack s;
  double c1 = std::min(std::abs(cosIncidence), 1.0);
  double nSin = n1 * std::sqrt(1.0 - c1 * c1);  // Snell's invariant
  s.cos1 = Complex(c1, 0.0);
  s.cos2 = cosineInMedium(n2, nSin);
  s.cos3 = cosineInMedium(n3, nSin);
  s.top = fresnelInterface(n1, s.cos1, n2, s.cos2);
  s.bottom = fresnelInterface(n2, s.cos2, n3, s.cos3);
  s.topUp = fresnelInterface(n2, s.cos2, n1, s.cos1);
  double dNm = thicknessUm * 1000.0;
  // Optical path difference of one round trip through the film: 2 n2 d cos(theta2).
  s.phase = phaseScale * 2.0 * M_PI * 2.0 * n2 * dNm * s.cos2 / lambdaNm;
  return s;
}

}  // namespace

AiryFilm airyFilm(double cosIncidence, double n1, double n2, double n3, double thicknessUm, double lambdaNm,
                  double phaseScale) {
  Stack s = stack(cosIncidence, n1, n2, n3, thicknessUm, lambdaNm, phaseScale);
  const Complex i(0.0, 1.0);
  Complex e = std::exp(i * s.phase), eHalf = std::exp(0.5 * i * s.phase);
  AiryFilm f;
  f.phase = s.phase;
  f.rs = (s.top.rs + s.bottom.rs * e) / (1.0 + s.top.rs * s.bottom.rs * e);
  f.rp = (s.top.rp + s.bottom.rp * e) / (1.0 + s.top.rp * s.bottom.rp * e);
  f.ts = s.top.ts * s.bottom.ts * eHalf / (1.0 + s.top.rs * s.bottom.rs * e);
  f.tp = s.top.tp * s.bottom.tp * eHalf / (1.0 + s.top.rp * s.bottom.rp * e);
  double c1 = s.cos1.real();
  f.flux = c1 > 0.0 ? std::max(0.0, n3 * s.cos3.real()) / (n1 * c1) : 0.0;
  return f;
}

std::pair<Complex, Complex> partialWaveSum(double cosIncidence, double n1, double n2, double n3, double thicknessUm,
                                           double lambdaNm, int bounces) {
  Stack s = stack(cosIncidence, n1, n2, n3, thicknessUm, lambdaNm, 1.0);
  Complex e = std::exp(Complex(0.0, 1.0) * s.phase);
  auto sum = [&](Complex r12, Complex t12, Complex r23, Complex r21, Complex t21) {
    Complex r = r12, wave = t12 * r23 * t21 * e;
    for (int k = 0; k < bounces; ++k) {
      r += wave;
      wave *= r21 * r23 * e;  // one more round trip inside the film
    }
    return r;
  };
  return {sum(s.top.rs, s.top.ts, s.bottom.rs, s.topUp.rs, s.topUp.ts),
          sum(s.top.rp, s.top.tp, s.bottom.rp, s.topUp.rp, s.topUp.tp)};
}

double freeStandingReflectanceEnvelope(double cosIncidence, double nOutside, double nFilm) {
  double c1 = std::min(std::abs(cosIncidence), 1.0);
  Complex cos2 = cosineInMedium(nFilm, nOutside * std::sqrt(1.0 - c1 * c1));
  Interface f = fresnelInterface(nOutside, Complex(c1, 0.0), nFilm, cos2);
  auto peak = [](Complex r12) {
    double R = std::norm(r12);
    return 4.0 * R / ((1.0 + R) * (1.0 + R));
  };
  return 0.5 * (peak(f.rs) + peak(f.rp));
}

double freeStandingTransmittanceProduct(double cos1, double cos2, double nOutside, double nFilm, double thicknessUm,
                                        double lambdaNm, double phaseScale) {
  AiryFilm in = airyFilm(cos1, nOutside, nFilm, nOutside, thicknessUm, lambdaNm, phaseScale);
  AiryFilm out = airyFilm(cos2, nOutside, nFilm, nOutside, thicknessUm, lambdaNm, phaseScale);
  return 0.5 * (in.transmittanceS() * out.transmittanceS() + in.transmittanceP() * out.transmittanceP());
}

}  // namespace columba::reference
