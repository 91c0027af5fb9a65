// The phase functions: chi-square of their sampling against their densities, and closed forms
// (normalisation, Henyey-Greenstein's mean cosine g, isotropy).
#include <gtest/gtest.h>

#include <cmath>

#include "core/frame.h"
#include "core/sampling.h"
#include "media/hg_phase.h"
#include "media/isotropic_phase.h"
#include "support/bsdf_test_support.h"
#include "support/chi_square.h"
#include "support/error_test_support.h"

using namespace columba;
using namespace columba::testing;

namespace {

// Directions drawn from `phase` for light arriving from `wi` against its pdf.
ChiSquareResult chiSquarePhase(const PhaseFunction& phase, const Vec3& wi, int thetaBins = 20) {
  return chiSquareDirectionTest(
      [&](PCG32& rng) -> std::optional<Vec3> {
        auto s = phase.sample(wi, Vec2(rng.nextFloat(), rng.nextFloat()));
        return s ? std::optional(s->wo) : std::nullopt;
      },
      [&](const Vec3& wo) { return double(phase.pdf(wi, wo)); }, 200000, thetaBins, 40, 16);
}

// Integral over the sphere of phase(wi, wo) * g(cos theta), theta between -wi and wo, by midpoints
// in cos theta (the phase functions here are symmetric about -wi).
double integrateOverCosTheta(const PhaseFunction& phase, const Vec3& wi, double (*g)(double)) {
  const Frame frame = Frame::fromNormal(-wi);
  const int n = 200000;
  double sum = 0.0;
  for (int i = 0; i < n; ++i) {
    const double c = -1.0 + (i + 0.5) * 2.0 / n, s = std::sqrt(std::max(0.0, 1.0 - c * c));
    const Vec3 wo = frame.toWorld(Vec3(float(s), 0.0f, float(c)));
    sum += phase.eval(wi, wo) * g(c) * 2.0 / n * kTwoPi;
  }
  return sum;
}

const Vec3 kObliqueWi = normalize(Vec3(0.3f, -0.5f, 0.8f));

}  // namespace

TEST(PhaseFunctions, IsotropicSamplingMatchesItsDensitySlow) {
  IsotropicPhase phase;
  const ChiSquareResult r = chiSquarePhase(phase, kObliqueWi);
  EXPECT_GT(r.pValue, sidakThreshold(0.01, 5)) << r.message;
}

class HenyeyGreensteinChiSquare : public ::testing::TestWithParam<float> {};

TEST_P(HenyeyGreensteinChiSquare, SamplingMatchesItsDensitySlow) {
  HenyeyGreensteinPhase phase(GetParam());
  // Strongly forward lobes need finer bins in cos theta around -wi.
  const ChiSquareResult r = chiSquarePhase(phase, kObliqueWi, std::abs(GetParam()) > 0.8f ? 80 : 20);
  EXPECT_GT(r.pValue, sidakThreshold(0.01, 5)) << r.message;
}

INSTANTIATE_TEST_SUITE_P(G, HenyeyGreensteinChiSquare, ::testing::Values(0.0f, 0.5f, -0.4f, 0.9f));

TEST(PhaseFunctions, AreNormalisedAndHenyeyGreensteinsMeanCosineIsG) {
  IsotropicPhase isotropic;
  EXPECT_FLOAT_EQ(isotropic.eval(kObliqueWi, Vec3(0, 0, 1)), 1.0f / (4.0f * kPi));
  EXPECT_NEAR(integrateOverCosTheta(isotropic, kObliqueWi, [](double) { return 1.0; }), 1.0, 1e-5);
  for (float g : {0.0f, 0.3f, -0.6f, 0.85f}) {
    HenyeyGreensteinPhase hg(g);
    EXPECT_NEAR(integrateOverCosTheta(hg, kObliqueWi, [](double) { return 1.0; }), 1.0, 1e-3) << g;
    EXPECT_NEAR(integrateOverCosTheta(hg, kObliqueWi, [](double c) { return c; }), g, 1e-3) << g;
    // Forward is along the light's travel, -wi: for g > 0 the phase function is largest there.
    if (g > 0.0f) {
      EXPECT_GT(hg.eval(kObliqueWi, -kObliqueWi), hg.eval(kObliqueWi, kObliqueWi));
    }
    // The closed form at theta = 90 degrees: (1 - g^2) / (4 pi (1 + g^2)^1.5).
    const Vec3 side = normalize(cross(kObliqueWi, Vec3(0, 0, 1)));
    EXPECT_NEAR(hg.eval(kObliqueWi, side), (1 - g * g) / (4 * kPi * std::pow(1 + g * g, 1.5f)), 1e-5f);
    // Samples' densities are their values (weight 1).
    PCG32 rng(3);
    for (int i = 0; i < 100; ++i) {
      auto s = hg.sample(kObliqueWi, Vec2(rng.nextFloat(), rng.nextFloat()));
      ASSERT_TRUE(s);
      EXPECT_NEAR(s->pdf, hg.eval(kObliqueWi, s->wo), 1e-4f * s->pdf);
    }
  }
}

TEST(PhaseFunctions, HenyeyGreensteinRefusesGOutsideTheOpenInterval) {
  Properties props;
  props.tag = "phase";
  props.type = "hg";
  props.location = SourceLocation{"scene.xml", 7};
  props.setFloat("g", 1.0);
  std::string message;
  try {
    makeHenyeyGreensteinPhase(props);
  } catch (const InputError& e) {
    message = e.what();
  }
  expectContains(message, {"scene.xml:7", "g must lie strictly between -1 and 1", "1.0"});
}
