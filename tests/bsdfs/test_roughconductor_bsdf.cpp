#include <gtest/gtest.h>

#include <iostream>
#include "bsdfs/roughconductor.h"
#include "optics/conductor_fresnel.h"
#include "support/bsdf_test_support.h"

using namespace columba;
using namespace columba::testing;

namespace {

const float kAngles[] = {0.0f, 30.0f, 60.0f, 85.0f};
const float kAlphas[] = {0.1f, 0.3f, 0.7f};
const MicrofacetType kTypes[] = {MicrofacetType::Beckmann, MicrofacetType::GGX};
const char* name(MicrofacetType t) { return t == MicrofacetType::GGX ? "ggx" : "beckmann"; }

// A copper-like conductor, to exercise the spectral Fresnel term.
const SpectralDistribution kCopperEta =
    SpectralDistribution::piecewiseLinear({400.0f, 550.0f, 700.0f}, {1.2f, 1.0f, 0.2f});
const SpectralDistribution kCopperK =
    SpectralDistribution::piecewiseLinear({400.0f, 550.0f, 700.0f}, {2.2f, 2.6f, 4.0f});
ConductorIndexParameter copperLike() { return {kCopperEta, kCopperK}; }

RoughConductorBSDF mirror(MicrofacetType type, float alphaX, float alphaY) {
  return RoughConductorBSDF(MicrofacetDistribution(type, alphaX, alphaY), std::nullopt,
                            SpectralDistribution::constant(1.0f));
}

}  // namespace

TEST(RoughConductor, SamplingMatchesPdfSlow) {
  struct Case {
    MicrofacetType type;
    float alphaX, alphaY, theta;
  };
  std::vector<Case> cases;
  for (MicrofacetType type : kTypes) {
    for (float alpha : kAlphas)
      for (float theta : kAngles) cases.push_back({type, alpha, alpha, theta});
    for (float theta : {30.0f, 85.0f}) cases.push_back({type, 0.1f, 0.4f, theta});
  }
  const double threshold = sidakThreshold(0.01, int(cases.size()));
  double minP = 1.0;
  uint64_t seed = 1;
  for (const Case& c : cases) {
    RoughConductorBSDF bsdf = mirror(c.type, c.alphaX, c.alphaY);
    auto result =
        chiSquareBSDF(bsdf, directionAt(c.theta, 40.0f), chiSquareGrid(std::min(c.alphaX, c.alphaY)), 200000, seed++);
    std::cout << "roughconductor " << name(c.type) << " alpha " << c.alphaX << "/" << c.alphaY << " theta " << c.theta
              << ": " << result.message << "\n";
    EXPECT_GT(result.pValue, threshold) << name(c.type) << " alpha " << c.alphaX << "/" << c.alphaY << " theta "
                                        << c.theta;
    minP = std::min(minP, result.pValue);
  }
  std::cout << "roughconductor: min p = " << minP << " over " << cases.size() << " tests (threshold " << threshold
            << ")\n";
}

TEST(RoughConductor, WeightIsEvalOverPdfSlow) {
  for (MicrofacetType type : kTypes)
    for (float alpha : kAlphas) {
      RoughConductorBSDF bsdf(MicrofacetDistribution(type, alpha, alpha * 0.5f), copperLike(),
                              SpectralDistribution::constant(0.9f));
      for (float theta : kAngles)
        EXPECT_LT(maxWeightError(bsdf, directionAt(theta, 15.0f)), 2e-3)
            << name(type) << " alpha " << alpha << " theta " << theta;
    }
}

TEST(RoughConductor, PerfectMirrorConservesEnergySlow) {
  for (MicrofacetType type : kTypes)
    for (float theta : kAngles) {
      // Single scattering loses energy to masking as the roughness grows (away from grazing,
      // where the smoothest surfaces also lose reflections that end below the horizon).
      float previous = 1.0f;
      for (float alpha : {0.01f, 0.1f, 0.3f, 0.7f}) {
        float albedo = sampledAlbedo(mirror(type, alpha, alpha), directionAt(theta), 100000)[0];
        std::cout << "roughconductor " << name(type) << " alpha " << alpha << " theta " << theta << ": albedo "
                  << albedo << "\n";
        EXPECT_LE(albedo, 1.0f);
        if (theta <= 60.0f) {
          EXPECT_LE(albedo, previous + 0.005f);
          if (alpha <= 0.01f) {
            EXPECT_GT(albedo, 0.995f);
          }
        }
        previous = albedo;
      }
    }
}

TEST(RoughConductor, IntegratedEvalMatchesSampledAlbedoSlow) {
  // The integral of eval, estimated without the BSDF's sampler, equals the mean sample weight.
  for (MicrofacetType type : kTypes)
    for (float theta : {0.0f, 60.0f}) {
      RoughConductorBSDF bsdf(MicrofacetDistribution(type, 0.5f, 0.5f), copperLike(),
                              SpectralDistribution::constant(1.0f));
      Spectrum integrated = integratedAlbedo(bsdf, directionAt(theta), 400000);
      Spectrum sampled = sampledAlbedo(bsdf, directionAt(theta), 100000);
      for (int i = 0; i < kSpectrumSamples; ++i)
        EXPECT_NEAR(integrated[i], sampled[i], 0.02f) << name(type) << " theta " << theta << " wavelength " << i;
    }
}

TEST(RoughConductor, SmoothLimitReflectsTheFresnelTermSlow) {
  RoughConductorBSDF bsdf(MicrofacetDistribution(MicrofacetType::GGX, 0.005f, 0.005f), copperLike(),
                          SpectralDistribution::constant(1.0f));
  const Wavelengths wl = testWavelengths();
  Spectrum albedo = sampledAlbedo(bsdf, directionAt(30.0f), 2000);
  for (int i = 0; i < kSpectrumSamples; ++i)
    EXPECT_NEAR(albedo[i], fresnelConductor(std::cos(degToRad(30.0f)), kCopperEta.eval(wl[i]), kCopperK.eval(wl[i])),
                3e-3f);
}

TEST(RoughConductor, IsReciprocalSlow) {
  RoughConductorBSDF bsdf(MicrofacetDistribution(MicrofacetType::Beckmann, 0.2f, 0.4f), copperLike(),
                          SpectralDistribution::constant(1.0f));
  const Wavelengths wl = testWavelengths();
  PCG32 rng(9, 9);
  for (int n = 0; n < 200; ++n) {
    Vec3 a = directionAt(85.0f * rng.nextFloat(), 360.0f * rng.nextFloat());
    Vec3 b = directionAt(85.0f * rng.nextFloat(), 360.0f * rng.nextFloat());
    Spectrum fab = bsdf.eval({}, a, b, wl) / b.z, fba = bsdf.eval({}, b, a, wl) / a.z;
    for (int i = 0; i < kSpectrumSamples; ++i) EXPECT_NEAR(fab[i], fba[i], 1e-4f * std::max(1.0f, fab[i]));
  }
}

TEST(RoughConductor, IsBlackFromBelowSlow) {
  RoughConductorBSDF bsdf = mirror(MicrofacetType::GGX, 0.3f, 0.3f);
  const Wavelengths wl = testWavelengths();
  Vec3 below = -directionAt(30.0f), above = directionAt(30.0f, 180.0f);
  EXPECT_TRUE(bsdf.eval({}, below, -above, wl).isZero());
  EXPECT_TRUE(bsdf.eval({}, above, below, wl).isZero());
  EXPECT_EQ(bsdf.pdf({}, below, -above, wl), 0.0f);
  EXPECT_FALSE(bsdf.sample({}, below, wl, 0.5f, Vec2(0.5f, 0.5f)));
}

TEST(RoughConductor, FactoryReadsMitsubaParametersSlow) {
  const Wavelengths wl = testWavelengths();
  Vec3 wi = directionAt(20.0f), wo = directionAt(25.0f, 180.0f);
  Properties defaults;
  auto plain = std::dynamic_pointer_cast<BSDF>(makeRoughConductorBSDF(defaults));
  ASSERT_TRUE(plain);
  // Default: Beckmann, alpha 0.1, a perfect mirror.
  Spectrum expected = mirror(MicrofacetType::Beckmann, 0.1f, 0.1f).eval({}, wi, wo, wl);
  EXPECT_NEAR(plain->eval({}, wi, wo, wl)[0], expected[0], 1e-5f * expected[0]);

  Properties props;
  setString(props, "distribution", "ggx");
  setFloat(props, "alpha_u", 0.2f);
  setFloat(props, "alpha_v", 0.3f);
  setFloat(props, "eta", 0.2f);
  setFloat(props, "k", 3.0f);
  setBool(props, "sample_visible", true);
  auto metal = std::dynamic_pointer_cast<BSDF>(makeRoughConductorBSDF(props));
  EXPECT_NO_THROW(props.checkAllUsed());
  RoughConductorBSDF reference(
      MicrofacetDistribution(MicrofacetType::GGX, 0.2f, 0.3f),
      ConductorIndexParameter{SpectralDistribution::constant(0.2f), SpectralDistribution::constant(3.0f)},
      SpectralDistribution::constant(1.0f));
  EXPECT_NEAR(metal->eval({}, wi, wo, wl)[1], reference.eval({}, wi, wo, wl)[1], 1e-5f);
}

TEST(RoughConductor, FactoryRejectsBadParametersSlow) {
  auto build = [](auto fill) {
    Properties props;
    fill(props);
    return makeRoughConductorBSDF(props);
  };
  EXPECT_THROW(build([](Properties& p) { setString(p, "distribution", "phong"); }), InputError);
  EXPECT_THROW(build([](Properties& p) { setString(p, "material", "Unobtainium"); }), InputError);
  EXPECT_THROW(build([](Properties& p) {
                 setString(p, "material", "Au");
                 setFloat(p, "eta", 0.2f);
               }),
               InputError);
  EXPECT_THROW(build([](Properties& p) { setFloat(p, "alpha_u", 0.2f); }), InputError);
  EXPECT_THROW(build([](Properties& p) {
                 setFloat(p, "alpha", 0.2f);
                 setFloat(p, "alpha_u", 0.2f);
                 setFloat(p, "alpha_v", 0.1f);
               }),
               InputError);
  EXPECT_THROW(build([](Properties& p) { setFloat(p, "alpha", -0.1f); }), InputError);
}
