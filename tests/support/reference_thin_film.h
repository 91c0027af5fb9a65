#pragma once
// Test-only reference of thin-film interference, written plainly in the textbook's terms and in
// double precision, to check the production film (optics/thin_film.h) against: complex Fresnel
// amplitudes per interface, the round-trip phase and the Airy sum of the multiply reflected waves.
// Nothing here shares code with the production film.
//
// Layers: incident medium n1 | film n2 of thickness d | substrate n3, real indices (the barbule's
// keratin cortex is lossless; the melanin under it enters the model as a measured intensity
// reflectance, not as a layer). Beyond a critical angle the cosines are complex (evanescent waves).
#include <complex>
#include <utility>

namespace columba::reference {

using Complex = std::complex<double>;

// Keratin after Cauchy (the model's film): n = 1.532 + 5890 / lambda^2, lambda in nm.
double keratinIndex(double lambdaNm);
inline constexpr double kAirIndex = 1.000277;

// Field amplitudes of one interface from medium i into medium j (cosines ci, cj of the angles
// there), s and p polarisation, with the convention t_p = 2 n_i c_i / (n_j c_i + n_i c_j).
struct Interface {
  Complex rs, rp, ts, tp;
};
Interface fresnelInterface(double ni, Complex ci, double nj, Complex cj);

// Cosine of the angle in a medium of index n for the invariant nSin = n1 sin(theta1); the root
// with non-negative imaginary part (a wave that decays away from the interface).
Complex cosineInMedium(double n, double nSin);

struct AiryFilm {
  Complex rs, rp;  // reflected over incident field
  Complex ts, tp;  // transmitted (into the substrate) over incident field
  Complex phase;   // round-trip phase 2 pi 2 n2 d cos(theta2) / lambda (complex beyond critical)
  // Intensity transmittance per polarisation is flux * |t|^2: n3 Re(cos3) / (n1 cos1).
  double flux = 0.0;
  double reflectanceS() const { return std::norm(rs); }
  double reflectanceP() const { return std::norm(rp); }
  double transmittanceS() const { return flux * std::norm(ts); }
  double transmittanceP() const { return flux * std::norm(tp); }
  // Unpolarised: the mean of the two polarisations.
  double reflectance() const { return 0.5 * (reflectanceS() + reflectanceP()); }
  double transmittance() const { return 0.5 * (transmittanceS() + transmittanceP()); }
};

// The Airy sum r = (r12 + r23 e^{i phi}) / (1 + r12 r23 e^{i phi}),
// t = t12 t23 e^{i phi / 2} / (1 + r12 r23 e^{i phi}), for light meeting the film with incidence
// cosine `cosIncidence` (in the incident medium; its sign is ignored), d in micrometres and the
// vacuum wavelength in nanometres. `phaseScale` multiplies the round-trip phase (1 for the
// physics; tests use it to show what a phase error would look like).
AiryFilm airyFilm(double cosIncidence, double n1, double n2, double n3, double thicknessUm, double lambdaNm,
                  double phaseScale = 1.0);

// The same film's reflected amplitude as the explicit sum of the partial waves
// r12 + t12 r23 t21 e^{i phi} sum_k (r21 r23 e^{i phi})^k, `bounces` terms: an independent check
// of the closed form. Returns {r_s, r_p}.
std::pair<Complex, Complex> partialWaveSum(double cosIncidence, double n1, double n2, double n3, double thicknessUm,
                                           double lambdaNm, int bounces);

// A film with the same medium on both sides (a free-standing film): the largest unpolarised
// reflectance over all thicknesses at this angle, reached where e^{i phi} = -1:
// 1/2 sum over s, p of (2 |r12| / (1 + |r12|^2))^2. The scale against which reflectance errors of
// an interference pattern are judged: near its zeros the reflectance itself is arbitrarily small.
double freeStandingReflectanceEnvelope(double cosIncidence, double nOutside, double nFilm);

// Intensity transmittance of two crossings of a free-standing film, entering at cos1 and leaving
// at cos2, each polarisation keeping its state: 1/2 (T_s(cos1) T_s(cos2) + T_p(cos1) T_p(cos2)).
double freeStandingTransmittanceProduct(double cos1, double cos2, double nOutside, double nFilm, double thicknessUm,
                                        double lambdaNm, double phaseScale = 1.0);

}  // namespace columba::reference
