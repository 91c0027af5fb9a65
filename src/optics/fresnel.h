#pragma once
// Fresnel equations at a smooth interface between two dielectrics.
#include "core/math.h"

namespace columba {

// Amplitude coefficients for light arriving with cos(theta_i) = cosI (> 0 on the incident side)
// at an interface with relative index eta = n_transmitted / n_incident.
struct FresnelAmplitudes {
  float rs = 1, rp = 1;  // reflection, s and p polarisation
  float ts = 0, tp = 0;  // transmission
  float cosT = 0;        // cosine of the refracted angle
  bool totalInternalReflection = true;
};

inline FresnelAmplitudes fresnelAmplitudes(float cosI, float eta) {
  FresnelAmplitudes a;
  cosI = clampf(std::abs(cosI), 0.0f, 1.0f);
  float sin2T = (1.0f - cosI * cosI) / (eta * eta);
  if (sin2T >= 1.0f) return a;
  float cosT = std::sqrt(1.0f - sin2T);
  a.cosT = cosT;
  a.totalInternalReflection = false;
  a.rs = (cosI - eta * cosT) / (cosI + eta * cosT);
  a.rp = (eta * cosI - cosT) / (eta * cosI + cosT);
  a.ts = 2.0f * cosI / (cosI + eta * cosT);
  a.tp = 2.0f * cosI / (eta * cosI + cosT);
  return a;
}

// Unpolarised reflectance. `cosI` < 0 means arriving from the other side (eta inverted).
inline float fresnelDielectric(float cosI, float eta) {
  if (cosI < 0.0f) {
    eta = 1.0f / eta;
    cosI = -cosI;
  }
  FresnelAmplitudes a = fresnelAmplitudes(cosI, eta);
  return 0.5f * (a.rs * a.rs + a.rp * a.rp);
}

}  // namespace columba
