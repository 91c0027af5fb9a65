#include "optics/diffuse_fresnel.h"

#include "optics/fresnel.h"

namespace columba {

float fresnelDiffuseReflectance(float eta) {
  // With s = mu^2 the cosine-weighted integral is the plain mean of F(sqrt(s)) over [0, 1]: the
  // midpoint rule there is accurate to ~1e-5 despite the kink at the critical angle.
  constexpr int kSteps = 2048;
  double sum = 0.0;
  for (int i = 0; i < kSteps; ++i) {
    float mu = std::sqrt((i + 0.5f) / kSteps);
    sum += fresnelDielectric(mu, eta);
  }
  return float(sum / kSteps);
}

}  // namespace columba
