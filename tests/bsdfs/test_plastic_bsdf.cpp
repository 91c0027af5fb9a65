#include <gtest/gtest.h>

#include <iostream>
#include "bsdfs/plastic.h"
#include "optics/diffuse_fresnel.h"
#include "optics/fresnel.h"
#include "support/bsdf_test_support.h"

using namespace columba;
using namespace columba::testing;

namespace {

const float kAngles[] = {0.0f, 30.0f, 60.0f, 85.0f};
const float kEta = 1.49f;

PlasticBSDF plastic(float diffuse, float specular = 1.0f, bool nonlinear = false) {
  return PlasticBSDF(kEta, SpectralDistribution::constant(diffuse), SpectralDistribution::constant(specular),
                     nonlinear);
}

}  // namespace

TEST(Plastic, DiffuseSamplingMatchesPdf) {
  PlasticBSDF bsdf = plastic(0.5f);
  const double threshold = sidakThreshold(0.01, 4);
  double minP = 1.0;
  uint64_t seed = 1;
  for (float theta : kAngles) {
    auto result = chiSquareBSDF(bsdf, directionAt(theta, 10.0f), {}, 200000, seed++);
    std::cout << "plastic theta " << theta << ": " << result.message << "\n";
    EXPECT_GT(result.pValue, threshold) << "theta " << theta;
    minP = std::min(minP, result.pValue);
  }
  std::cout << "plastic: min p = " << minP << " (threshold " << threshold << ")\n";
}

TEST(Plastic, WeightIsEvalOverPdf) {
  PlasticBSDF bsdf(kEta, SpectralDistribution::piecewiseLinear({400.0f, 700.0f}, {0.1f, 0.8f}),
                   SpectralDistribution::constant(0.9f), true);
  for (float theta : kAngles) EXPECT_LT(maxWeightError(bsdf, directionAt(theta)), 1e-4) << "theta " << theta;
}

TEST(Plastic, SpecularSampleIsTheFresnelWeightedMirror) {
  PlasticBSDF bsdf = plastic(0.5f, 0.8f);
  const Wavelengths wl = testWavelengths();
  Vec3 wi = directionAt(60.0f, 30.0f);
  auto s = bsdf.sample({}, wi, wl, 0.0f, Vec2(0.5f, 0.5f));
  ASSERT_TRUE(s);
  EXPECT_TRUE(s->delta);
  EXPECT_NEAR(s->wo.x, -wi.x, 1e-6f);
  EXPECT_NEAR(s->wo.y, -wi.y, 1e-6f);
  EXPECT_NEAR(s->wo.z, wi.z, 1e-6f);
  EXPECT_NEAR(s->weight[0] * s->pdf, 0.8f * fresnelDielectric(wi.z, kEta), 1e-6f);
  // Delta components are invisible to eval and pdf: the diffuse lobe alone remains there.
  float diffusePdf = bsdf.pdf({}, wi, s->wo, wl);
  EXPECT_NEAR(diffusePdf, (1.0f - s->pdf) * wi.z * kInvPi, 1e-5f);
}

TEST(Plastic, AlbedoIsReflectedPlusTransmittedDiffuse) {
  // Light entering the coat comes back out in full when the base is white, since the internal
  // and external diffuse transmittances satisfy 1 - Ri = (1 - Re) / eta^2.
  const float ri = fresnelDiffuseReflectance(1.0f / kEta);
  for (float kd : {0.5f, 1.0f})
    for (bool nonlinear : {false, true})
      for (float theta : kAngles) {
        float fresnel = fresnelDielectric(std::cos(degToRad(theta)), kEta);
        float base = nonlinear ? kd * (1.0f - ri) / (1.0f - kd * ri) : kd;
        float expected = fresnel + (1.0f - fresnel) * base;
        float albedo = sampledAlbedo(plastic(kd, 1.0f, nonlinear), directionAt(theta), 100000)[0];
        std::cout << "plastic kd " << kd << (nonlinear ? " nonlinear" : "") << " theta " << theta << ": albedo "
                  << albedo << " (expected " << expected << ")\n";
        EXPECT_NEAR(albedo, expected, 0.01f);
        EXPECT_LE(albedo, 1.005f);
      }
}

TEST(Plastic, DiffuseFresnelReflectanceMatchesKnownValues) {
  // Cosine-weighted Fresnel reflectance: about 0.092 outside and 0.596 inside for eta = 1.5.
  EXPECT_NEAR(fresnelDiffuseReflectance(1.5f), 0.0918f, 1e-3f);
  EXPECT_NEAR(fresnelDiffuseReflectance(1.0f / 1.5f), 0.5963f, 1e-3f);
  EXPECT_NEAR(fresnelDiffuseReflectance(1.0f), 0.0f, 1e-6f);
}

TEST(Plastic, FactoryReadsMitsubaDefaults) {
  const Wavelengths wl = testWavelengths();
  Vec3 wi = directionAt(10.0f), wo = directionAt(50.0f, 90.0f);
  Properties defaults;
  auto bsdf = std::dynamic_pointer_cast<BSDF>(makePlasticBSDF(defaults));
  ASSERT_TRUE(bsdf);
  // polypropylene (1.49) in air, diffuse 0.5, specular 1, linear.
  PlasticBSDF reference(1.49f / 1.000277f, SpectralDistribution::constant(0.5f), SpectralDistribution::constant(1.0f),
                        false);
  EXPECT_NEAR(bsdf->eval({}, wi, wo, wl)[0], reference.eval({}, wi, wo, wl)[0], 1e-6f);

  Properties props;
  setFloat(props, "int_ior", 1.6f);
  setString(props, "ext_ior", "vacuum");
  setFloat(props, "diffuse_reflectance", 0.3f);
  setFloat(props, "specular_reflectance", 0.7f);
  setBool(props, "nonlinear", true);
  auto custom = std::dynamic_pointer_cast<BSDF>(makePlasticBSDF(props));
  EXPECT_NO_THROW(props.checkAllUsed());
  PlasticBSDF expected(1.6f, SpectralDistribution::constant(0.3f), SpectralDistribution::constant(0.7f), true);
  EXPECT_NEAR(custom->eval({}, wi, wo, wl)[0], expected.eval({}, wi, wo, wl)[0], 1e-6f);
}
