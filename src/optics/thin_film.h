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

// A film (index nFilm(lambda), optically denser than its surroundings) with the same medium on
// both sides, evaluated at a path's wavelengths: the barbule cortex in air. With a lossless film
// and equal media, R + T = 1 per polarisation, so the transmittance is 1 - R. Real arithmetic only
// (for R12 = r12^2, R = 2 R12 (1 - cos delta) / (1 + R12^2 - 2 R12 cos delta)), laid out so the
// compiler evaluates the wavelengths in SIMD lanes.
class FreeStandingFilm {
 public:
  FreeStandingFilm() = default;
  FreeStandingFilm(const CauchyIOR& film, float nOutside, float thicknessUm, const Wavelengths& wl);

  struct Reflectance {
    std::array<float, kSpectrumSamples> s, p;
  };
  // Intensity reflectance for light meeting the film with incidence cosine `cosIncidence` (>= 0).
  Reflectance reflectance(float cosIncidence) const;

 private:
  std::array<float, kSpectrumSamples> eta_{};         // nFilm / nOutside
  std::array<float, kSpectrumSamples> invEtaSqr_{};   // 1 / eta^2 (Snell's law for sin^2)
  std::array<float, kSpectrumSamples> phaseScale_{};  // 4 pi nFilm d / lambda: delta = phaseScale cos(theta2)
};

}  // namespace columba
