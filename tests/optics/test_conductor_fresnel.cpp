#include <gtest/gtest.h>

#include "optics/conductor_fresnel.h"
#include "optics/fresnel.h"

using namespace columba;

TEST(ConductorFresnel, MatchesNormalIncidenceFormula) {
  for (auto [eta, k] : {std::pair{0.2f, 3.5f}, std::pair{1.5f, 0.0f}, std::pair{2.9f, 3.1f}}) {
    float expected = (sqr(eta - 1.0f) + k * k) / (sqr(eta + 1.0f) + k * k);
    EXPECT_NEAR(fresnelConductor(1.0f, eta, k), expected, 1e-5f) << eta << " + " << k << "i";
  }
}

TEST(ConductorFresnel, ReducesToDielectricWithoutAbsorption) {
  for (float cosI : {1.0f, 0.8f, 0.5f, 0.2f, 0.05f})
    EXPECT_NEAR(fresnelConductor(cosI, 1.5f, 0.0f), fresnelDielectric(cosI, 1.5f), 1e-5f) << cosI;
}

TEST(ConductorFresnel, PurelyImaginaryIndexIsAPerfectMirror) {
  for (float cosI : {1.0f, 0.7f, 0.3f, 0.0f}) EXPECT_NEAR(fresnelConductor(cosI, 0.0f, 1.0f), 1.0f, 1e-6f) << cosI;
}

TEST(ConductorFresnel, IsAFractionAndReachesOneAtGrazing) {
  // Gold-like index: reflectance dips at an oblique angle (the pseudo-Brewster minimum) and rises to 1.
  float previous = fresnelConductor(1.0f, 0.47f, 2.4f);
  EXPECT_GT(previous, 0.0f);
  for (float cosI = 0.95f; cosI >= 0.0f; cosI -= 0.05f) {
    float r = fresnelConductor(cosI, 0.47f, 2.4f);
    EXPECT_GE(r, 0.0f);
    EXPECT_LE(r, 1.0f);
  }
  EXPECT_NEAR(fresnelConductor(0.0f, 0.47f, 2.4f), 1.0f, 1e-5f);
  EXPECT_GT(fresnelConductor(0.05f, 0.47f, 2.4f), previous);
}
