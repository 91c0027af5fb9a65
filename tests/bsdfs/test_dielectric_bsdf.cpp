#include <gtest/gtest.h>

#include <iostream>
#include "bsdfs/dielectric.h"
#include "optics/fresnel.h"
#include "support/bsdf_test_support.h"

using namespace columba;
using namespace columba::testing;

namespace {

const float kEta = 1.5f;

DielectricBSDF glass(float reflectance = 1.0f, float transmittance = 1.0f) {
  return DielectricBSDF(kEta, SpectralDistribution::constant(reflectance),
                        SpectralDistribution::constant(transmittance));
}

float sinTheta(const Vec3& w) { return std::sqrt(w.x * w.x + w.y * w.y); }

}  // namespace

TEST(Dielectric, IsDeltaOnly) {
  DielectricBSDF bsdf = glass();
  const Wavelengths wl = testWavelengths();
  Vec3 wi = directionAt(30.0f), mirror = directionAt(30.0f, 180.0f);
  EXPECT_TRUE(bsdf.isDeltaOnly());
  EXPECT_TRUE(bsdf.eval({}, wi, mirror, wl).isZero());
  EXPECT_EQ(bsdf.pdf({}, wi, mirror, wl), 0.0f);
  for (float uComponent : {0.01f, 0.99f}) {
    auto s = bsdf.sample({}, wi, wl, uComponent, Vec2(0.3f, 0.3f));
    ASSERT_TRUE(s);
    EXPECT_TRUE(s->delta);
  }
}

TEST(Dielectric, SamplesTheMirrorAndTheRefractedDirections) {
  DielectricBSDF bsdf = glass(0.9f, 0.8f);
  const Wavelengths wl = testWavelengths();
  // From outside (eta = 1.5 across) and from inside below the critical angle (1 / 1.5 across).
  for (float side : {1.0f, -1.0f})
    for (float theta : {0.0f, 30.0f, 40.0f, 60.0f, 85.0f}) {
      if (side < 0.0f && theta >= 41.0f) continue;
      Vec3 wi = directionAt(theta, 70.0f) * Vec3(1.0f, 1.0f, side);
      float etaI = side > 0.0f ? 1.0f : kEta, etaT = side > 0.0f ? kEta : 1.0f;

      auto r = bsdf.sample({}, wi, wl, 0.0f, Vec2(0.5f, 0.5f));
      ASSERT_TRUE(r);
      EXPECT_NEAR(r->wo.x, -wi.x, 1e-6f);
      EXPECT_NEAR(r->wo.y, -wi.y, 1e-6f);
      EXPECT_NEAR(r->wo.z, wi.z, 1e-6f);
      EXPECT_NEAR(r->weight[0], 0.9f, 1e-6f);

      auto t = bsdf.sample({}, wi, wl, 0.999999f, Vec2(0.5f, 0.5f));
      ASSERT_TRUE(t);
      EXPECT_NEAR(length(t->wo), 1.0f, 1e-5f);
      EXPECT_LT(t->wo.z * wi.z, 0.0f) << "refraction crosses the surface";
      EXPECT_NEAR(etaI * sinTheta(wi), etaT * sinTheta(t->wo), 1e-5f) << "Snell's law, theta " << theta;
      EXPECT_LE(t->wo.x * wi.x + t->wo.y * wi.y, 0.0f) << "the refracted ray keeps going forward";
      // Radiance scaling by (n_wi / n_wo)^2.
      EXPECT_NEAR(t->weight[0], 0.8f * sqr(etaI / etaT), 1e-5f);
    }
}

TEST(Dielectric, ComponentProbabilitiesAreTheFresnelTerms) {
  DielectricBSDF bsdf = glass();
  const Wavelengths wl = testWavelengths();
  PCG32 rng(4, 4);
  for (float side : {1.0f, -1.0f})
    for (float theta : {0.0f, 30.0f, 60.0f, 85.0f}) {
      Vec3 wi = directionAt(theta) * Vec3(1.0f, 1.0f, side);
      const float fresnel = fresnelDielectric(wi.z, kEta);
      auto r = bsdf.sample({}, wi, wl, 0.0f, Vec2(0.5f, 0.5f));
      auto t = bsdf.sample({}, wi, wl, 0.999999f, Vec2(0.5f, 0.5f));
      ASSERT_TRUE(r && t);
      EXPECT_NEAR(r->pdf, fresnel, 1e-6f);
      if (fresnel < 1.0f)
        EXPECT_NEAR(r->pdf + t->pdf, 1.0f, 1e-6f);
      else  // total internal reflection: the transmission is never chosen
        EXPECT_EQ(t->wo.z, wi.z);
      // The fraction of reflected samples estimates the same probability.
      const int n = 40000;
      int reflected = 0;
      for (int i = 0; i < n; ++i) {
        auto s = bsdf.sample({}, wi, wl, rng.nextFloat(), Vec2(0.5f, 0.5f));
        if (s && s->wo.z * wi.z > 0.0f) ++reflected;
      }
      float sigma = std::sqrt(std::max(fresnel * (1.0f - fresnel), 1e-4f) / n);
      EXPECT_NEAR(float(reflected) / n, fresnel, 5.0f * sigma) << "side " << side << " theta " << theta;
    }
}

TEST(Dielectric, TotalInternalReflectionReflectsEverything) {
  DielectricBSDF bsdf = glass(0.7f, 1.0f);
  const Wavelengths wl = testWavelengths();
  Vec3 wi = directionAt(50.0f) * Vec3(1.0f, 1.0f, -1.0f);  // beyond the critical angle asin(1/1.5) = 41.8 deg
  for (float uComponent : {0.0f, 0.5f, 0.999999f}) {
    auto s = bsdf.sample({}, wi, wl, uComponent, Vec2(0.5f, 0.5f));
    ASSERT_TRUE(s);
    EXPECT_NEAR(s->wo.z, wi.z, 1e-6f);
    EXPECT_NEAR(s->pdf, 1.0f, 1e-6f);
    EXPECT_NEAR(s->weight[0], 0.7f, 1e-6f);
  }
}

TEST(Dielectric, FactoryReadsNamedAndNumericIORs) {
  Properties defaults;
  auto bk7 = std::dynamic_pointer_cast<DielectricBSDF>(makeDielectricBSDF(defaults));
  ASSERT_TRUE(bk7);
  EXPECT_NEAR(bk7->eta(), 1.5046f / 1.000277f, 1e-5f);

  Properties named;
  setString(named, "int_ior", "water");
  setFloat(named, "ext_ior", 1.0f);
  setFloat(named, "specular_transmittance", 0.5f);
  auto water = std::dynamic_pointer_cast<DielectricBSDF>(makeDielectricBSDF(named));
  EXPECT_NEAR(water->eta(), 1.333f, 1e-5f);
  EXPECT_NO_THROW(named.checkAllUsed());
  auto t = water->sample({}, directionAt(0.0f), testWavelengths(), 0.999999f, Vec2(0.5f, 0.5f));
  ASSERT_TRUE(t);
  EXPECT_NEAR(t->weight[0], 0.5f / sqr(1.333f), 1e-5f);

  Properties numeric;
  setFloat(numeric, "int_ior", 1.7f);
  EXPECT_NEAR(std::dynamic_pointer_cast<DielectricBSDF>(makeDielectricBSDF(numeric))->eta(), 1.7f / 1.000277f, 1e-5f);
}

TEST(Dielectric, FactoryRejectsBadIORs) {
  Properties unknown;
  setString(unknown, "int_ior", "unobtainium");
  EXPECT_THROW(makeDielectricBSDF(unknown), InputError);
  Properties negative;
  setFloat(negative, "ext_ior", -1.0f);
  EXPECT_THROW(makeDielectricBSDF(negative), InputError);
  Properties wrongKind;
  setBool(wrongKind, "int_ior", true);
  EXPECT_THROW(makeDielectricBSDF(wrongKind), InputError);
}
