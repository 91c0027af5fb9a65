#include <gtest/gtest.h>

#include <iostream>
#include "bsdfs/plastic.h"
#include "bsdfs/roughplastic.h"
#include "optics/fresnel.h"
#include "support/bsdf_test_support.h"

using namespace columba;
using namespace columba::testing;

namespace {

const float kAngles[] = {0.0f, 30.0f, 60.0f, 85.0f};
const float kAlphas[] = {0.1f, 0.3f, 0.7f};
const MicrofacetType kTypes[] = {MicrofacetType::Beckmann, MicrofacetType::GGX};
const char* name(MicrofacetType t) { return t == MicrofacetType::GGX ? "ggx" : "beckmann"; }
const float kEta = 1.49f;

RoughPlasticBSDF roughPlastic(MicrofacetType type, float alpha, SpectralDistribution diffuse, float specular = 1.0f,
                              bool nonlinear = false) {
  return RoughPlasticBSDF(MicrofacetDistribution(type, alpha, alpha), kEta, std::move(diffuse),
                          SpectralDistribution::constant(specular), nonlinear);
}

}  // namespace

TEST(RoughPlastic, SamplingMatchesPdfSlow) {
  const double threshold = sidakThreshold(0.01, 2 * 3 * 4);
  double minP = 1.0;
  uint64_t seed = 1;
  for (MicrofacetType type : kTypes)
    for (float alpha : kAlphas) {
      RoughPlasticBSDF bsdf = roughPlastic(type, alpha, SpectralDistribution::constant(0.5f));
      for (float theta : kAngles) {
        auto result = chiSquareBSDF(bsdf, directionAt(theta, 40.0f), chiSquareGrid(alpha), 200000, seed++);
        std::cout << "roughplastic " << name(type) << " alpha " << alpha << " theta " << theta << ": " << result.message
                  << "\n";
        EXPECT_GT(result.pValue, threshold) << name(type) << " alpha " << alpha << " theta " << theta;
        minP = std::min(minP, result.pValue);
      }
    }
  std::cout << "roughplastic: min p = " << minP << " (threshold " << threshold << ")\n";
}

TEST(RoughPlastic, WeightIsEvalOverPdf) {
  for (MicrofacetType type : kTypes) {
    RoughPlasticBSDF bsdf =
        roughPlastic(type, 0.2f, SpectralDistribution::piecewiseLinear({400.0f, 700.0f}, {0.1f, 0.8f}), 0.9f);
    for (float theta : kAngles)
      EXPECT_LT(maxWeightError(bsdf, directionAt(theta)), 1e-4) << name(type) << " theta " << theta;
  }
}

TEST(RoughPlastic, AlbedoIsAtMostOneSlow) {
  // The worst case, a white base under a white coat, reflects at most everything; single
  // scattering in the coat loses more energy as the roughness grows.
  for (MicrofacetType type : kTypes)
    for (float theta : kAngles) {
      float previous = 1.0f;
      for (float alpha : {0.05f, 0.1f, 0.3f, 0.7f}) {
        RoughPlasticBSDF bsdf = roughPlastic(type, alpha, SpectralDistribution::constant(1.0f));
        float albedo = sampledAlbedo(bsdf, directionAt(theta), 40000)[0];
        std::cout << "roughplastic " << name(type) << " alpha " << alpha << " theta " << theta << ": albedo " << albedo
                  << "\n";
        EXPECT_LE(albedo, 1.005f) << name(type) << " alpha " << alpha << " theta " << theta;
        EXPECT_LE(albedo, previous + 0.005f) << name(type) << " alpha " << alpha << " theta " << theta;
        previous = albedo;
      }
    }
}

TEST(RoughPlastic, NonlinearBaseTintsEveryInternalBounce) {
  // Kd / (1 - Kd Ri) < Kd / (1 - Ri) for a coloured base; the same for a white one.
  for (float kd : {0.5f, 1.0f}) {
    RoughPlasticBSDF linear = roughPlastic(MicrofacetType::GGX, 0.2f, SpectralDistribution::constant(kd), 1.0f, false);
    RoughPlasticBSDF nonlinear =
        roughPlastic(MicrofacetType::GGX, 0.2f, SpectralDistribution::constant(kd), 1.0f, true);
    const Wavelengths wl = testWavelengths();
    Vec3 wi = directionAt(20.0f), wo = directionAt(70.0f, 90.0f);
    float a = linear.eval({}, wi, wo, wl)[0], b = nonlinear.eval({}, wi, wo, wl)[0];
    if (kd < 1.0f)
      EXPECT_LT(b, a * 0.9f);
    else
      EXPECT_FLOAT_EQ(a, b);
  }
}

TEST(RoughPlastic, CoatReflectanceApproachesFresnelWhenSmooth) {
  MicrofacetDistribution smooth(MicrofacetType::GGX, 0.005f, 0.005f);
  for (float theta : {0.0f, 30.0f, 60.0f}) {
    float mu = std::cos(degToRad(theta));
    EXPECT_NEAR(RoughPlasticBSDF::coatReflectance(smooth, mu, kEta), fresnelDielectric(mu, kEta), 2e-3f) << theta;
    EXPECT_NEAR(RoughPlasticBSDF::coatReflectance(smooth, mu, 1.0f / kEta), fresnelDielectric(mu, 1.0f / kEta), 2e-3f)
        << theta;
  }
}

TEST(RoughPlastic, CoatTransmittanceIsOneMinusFresnelWhenSmoothAndLosesMaskedLightWhenRough) {
  // Smooth: T = 1 - F(mu), Fresnel's closed form. Rough: light masked after refraction is lost,
  // so T + R < 1, the more so the rougher and the more grazing (Mitsuba 3's roughplastic table).
  MicrofacetDistribution smooth(MicrofacetType::GGX, 0.005f, 0.005f);
  for (float theta : {0.0f, 30.0f, 60.0f}) {
    const float mu = std::cos(degToRad(theta));
    EXPECT_NEAR(RoughPlasticBSDF::coatTransmittance(smooth, mu, kEta), 1.0f - fresnelDielectric(mu, kEta), 2e-3f)
        << theta;
  }
  float previousLoss = 0.0f;
  for (float alpha : {0.1f, 0.4f, 1.0f}) {
    MicrofacetDistribution rough(MicrofacetType::GGX, alpha, alpha);
    const float loss = 1.0f - RoughPlasticBSDF::coatTransmittance(rough, 1.0f, kEta) -
                       RoughPlasticBSDF::coatReflectance(rough, 1.0f, kEta);
    EXPECT_GT(loss, previousLoss) << alpha;
    previousLoss = loss;
    EXPECT_LT(RoughPlasticBSDF::coatTransmittance(rough, 0.2f, kEta),
              RoughPlasticBSDF::coatTransmittance(rough, 1.0f, kEta))
        << alpha;
  }
  EXPECT_GT(previousLoss, 0.05f);  // at alpha 1 a tenth of the light is lost at normal incidence
}

TEST(RoughPlastic, SmoothLimitMatchesPlastic) {
  PlasticBSDF smooth(kEta, SpectralDistribution::constant(0.5f), SpectralDistribution::constant(1.0f), false);
  RoughPlasticBSDF rough = roughPlastic(MicrofacetType::GGX, 0.01f, SpectralDistribution::constant(0.5f));
  for (float theta : {0.0f, 30.0f, 60.0f}) {
    float expected = sampledAlbedo(smooth, directionAt(theta), 100000)[0];
    float albedo = sampledAlbedo(rough, directionAt(theta), 100000)[0];
    EXPECT_NEAR(albedo, expected, 0.01f) << "theta " << theta;
  }
}

TEST(RoughPlastic, IsReciprocal) {
  RoughPlasticBSDF bsdf = roughPlastic(MicrofacetType::Beckmann, 0.3f,
                                       SpectralDistribution::piecewiseLinear({400.0f, 700.0f}, {0.1f, 0.8f}));
  const Wavelengths wl = testWavelengths();
  PCG32 rng(8, 8);
  for (int n = 0; n < 200; ++n) {
    Vec3 a = directionAt(85.0f * rng.nextFloat(), 360.0f * rng.nextFloat());
    Vec3 b = directionAt(85.0f * rng.nextFloat(), 360.0f * rng.nextFloat());
    Spectrum fab = bsdf.eval({}, a, b, wl) / b.z, fba = bsdf.eval({}, b, a, wl) / a.z;
    for (int i = 0; i < kSpectrumSamples; ++i) EXPECT_NEAR(fab[i], fba[i], 1e-4f * std::max(1.0f, fab[i]));
  }
}

TEST(RoughPlastic, IsBlackFromBelow) {
  RoughPlasticBSDF bsdf = roughPlastic(MicrofacetType::GGX, 0.3f, SpectralDistribution::constant(0.5f));
  const Wavelengths wl = testWavelengths();
  Vec3 below = -directionAt(30.0f), above = directionAt(30.0f, 180.0f);
  EXPECT_TRUE(bsdf.eval({}, below, -above, wl).isZero());
  EXPECT_TRUE(bsdf.eval({}, above, below, wl).isZero());
  EXPECT_FALSE(bsdf.sample({}, below, wl, 0.5f, Vec2(0.5f, 0.5f)));
}

TEST(RoughPlastic, FactoryReadsMitsubaParameters) {
  const Wavelengths wl = testWavelengths();
  Vec3 wi = directionAt(20.0f), wo = directionAt(30.0f, 180.0f);
  Properties defaults;
  auto bsdf = std::dynamic_pointer_cast<BSDF>(makeRoughPlasticBSDF(defaults));
  ASSERT_TRUE(bsdf);
  // Beckmann, alpha 0.1, polypropylene in air, diffuse 0.5, specular 1, linear.
  RoughPlasticBSDF reference(MicrofacetDistribution(MicrofacetType::Beckmann, 0.1f, 0.1f), 1.49f / 1.000277f,
                             SpectralDistribution::constant(0.5f), SpectralDistribution::constant(1.0f), false);
  EXPECT_NEAR(bsdf->eval({}, wi, wo, wl)[0], reference.eval({}, wi, wo, wl)[0], 1e-5f);

  Properties props;
  setString(props, "distribution", "GGX");
  setFloat(props, "alpha", 0.15f);
  setString(props, "int_ior", "acrylic glass");
  setFloat(props, "diffuse_reflectance", 0.132f);
  setFloat(props, "specular_reflectance", 0.6f);
  setBool(props, "nonlinear", true);
  auto custom = std::dynamic_pointer_cast<BSDF>(makeRoughPlasticBSDF(props));
  EXPECT_NO_THROW(props.checkAllUsed());
  RoughPlasticBSDF expected(MicrofacetDistribution(MicrofacetType::GGX, 0.15f, 0.15f), 1.49f / 1.000277f,
                            SpectralDistribution::constant(0.132f), SpectralDistribution::constant(0.6f), true);
  EXPECT_NEAR(custom->eval({}, wi, wo, wl)[0], expected.eval({}, wi, wo, wl)[0], 1e-5f);

  Properties anisotropic;
  setFloat(anisotropic, "alpha_u", 0.1f);
  setFloat(anisotropic, "alpha_v", 0.2f);
  EXPECT_THROW(makeRoughPlasticBSDF(anisotropic), InputError);
}
