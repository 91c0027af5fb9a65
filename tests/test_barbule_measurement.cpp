#include <gtest/gtest.h>

#include "bsdfs/barbule_measurement.h"
#include "core/rng.h"
#include "core/sampling.h"

using namespace columba;

TEST(BarbuleMeasurement, LobeReflectanceMatchesMonteCarloIntegration) {
  BarbuleBSDF bsdf{BarbuleParameters{}};
  const std::vector<float> lambdas = {450, 530, 610, 690};
  Wavelengths wl = Wavelengths::fixed({450, 530, 610, 690});
  for (float thetaDeg : {0.0f, 35.0f, 65.0f}) {
    Vec3 omegaI(std::sin(degToRad(thetaDeg)), 0.0f, std::cos(degToRad(thetaDeg)));
    LobeReflectance grid = lobeReflectance(bsdf, omegaI, lambdas);
    // Independent estimate: uniform directions over the sphere.
    PCG32 rng(11, 3);
    const int n = 400000;
    double r[4] = {}, t[4] = {};
    for (int i = 0; i < n; ++i) {
      Vec3 wo = sampleUniformSphere(Vec2(rng.nextFloat(), rng.nextFloat()));
      BarbuleBSDF::Lobes lobes = bsdf.evalLobes(BSDFContext{}, omegaI, wo, wl);
      for (int k = 0; k < 4; ++k) {
        r[k] += lobes.reflection[k] * std::abs(wo.z) / uniformSpherePdf() / n;
        t[k] += lobes.trt[k] * std::abs(wo.z) / uniformSpherePdf() / n;
      }
    }
    for (int k = 0; k < 4; ++k) {
      SCOPED_TRACE(testing::Message() << "theta " << thetaDeg << " lambda " << lambdas[k]);
      EXPECT_NEAR(grid.reflection[k], r[k], 0.03 * r[k] + 1e-4);
      EXPECT_NEAR(grid.trt[k], t[k], 0.02 * t[k] + 1e-4);
      EXPECT_LE(grid.reflection[k] + grid.trt[k], 1.0f);
    }
  }
}

TEST(BarbuleMeasurement, ScatterometerImageIsBlackOutsideTheDiskAndPeaksOppositeTheLight) {
  BarbuleBSDF bsdf{BarbuleParameters{}};
  Vec3 light(std::sin(degToRad(45.0f)), 0.0f, std::cos(degToRad(45.0f)));  // from +x
  Image img = scatterometerImage(bsdf, light, 64, 1);
  for (int c = 0; c < 3; ++c) EXPECT_EQ(img.pixel(0, 0)[c], 0.0f);
  int bestX = 0, bestY = 0;
  float best = -1;
  for (int y = 0; y < 64; ++y)
    for (int x = 0; x < 64; ++x) {
      float v = img.pixel(x, y)[0] + img.pixel(x, y)[1] + img.pixel(x, y)[2];
      if (v > best) { best = v; bestX = x; bestY = y; }
    }
  EXPECT_GT(best, 0.0f);
  EXPECT_LT(bestX, 32);                 // the specular side, -x
  EXPECT_NEAR(bestY, 31.5, 6.0);        // near the plane of incidence
}
