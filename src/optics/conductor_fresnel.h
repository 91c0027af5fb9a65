#pragma once
// Fresnel reflectance of a smooth conductor (an absorbing medium with complex index eta + i k).
#include <complex>
#include "core/math.h"

namespace columba {

// Unpolarised reflectance for light arriving with cos(theta_i) = cosI (clamped to [0, 1]) on a
// conductor with complex index eta + i k relative to the outside medium. k = 0 gives the
// dielectric Fresnel reflectance; eta = 0, k = 1 is a perfect mirror, and so is eta = k = 0 (the
// limit as the index vanishes, which the formula below would divide by).
inline float fresnelConductor(float cosI, float eta, float k) {
  using Complex = std::complex<float>;
  if (eta == 0.0f && k == 0.0f) return 1.0f;
  cosI = clampf(cosI, 0.0f, 1.0f);
  const Complex n(eta, k);
  // Snell's law with a complex index: the principal root gives the wave decaying into the metal.
  const Complex cosT = std::sqrt(Complex(1.0f) - (1.0f - cosI * cosI) / (n * n));
  const Complex rs = (cosI - n * cosT) / (cosI + n * cosT);
  const Complex rp = (n * cosI - cosT) / (n * cosI + cosT);
  return 0.5f * (std::norm(rs) + std::norm(rp));
}

}  // namespace columba
