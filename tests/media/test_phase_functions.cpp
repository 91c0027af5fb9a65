// The phase functions: chi-square of their sampling against their densities, and closed forms
// (normalisation, Henyey-Greenstein's mean cosine g, isotropy, Rayleigh's moments, a blend's mix).
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>

#include "core/frame.h"
#include "core/sampling.h"
#include "media/blend_phase.h"
#include "media/hg_phase.h"
#include "media/isotropic_phase.h"
#include "media/rayleigh_phase.h"
#include "media/tabulated_phase.h"
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

namespace {
// `blendphase` read from its properties: `weight` (unless empty) and the nested phase functions.
std::shared_ptr<Object> blendOf(const std::string& weight, std::vector<std::shared_ptr<Object>> nested) {
  Properties props;
  props.tag = "phase";
  props.type = "blendphase";
  props.location = SourceLocation{"scene.xml", 4};
  if (!weight.empty()) props.setFloat("weight", std::stod(weight));
  for (auto& object : nested) props.addChild({"", std::move(object), props.location, "phase", "?"});
  return makeBlendPhase(props);
}
}  // namespace

TEST(PhaseFunctions, RayleighSamplingMatchesItsDensitySlow) {
  RayleighPhase phase;
  const ChiSquareResult r = chiSquarePhase(phase, kObliqueWi);
  EXPECT_GT(r.pValue, sidakThreshold(0.01, 5)) << r.message;
}

TEST(PhaseFunctions, RayleighHasItsClosedForms) {
  RayleighPhase rayleigh;
  // Normalised, symmetric (mean cosine 0) and <cos^2> = 3/8 (2/3 + 2/5) = 2/5.
  EXPECT_NEAR(integrateOverCosTheta(rayleigh, kObliqueWi, [](double) { return 1.0; }), 1.0, 1e-6);
  EXPECT_NEAR(integrateOverCosTheta(rayleigh, kObliqueWi, [](double c) { return c; }), 0.0, 1e-6);
  EXPECT_NEAR(integrateOverCosTheta(rayleigh, kObliqueWi, [](double c) { return c * c; }), 0.4, 1e-6);
  // Forward and backward 3 / (8 pi), sideways half of that.
  const Vec3 side = normalize(cross(kObliqueWi, Vec3(0, 0, 1)));
  EXPECT_NEAR(rayleigh.eval(kObliqueWi, -kObliqueWi), 3.0f / (8.0f * kPi), 1e-6f);
  EXPECT_NEAR(rayleigh.eval(kObliqueWi, kObliqueWi), 3.0f / (8.0f * kPi), 1e-6f);
  EXPECT_NEAR(rayleigh.eval(kObliqueWi, side), 3.0f / (16.0f * kPi), 1e-6f);
  // The sampled cosine inverts the distribution (3 c + c^3 + 4) / 8: u = 1/2 gives c = 0.
  const Frame frame = Frame::fromNormal(-kObliqueWi);
  for (float u : {0.0f, 0.1f, 0.5f, 0.93f, 0.999f}) {
    auto s = rayleigh.sample(kObliqueWi, Vec2(u, 0.3f));
    ASSERT_TRUE(s);
    const float c = frame.toLocal(s->wo).z;
    EXPECT_NEAR((3.0f * c + c * c * c + 4.0f) / 8.0f, u, 2e-5f) << u;
    EXPECT_NEAR(s->pdf, rayleigh.eval(kObliqueWi, s->wo), 1e-5f);
  }
}

TEST(PhaseFunctions, ABlendIsItsComponentsMixedSlow) {
  auto blend = std::dynamic_pointer_cast<const PhaseFunction>(
      blendOf("0.3", {std::make_shared<IsotropicPhase>(), std::make_shared<HenyeyGreensteinPhase>(0.7f)}));
  ASSERT_TRUE(blend);
  IsotropicPhase isotropic;
  HenyeyGreensteinPhase hg(0.7f);
  PCG32 rng(5);
  for (int i = 0; i < 50; ++i) {
    const Vec3 wo = sampleUniformSphere(Vec2(rng.nextFloat(), rng.nextFloat()));
    EXPECT_NEAR(blend->eval(kObliqueWi, wo), 0.7f * isotropic.eval(kObliqueWi, wo) + 0.3f * hg.eval(kObliqueWi, wo),
                1e-6f);
    EXPECT_NEAR(blend->pdf(kObliqueWi, wo), blend->eval(kObliqueWi, wo), 1e-6f);
  }
  // Its mean cosine is the blend of the components' (0 and g).
  EXPECT_NEAR(integrateOverCosTheta(*blend, kObliqueWi, [](double c) { return c; }), 0.3 * 0.7, 1e-3);
  const ChiSquareResult r = chiSquarePhase(*blend, kObliqueWi, 40);
  EXPECT_GT(r.pValue, sidakThreshold(0.01, 5)) << r.message;
}

TEST(PhaseFunctions, ABlendNeedsTwoPhaseFunctionsAndAWeightWithinZeroAndOne) {
  std::string message;
  try {
    blendOf("", {std::make_shared<IsotropicPhase>()});
  } catch (const InputError& e) {
    message = e.what();
  }
  expectContains(message, {"scene.xml:4", "two nested phase functions, not 1"});
  message.clear();
  try {
    blendOf("1.5", {std::make_shared<IsotropicPhase>(), std::make_shared<RayleighPhase>()});
  } catch (const InputError& e) {
    message = e.what();
  }
  expectContains(message, {"weight", "must lie in [0, 1]", "1.5"});
}

TEST(PhaseFunctions, ATableOfValuesIsAPiecewiseLinearDensitySlow) {
  // Values 0, 1 over cos theta in [-1, 1]: density (1 + c) / 2 in c, (1 + c) / (4 pi) per
  // steradian, mean cosine 1/3.
  TabulatedPhase ramp({0.0f, 1.0f});
  EXPECT_NEAR(ramp.eval(kObliqueWi, -kObliqueWi), 1.0f / (2.0f * kPi), 1e-6f);
  EXPECT_NEAR(ramp.eval(kObliqueWi, kObliqueWi), 0.0f, 1e-6f);
  EXPECT_NEAR(integrateOverCosTheta(ramp, kObliqueWi, [](double) { return 1.0; }), 1.0, 1e-5);
  EXPECT_NEAR(integrateOverCosTheta(ramp, kObliqueWi, [](double c) { return c; }), 1.0 / 3.0, 1e-5);
  // A flat table is isotropic whatever its scale.
  TabulatedPhase flat({3.0f, 3.0f, 3.0f});
  EXPECT_NEAR(flat.eval(kObliqueWi, Vec3(0, 0, 1)), 1.0f / (4.0f * kPi), 1e-7f);
  // An uneven table with a zero segment: sampling against the density, and the sampled cosine
  // inverts the ramp's distribution ((1 + c)^2 / 4 = u).
  TabulatedPhase uneven({0.2f, 0.0f, 0.0f, 1.5f, 0.4f, 3.0f, 0.7f});
  const ChiSquareResult r = chiSquarePhase(uneven, kObliqueWi, 40);
  EXPECT_GT(r.pValue, sidakThreshold(0.01, 5)) << r.message;
  EXPECT_NEAR(integrateOverCosTheta(uneven, kObliqueWi, [](double) { return 1.0; }), 1.0, 1e-5);
  const Frame frame = Frame::fromNormal(-kObliqueWi);
  for (float u : {0.01f, 0.25f, 0.5f, 0.9f}) {
    auto s = ramp.sample(kObliqueWi, Vec2(u, 0.7f));
    ASSERT_TRUE(s);
    const float c = frame.toLocal(s->wo).z;
    EXPECT_NEAR((1.0f + c) * (1.0f + c) / 4.0f, u, 1e-5f) << u;
    EXPECT_NEAR(s->pdf, ramp.eval(kObliqueWi, s->wo), 1e-6f);
  }
}

TEST(PhaseFunctions, ATableNeedsTwoValuesNotNegativeNotAllZero) {
  auto message = [](const std::string& values) {
    Properties props;
    props.tag = "phase";
    props.type = "tabphase";
    props.location = SourceLocation{"scene.xml", 9};
    props.setString("values", values);
    try {
      makeTabulatedPhase(props);
    } catch (const InputError& e) {
      return std::string(e.what());
    }
    return std::string();
  };
  expectContains(message("1"), {"scene.xml:9", "at least two values"});
  expectContains(message("1, -2, 3"), {"scene.xml:9", "'-2' is not a number at least 0", "value 2"});
  expectContains(message("1, x"), {"'1, x'", "item 2", "'x'", "is not a number"});
  // An empty place between commas used to be dropped, shifting the table; and values past float's
  // range are not numbers.
  expectContains(message("1,,2"), {"scene.xml:9", "'values'", "'1,,2'", "empty place between its commas", "item 2"});
  expectContains(message(",1,2"), {"',1,2'", "item 1"});
  expectContains(message("1, 2,"), {"'1, 2,'", "item 3"});
  expectContains(message("1, 1e400"), {"'1e400'", "is not a number"});
  expectContains(message("0 0 0"), {"all zero"});
  EXPECT_EQ(message("0.5, 1 2"), "");
}

// Only a table's ratios matter: values of 1e37 and above used to overflow its area and 1e-38 and
// below to vanish, losing all scattering; they give what 1 1 1 gives.
TEST(PhaseFunctions, ATablesScaleDoesNotMatterHoweverLargeOrSmall) {
  const TabulatedPhase ones({1.0, 1.0, 1.0}), ramp({1.0, 2.0, 4.0});
  for (double scale : {1e37, 3e38, 1e300, 1e-38, 1e-45, 1e-300}) {
    const TabulatedPhase flat({scale, scale, scale}), scaledRamp({scale, 2.0 * scale, 4.0 * scale});
    for (const Vec3& wo : {Vec3(0, 0, 1), -kObliqueWi, normalize(Vec3(1, 1, 0))}) {
      EXPECT_EQ(flat.eval(kObliqueWi, wo), ones.eval(kObliqueWi, wo)) << scale;
      EXPECT_FLOAT_EQ(scaledRamp.eval(kObliqueWi, wo), ramp.eval(kObliqueWi, wo)) << scale;
    }
    for (float u : {0.1f, 0.6f}) {
      const auto a = flat.sample(kObliqueWi, Vec2(u, 0.3f)), b = ones.sample(kObliqueWi, Vec2(u, 0.3f));
      ASSERT_TRUE(a && b);
      EXPECT_EQ(a->pdf, b->pdf);
    }
  }
}

// Near g = +-1 the lobe is narrower than float resolves in cos theta: at g 0.9999 and 0.99999 the
// sampled light was lost (a mean of 0.729 against the forward limit's 0.909). Every sample's
// weight eval / pdf is 1, so the scattered energy is kept, and the distribution of 1 - cos theta
// matches Henyey-Greenstein's, by chi-square over 20 bins of equal probability (the direction
// bins of chiSquareDirectionTest cannot resolve a lobe 1e-10 wide).
TEST(PhaseFunctions, HenyeyGreensteinKeepsItsLightNearGOfOne) {
  for (float g : {0.999f, 0.9999f, 0.99999f}) {
    const HenyeyGreensteinPhase phase(g);
    const double gd = g;
    // P(1 - cos theta > x) = ((1 - g^2) / sqrt((1 - g)^2 + 2 g x) - (1 - g)) / (2 g).
    auto survival = [&](double x) {
      return ((1.0 - gd) * (1.0 + gd) / std::sqrt((1.0 - gd) * (1.0 - gd) + 2.0 * gd * x) - (1.0 - gd)) / (2.0 * gd);
    };
    const int bins = 20, samples = 100000;
    std::vector<double> observed(bins, 0.0), expected(bins, double(samples) / bins);
    PCG32 rng(4);
    for (int i = 0; i < samples; ++i) {
      const auto s = phase.sample(kObliqueWi, Vec2(rng.nextFloat(), rng.nextFloat()));
      ASSERT_TRUE(s) << g;
      ASSERT_EQ(phase.eval(kObliqueWi, s->wo) / s->pdf, 1.0f) << g;
      const Vec3 sum = kObliqueWi + s->wo;
      const double x = 0.5 * double(dot(sum, sum));  // 1 - cos theta
      observed[std::clamp(int((1.0 - survival(x)) * bins), 0, bins - 1)] += 1.0;
    }
    const ChiSquareResult r = chiSquareTest(observed, expected);
    EXPECT_GT(r.pValue, 0.001) << g << ": " << r.message;
  }
  // Backward, the same: every sample kept with weight 1.
  const HenyeyGreensteinPhase backward(-0.99999f);
  PCG32 rng(8);
  for (int i = 0; i < 10000; ++i) {
    const auto s = backward.sample(kObliqueWi, Vec2(rng.nextFloat(), rng.nextFloat()));
    ASSERT_TRUE(s);
    ASSERT_EQ(backward.eval(kObliqueWi, s->wo) / s->pdf, 1.0f);
  }
}
