// The barbule BSDF of arms: sample against pdf (chi-square), the sampler's and an independent
// integral's albedo, the one-arm case against barbulebsdf's R lobe, the three mirrors' directions
// and colours, and its parameters.
#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <optional>
#include <string>
#include "bsdfs/barbulearms.h"
#include "bsdfs/barbulebsdf.h"
#include "core/math.h"
#include "core/rng.h"
#include "core/sampling.h"
#include "support/bsdf_test_support.h"
#include "support/chi_square.h"

using namespace columba;
using namespace columba::testing;

namespace {

const Wavelengths kWavelengths = Wavelengths::fixed({430.0f, 520.0f, 610.0f, 700.0f});

struct ArmsSet {
  const char* name;
  std::vector<double> tiltsDeg;
  float b, p, mu, H;
};

// A roof and a trough of three mirrors at the parotia's angles, a V of ellipses packed at contact
// and tilted, and the paper's ellipse barbule as one arm. The mirrors' exponent is 2.5: from 3 up
// the flat faces' normal density is singular enough that neither a bin's quadrature nor an
// estimate from eval alone (infinite variance, docs/model.md "Which estimators converge") can
// check the sampler; every exponent shares its code.
const ArmsSet kSets[] = {
    {"roof", {-30.0, 0.0, 30.0}, 0.2f, 2.5f, 0.0f, 7.0f},
    {"trough", {30.0, 0.0, -30.0}, 0.2f, 2.5f, 0.0f, 7.0f},
    {"V", {40.0, -40.0}, 0.3f, 2.0f, 0.25f, 0.0f},
    {"one arm", {0.0}, 0.25f, 2.0f, -0.35f, 1.25f},
};

BarbuleArmsBSDF makeArms(const ArmsSet& set, float height = 0.4f) {
  std::vector<double> tilts;
  for (double t : set.tiltsDeg) tilts.push_back(t * kPiDouble / 180.0);
  BarbuleParameters film;
  film.height = height;
  film.profileExponent = set.p;
  return BarbuleArmsBSDF(ArmedCrossSection(tilts, set.b, set.p, set.mu, set.H), film);
}

Vec3 direction(float thetaDeg, float phiDeg) {
  const float t = thetaDeg * kPi / 180.0f, p = phiDeg * kPi / 180.0f;
  return {std::sin(t) * std::cos(p), std::sin(t) * std::sin(p), std::cos(t)};
}

// Chi-square bins with the barbule axis as the pole, as barbulebsdf's tests bin them: the lobe is
// narrow in the angle to the axis.
Vec3 axisAsPole(const Vec3& w) { return {w.z, w.x, w.y}; }
Vec3 fromAxisAsPole(const Vec3& v) { return {v.y, v.z, v.x}; }

}  // namespace

TEST(BarbuleArmsBSDF, SampledDirectionsFollowThePdfSlow) {
  const BSDFContext ctx;
  const Vec3 incident[] = {direction(0.0f, 0.0f), direction(35.0f, 20.0f), direction(60.0f, 160.0f)};
  const double threshold = sidakThreshold(0.01, 4 * 3);
  for (const ArmsSet& set : kSets) {
    const BarbuleArmsBSDF bsdf = makeArms(set);
    for (const Vec3& wi : incident) {
      int scattered = 0;
      ChiSquareResult result = chiSquareDirectionTest(
          [&](PCG32& rng) -> std::optional<Vec3> {
            const float uComponent = rng.nextFloat();
            const Vec2 u(rng.nextFloat(), rng.nextFloat());
            std::optional<BSDFSample> s = bsdf.sample(ctx, wi, kWavelengths, uComponent, u);
            if (!s || s->passThrough) return std::nullopt;
            ++scattered;
            return axisAsPole(s->wo);
          },
          [&](const Vec3& w) { return double(bsdf.pdf(ctx, wi, fromAxisAsPole(w), kWavelengths)); }, 40000, 20, 20, 32);
      std::printf("%-8s wi (%6.3f %6.3f %6.3f): %5d scattered, p = %.3g\n", set.name, wi.x, wi.y, wi.z, scattered,
                  result.pValue);
      EXPECT_GT(scattered, 1000) << set.name;
      EXPECT_GT(result.pValue, threshold) << set.name << ": " << result.message;
    }
  }
}

TEST(BarbuleArmsBSDF, TheSamplersAlbedoIsTheIntegralOfEvalSlow) {
  // Two estimators of the reflected fraction: the mean weight of the sampler's scattering samples
  // (pass-through samples weigh 1 - coverage over its own probability, also 1 - coverage), and eval
  // integrated over directions drawn from the cosine, blind to the sampler.
  for (const ArmsSet& set : {kSets[0], kSets[2]}) {
    const BarbuleArmsBSDF bsdf = makeArms(set);
    for (const Vec3& wi : {direction(0.0f, 0.0f), direction(50.0f, 30.0f)}) {
      const Spectrum sampled = sampledAlbedo(bsdf, wi, 200000) - bsdf.passThrough({}, wi, testWavelengths());
      const Spectrum integrated = integratedAlbedo(bsdf, wi, 400000);
      for (int k = 0; k < kSpectrumSamples; ++k) {
        std::printf("%-8s wi (%6.3f %6.3f %6.3f): sampled %.5f integrated %.5f\n", set.name, wi.x, wi.y, wi.z,
                    sampled[k], integrated[k]);
        EXPECT_NEAR(sampled[k], integrated[k], 0.04f * integrated[k] + 1e-4f) << set.name;
      }
      EXPECT_GT(sampled[0], 0.01f);
    }
  }
}

TEST(BarbuleArmsBSDF, OneArmIsTheEllipseBarbulesReflectionLobe) {
  const ArmsSet& set = kSets[3];
  const BarbuleArmsBSDF arms = makeArms(set, 0.58f);
  BarbuleParameters params;
  params.b = set.b;
  params.phi0 = -kHalfPi;
  params.phi1 = kHalfPi;
  params.mu = set.mu;
  params.H = set.H;
  params.height = 0.58f;
  const BarbuleBSDF ellipse(params);
  const BSDFContext ctx;
  PCG32 rng(3);
  int compared = 0;
  for (int i = 0; i < 3000; ++i) {
    const Vec3 wi = sampleCosineHemisphere(Vec2(rng.nextFloat(), rng.nextFloat()));
    // Near wi's mirror about a random normal of the barbules, where R has its values.
    const float phi = (rng.nextFloat() - 0.5f) * 3.0f, theta = (rng.nextFloat() - 0.5f) * 0.15f;
    const Vec3 m(std::cos(theta) * std::sin(phi), std::sin(theta), std::cos(theta) * std::cos(phi));
    const Vec3 wo = reflect(wi, m);
    const Spectrum expected = ellipse.evalLobes(ctx, wi, wo, kWavelengths).reflection * std::abs(wo.z);
    const Spectrum value = arms.eval(ctx, wi, wo, kWavelengths);
    for (int k = 0; k < kSpectrumSamples; ++k)
      EXPECT_NEAR(value[k], expected[k], 2e-4f * expected[k] + 1e-6f) << "wi " << wi.x << " " << wi.y << " " << wi.z;
    compared += expected[0] > 0.0f;
    EXPECT_NEAR(arms.passThrough(ctx, wi, kWavelengths)[0], ellipse.passThrough(ctx, wi, kWavelengths)[0], 2e-5f);
  }
  EXPECT_GT(compared, 500);
}

TEST(BarbuleArmsBSDF, ThreeMirrorsSendNormalLightThreeWaysBluerOnTheArms) {
  // Stavenga et al. 2011: a reflector in the feather's plane and two at about 30 degrees. Light
  // along the vane normal leaves the middle arm along the normal and the side arms at 60 degrees;
  // the side arms' film is met at 30 degrees, so its colour moves to shorter wavelengths. A 0.1 um
  // keratin film (no layers) has one first-order peak in the visible, near 4 n d.
  const ArmsSet flat{"flat roof", {-30.0, 0.0, 30.0}, 0.1f, 16.0f, 0.0f, 10.0f};
  const BarbuleArmsBSDF bsdf = makeArms(flat, 0.1f);
  const BSDFContext ctx;
  const Vec3 wi(0.0f, 0.0f, 1.0f);
  auto at = [&](float angleDeg, float lambda) {
    const Vec3 wo = direction(angleDeg, 0.0f);
    return bsdf.eval(ctx, wi, wo, Wavelengths::fixed({lambda, lambda, lambda, lambda}))[0];
  };
  EXPECT_GT(at(0.0f, 550.0f), 0.0f);
  EXPECT_GT(at(60.0f, 550.0f), 0.0f);
  EXPECT_GT(at(-60.0f, 550.0f), 0.0f);
  // Between the mirrors only the arms' rounded corners reflect.
  EXPECT_LT(at(30.0f, 550.0f), 0.02f * at(60.0f, 550.0f));
  auto peak = [&](float angleDeg) {
    float best = 0.0f, where = 0.0f;
    for (float l = 380.0f; l <= 780.0f; l += 1.0f)
      if (const float v = at(angleDeg, l); v > best) best = v, where = l;
    return where;
  };
  const float middle = peak(0.0f), side = peak(60.0f);
  std::printf("peak along the normal %.0f nm, from the side arms at 60 degrees %.0f nm\n", middle, side);
  // The film's own peak: 2 n d cos(theta_t) = lambda / 2 with n ~ 1.55 (keratin).
  EXPECT_NEAR(middle, 620.0f, 25.0f);
  EXPECT_LT(side, middle - 20.0f);
  EXPECT_EQ(side, peak(-60.0f));
}

TEST(BarbuleArmsBSDF, TheSceneReadsItsParametersAndRefusesBadOnes) {
  std::shared_ptr<BSDF> bsdf = loadBSDF("barbulearms", "<string name=\"arm_tilts\" value=\"-30, 0, 30\"/>");
  auto* arms = dynamic_cast<BarbuleArmsBSDF*>(bsdf.get());
  ASSERT_NE(arms, nullptr);
  EXPECT_EQ(arms->geometry().armCount(), 3);
  EXPECT_NEAR(arms->geometry().spacing(), arms->geometry().contactSpacing(), 1e-12);
  EXPECT_TRUE(arms->hasSingularValues());  // exponent 4 by default

  EXPECT_NE(loadBSDFError("barbulearms", "").find("arm_tilts"), std::string::npos);
  EXPECT_NE(loadBSDFError("barbulearms", "<string name=\"arm_tilts\" value=\"0, 95\"/>").find("'95'"),
            std::string::npos);
  EXPECT_NE(loadBSDFError("barbulearms", "<string name=\"arm_tilts\" value=\"0, 89.5\"/>").find("-89 to 89"),
            std::string::npos);
  EXPECT_NE(loadBSDFError("barbulearms", "<string name=\"arm_tilts\" value=\"-30,,30\"/>").find("empty place"),
            std::string::npos);
  EXPECT_NE(loadBSDFError("barbulearms", "<string name=\"arm_tilts\" value=\"0\"/><float name=\"b\" value=\"1e-6\"/>")
                .find("'b'"),
            std::string::npos);
  EXPECT_NE(loadBSDFError("barbulearms", "<string name=\"arm_tilts\" value=\"0, ten\"/>").find("'ten'"),
            std::string::npos);
  EXPECT_NE(loadBSDFError("barbulearms", "<string name=\"arm_tilts\" value=\"0 0 0 0 0 0 0 0 0\"/>").find("got 9"),
            std::string::npos);
  EXPECT_NE(loadBSDFError("barbulearms", "<string name=\"arm_tilts\" value=\"0\"/><float name=\"H\" value=\"-1\"/>")
                .find("'H'"),
            std::string::npos);
  EXPECT_NE(loadBSDFError("barbulearms",
                          "<string name=\"arm_tilts\" value=\"0\"/><float name=\"profile_exponent\" value=\"40\"/>")
                .find("profile_exponent"),
            std::string::npos);
  // The ellipse's own parameters mean nothing here.
  EXPECT_NE(loadBSDFError("barbulearms", "<string name=\"arm_tilts\" value=\"0\"/><float name=\"phi_0\" value=\"0\"/>")
                .find("unknown parameter 'phi_0'"),
            std::string::npos);
  EXPECT_NE(
      loadBSDFError("barbulearms", "<string name=\"arm_tilts\" value=\"0\"/><string name=\"layers\" value=\"x:1\"/>")
          .find("layers"),
      std::string::npos);
}
