// Mitsuba 3's `principled` BSDF: sampling against the density, weights, energy, the limits the
// model reduces to, reciprocity, and reading it from a scene.
#include <gtest/gtest.h>

#include <iostream>
#include "bsdfs/principled.h"
#include "builtin/builtin_plugins.h"
#include "optics/fresnel.h"
#include "scene/scene_loader.h"
#include "support/bsdf_test_support.h"

using namespace columba;
using namespace columba::testing;

namespace {
const BSDFContext kContext;

struct NamedParameters {
  const char* name;
  PrincipledParameters parameters;
};

PrincipledParameters withBase(float base) {
  PrincipledParameters p;
  p.baseColor = SpectralDistribution::constant(base);
  return p;
}

// Parameter sets exercising every lobe: the plastic-like default, an anisotropic metal, a clear
// coat, a sheen, partly and fully transmissive glass, and an interior less dense than outside.
std::vector<NamedParameters> parameterSets() {
  std::vector<NamedParameters> sets;
  sets.push_back({"default", PrincipledParameters{}});
  PrincipledParameters metal = withBase(0.8f);
  metal.metallic = 1.0f;
  metal.roughness = 0.4f;
  metal.anisotropic = 0.8f;
  sets.push_back({"anisotropic metal", metal});
  PrincipledParameters coated = withBase(0.3f);
  coated.roughness = 0.6f;
  coated.clearcoat = 1.0f;
  coated.clearcoatGloss = 0.3f;
  coated.sheen = 0.5f;
  coated.sheenTint = 0.5f;
  coated.flatness = 0.5f;
  sets.push_back({"clearcoat", coated});
  PrincipledParameters glassy;
  glassy.specTrans = 0.7f;
  glassy.roughness = 0.45f;
  glassy.metallic = 0.2f;
  glassy.specTint = 0.5f;
  sets.push_back({"partly transmissive", glassy});
  PrincipledParameters glass = withBase(0.9f);
  glass.specTrans = 1.0f;
  glass.roughness = 0.5f;
  glass.anisotropic = 0.5f;
  sets.push_back({"glass", glass});
  // An interior less dense than the exterior: total internal reflection from above.
  PrincipledParameters lessDense;
  lessDense.roughness = 0.8f;
  lessDense.metallic = 0.2f;
  lessDense.clearcoat = 1.0f;
  lessDense.specTrans = 0.5f;
  lessDense.eta = 0.5f;
  sets.push_back({"eta 0.5", lessDense});
  return sets;
}

bool transmits(const PrincipledParameters& p) { return p.specTrans.mean() > 0.0f && p.metallic.mean() < 1.0f; }

// wi above the surface, and below it for the sets that transmit.
std::vector<float> anglesFor(const PrincipledParameters& p) {
  if (transmits(p)) return {10.0f, 50.0f, 80.0f, 130.0f, 170.0f};
  return {10.0f, 50.0f, 80.0f};
}

std::shared_ptr<BSDF> loadPrincipled(const std::string& parameters) { return loadBSDF("principled", parameters); }
std::string loadError(const std::string& parameters) { return loadBSDFError("principled", parameters); }
}  // namespace

TEST(Principled, SamplingMatchesPdfSlow) {
  int tests = 0;
  for (const auto& set : parameterSets()) tests += int(anglesFor(set.parameters).size());
  const double threshold = sidakThreshold(0.01, tests);
  double minP = 1.0;
  uint64_t seed = 1;
  for (const auto& set : parameterSets()) {
    PrincipledBSDF bsdf(set.parameters);
    // The clearcoat's GTR1 lobe (alpha 0.07 here) and refraction need the finer grid.
    ChiSquareGrid grid =
        set.parameters.clearcoat.mean() > 0.0f || transmits(set.parameters) ? chiSquareGrid(0.1f) : chiSquareGrid(0.3f);
    for (float theta : anglesFor(set.parameters)) {
      ChiSquareResult r = chiSquareBSDF(bsdf, directionAt(theta, 35.0f), grid, 300000, seed++);
      std::cout << set.name << " theta " << theta << ": " << r.message << "\n";
      EXPECT_GT(r.pValue, threshold) << set.name << " theta " << theta << ": " << r.message;
      minP = std::min(minP, r.pValue);
    }
  }
  std::cout << "principled: min p = " << minP << " (threshold " << threshold << ")\n";
}

TEST(Principled, WeightIsEvalOverPdf) {
  for (auto set : parameterSets()) {
    set.parameters.baseColor = SpectralDistribution::piecewiseLinear({400.0f, 700.0f}, {0.2f, 0.9f});
    PrincipledBSDF bsdf(set.parameters);
    for (float theta : anglesFor(set.parameters))
      EXPECT_LT(maxWeightError(bsdf, directionAt(theta, 60.0f)), 2e-3) << set.name << " theta " << theta;
  }
}

TEST(Principled, AlbedoIsAtMostOne) {
  // Radiance refracted into the denser side is compressed by 1 / eta^2 (1.5^2 here): counted
  // back, no light is created. Sets with a white diffuse base are left out on purpose: Disney's
  // diffuse lobe with its retro-reflection, plus the specular lobe on top of it, is not
  // energy-conserving there (in Mitsuba too).
  PrincipledParameters base = withBase(0.8f);
  std::vector<NamedParameters> sets = {{"default", base}};
  PrincipledParameters metal = withBase(1.0f);
  metal.metallic = 1.0f;
  metal.roughness = 0.3f;
  sets.push_back({"white metal", metal});
  PrincipledParameters glass = withBase(1.0f);
  glass.specTrans = 1.0f;
  glass.roughness = 0.3f;
  sets.push_back({"white glass", glass});
  PrincipledParameters mixed = withBase(0.7f);
  mixed.specTrans = 0.5f;
  mixed.clearcoat = 1.0f;
  mixed.roughness = 0.8f;
  sets.push_back({"mixed", mixed});
  const float eta = 1.5f;
  for (const auto& set : sets) {
    PrincipledBSDF bsdf(set.parameters);
    for (float theta : {0.0f, 45.0f, 80.0f, 135.0f}) {
      Vec3 wi = directionAt(theta, 20.0f);
      bool inside = wi.z < 0.0f;
      if (inside && !transmits(set.parameters)) continue;
      double energy = 0.0;
      PCG32 rng(4, uint64_t(theta));
      const int n = 100000;
      for (int i = 0; i < n; ++i) {
        auto s = bsdf.sample(kContext, wi, testWavelengths(), rng.nextFloat(), Vec2(rng.nextFloat(), rng.nextFloat()));
        if (!s) continue;
        float scale = sameHemisphere(wi, s->wo) ? 1.0f : (inside ? 1.0f / (eta * eta) : eta * eta);
        energy += s->weight[0] * scale / n;
      }
      // From below only the dielectric interface remains, weighted by (1 - metallic) spec_trans.
      double bound = inside ? (1.0 - set.parameters.metallic.mean()) * set.parameters.specTrans.mean() : 1.0;
      std::cout << set.name << " theta " << theta << ": albedo " << energy << " (at most " << bound << ")\n";
      EXPECT_LE(energy, bound + 0.01) << set.name << " theta " << theta;
      EXPECT_GT(energy, 0.3 * bound) << set.name << " theta " << theta;
    }
  }
}

TEST(Principled, SmoothMetalReflectsItsBaseColourAtNormalIncidence) {
  // Schlick's F(0) = R0 = base_color, and a near-delta GGX lobe reflects all it gets.
  const SpectralDistribution base = SpectralDistribution::piecewiseLinear({400.0f, 700.0f}, {0.9f, 0.3f});
  PrincipledParameters p;
  p.baseColor = base;
  p.metallic = 1.0f;
  p.roughness = 0.05f;
  PrincipledBSDF bsdf(p);
  Spectrum albedo = sampledAlbedo(bsdf, directionAt(0.0f), 20000);
  const Wavelengths wl = testWavelengths();
  for (int i = 0; i < kSpectrumSamples; ++i) EXPECT_NEAR(albedo[i], base.eval(wl[i]), 0.01f) << wl[i];
}

TEST(Principled, SmoothGlassSplitsAsFresnelSays) {
  // Normal incidence on nearly smooth glass (eta 1.5): 0.04 reflected, the rest refracted, tinted
  // by sqrt(base_color) and, from outside, compressed by 1 / 1.5^2; from inside expanded by 1.5^2.
  PrincipledParameters p = withBase(0.64f);
  p.specTrans = 1.0f;
  p.roughness = 0.05f;
  PrincipledBSDF bsdf(p);
  for (bool inside : {false, true}) {
    Vec3 wi(0.0f, 0.0f, inside ? -1.0f : 1.0f);
    double reflected = 0.0, refracted = 0.0;
    PCG32 rng(5, 9);
    const int n = 100000;
    for (int i = 0; i < n; ++i) {
      auto s = bsdf.sample(kContext, wi, testWavelengths(), rng.nextFloat(), Vec2(rng.nextFloat(), rng.nextFloat()));
      if (!s) continue;
      (sameHemisphere(s->wo, wi) ? reflected : refracted) += s->weight[0] / n;
    }
    float scale = 0.8f * (inside ? 2.25f : 1.0f / 2.25f);
    EXPECT_NEAR(reflected, 0.04, 0.003) << (inside ? "inside" : "outside");
    EXPECT_NEAR(refracted, 0.96 * scale, 0.01 * scale) << (inside ? "inside" : "outside");
  }
}

TEST(Principled, RoughDiffuseLimitIsBurleysDiffuse) {
  // specular 0 gives eta 1: no specular reflection, and the rest is Disney's diffuse,
  // f = base / pi (1 - F_L / 2)(1 - F_V / 2) + base / pi R_R (F_L + F_V + F_L F_V (R_R - 1)),
  // F = (1 - cos)^5, R_R = 2 roughness cos^2(theta_d), for roughness 1.
  PrincipledParameters p = withBase(0.6f);
  p.roughness = 1.0f;
  p.eta = 1.0f;
  PrincipledBSDF bsdf(p);
  const Vec3 wi = directionAt(30.0f, 0.0f), wo = directionAt(70.0f, 150.0f);
  const Vec3 h = normalize(wi + wo);
  double fl = std::pow(1.0 - wo.z, 5.0), fv = std::pow(1.0 - wi.z, 5.0);
  double rr = 2.0 * sqr(double(dot(h, wo)));
  double f = 0.6 / kPiDouble * ((1.0 - fl / 2) * (1.0 - fv / 2) + rr * (fl + fv + fl * fv * (rr - 1.0)));
  EXPECT_NEAR(bsdf.eval(kContext, wi, wo, testWavelengths())[0], f * wo.z, 1e-6);
}

TEST(Principled, AgreesWithMitsubasReferenceValues) {
  // Mitsuba 3's own regression values (src/bsdfs/tests/test_principled.py, test05_eval_pdf): eval
  // and pdf toward wo at theta = i / 19 * 90 degrees in the plane of wi = (1, 0, 1), which that
  // test leaves unnormalised. For it Mitsuba's Fresnel term takes cos(theta) above 1 as given
  // where Columba's clamps it, and its clearcoat masking reads wi.z alone: the source of the
  // remaining 0.2 %; with both imitated the values agree to 2e-7.
  const double pdfs[] = {0.17007458, 0.15398569, 0.14061448, 0.12924497, 0.11933098, 0.11045812, 0.10231399,
                         0.09466465, 0.08733665, 0.08020337, 0.07317451, 0.06618816, 0.05920459, 0.05220171,
                         0.04517134, 0.03811638, 0.03104863, 0.02398696, 0.01695592, 0.00998455};
  const double values[] = {0.06804996, 0.06425636, 0.06090123, 0.05784756, 0.05498623, 0.05223095, 0.04951376,
                           0.04678141, 0.04399250, 0.04111535, 0.03812597, 0.03500543, 0.03173549, 0.02829159,
                           0.02463321, 0.02069348, 0.01637275, 0.01154480, 0.00609156, 4.70366e-18};
  PrincipledParameters p;  // base_color and roughness at their defaults
  p.metallic = 0.3f;
  p.specTint = 0.6f;
  p.eta = 2.0f / (1.0f - std::sqrt(0.08f * 0.4f)) - 1.0f;  // specular 0.4
  p.anisotropic = 0.3f;
  p.clearcoat = 0.3f;
  p.clearcoatGloss = 0.5f;
  p.sheen = 0.9f;
  p.sheenTint = 0.9f;
  p.specTrans = 0.5f;
  p.flatness = 0.5f;
  expectValuesAlongMitsubasTestArc(PrincipledBSDF(p), values, pdfs, 3e-3, 3e-3);
}

TEST(Principled, ReflectionIsReciprocal) {
  PrincipledParameters p;
  p.baseColor = SpectralDistribution::piecewiseLinear({400.0f, 700.0f}, {0.1f, 0.8f});
  p.metallic = 0.3f;
  p.roughness = 0.4f;
  p.anisotropic = 0.6f;
  p.specTint = 0.4f;
  p.sheen = 0.7f;
  p.sheenTint = 0.3f;
  p.clearcoat = 0.8f;
  p.clearcoatGloss = 0.5f;
  p.flatness = 0.4f;
  PrincipledBSDF bsdf(p);
  const Wavelengths wl = testWavelengths();
  PCG32 rng(8, 8);
  for (int n = 0; n < 300; ++n) {
    Vec3 a = directionAt(85.0f * rng.nextFloat(), 360.0f * rng.nextFloat());
    Vec3 b = directionAt(85.0f * rng.nextFloat(), 360.0f * rng.nextFloat());
    Spectrum fab = bsdf.eval(kContext, a, b, wl) / b.z, fba = bsdf.eval(kContext, b, a, wl) / a.z;
    for (int i = 0; i < kSpectrumSamples; ++i) EXPECT_NEAR(fab[i], fba[i], 1e-4f * std::max(1.0f, fab[i]));
  }
}

TEST(Principled, OpaqueSettingsAreBlackFromBelow) {
  PrincipledParameters p;
  p.clearcoat = 1.0f;
  p.sheen = 1.0f;
  PrincipledBSDF bsdf(p);
  const Wavelengths wl = testWavelengths();
  Vec3 below = -directionAt(30.0f), above = directionAt(30.0f, 180.0f);
  EXPECT_TRUE(bsdf.eval(kContext, below, -above, wl).isZero());
  EXPECT_TRUE(bsdf.eval(kContext, below, above, wl).isZero());
  EXPECT_TRUE(bsdf.eval(kContext, above, below, wl).isZero());
  EXPECT_FALSE(bsdf.sample(kContext, below, wl, 0.5f, Vec2(0.5f, 0.5f)));
  EXPECT_EQ(bsdf.pdf(kContext, below, -above, wl), 0.0f);
}

TEST(Principled, SceneDefaultsAreMitsubas) {
  const Wavelengths wl = testWavelengths();
  auto defaults = loadPrincipled("");
  ASSERT_TRUE(defaults);
  // Mitsuba 3's defaults written out: specular 0.5 is eta 1.5.
  auto explicitDefaults = loadPrincipled(R"(
    <float name="base_color" value="0.5"/> <float name="roughness" value="0.5"/>
    <float name="anisotropic" value="0"/> <float name="metallic" value="0"/> <float name="spec_trans" value="0"/>
    <float name="eta" value="1.5"/> <float name="spec_tint" value="0"/> <float name="sheen" value="0"/>
    <float name="sheen_tint" value="0"/> <float name="flatness" value="0"/> <float name="clearcoat" value="0"/>
    <float name="clearcoat_gloss" value="0"/> <float name="main_specular_sampling_rate" value="1"/>
    <float name="diffuse_reflectance_sampling_rate" value="1"/> <float name="clearcoat_sampling_rate" value="1"/>)");
  auto tinted = loadPrincipled(R"(<rgb name="base_color" value="0.8, 0.2, 0.1"/>
    <float name="metallic" value="0.7"/> <float name="specular" value="0.6"/> <float name="clearcoat" value="0.6"/>)");
  ASSERT_TRUE(explicitDefaults && tinted);
  for (float theta : {0.0f, 40.0f, 75.0f}) {
    Vec3 wi = directionAt(theta), wo = directionAt(35.0f, 160.0f);
    float a = defaults->eval(kContext, wi, wo, wl)[0], b = explicitDefaults->eval(kContext, wi, wo, wl)[0];
    EXPECT_GT(a, 0.0f);
    EXPECT_NEAR(a, b, 1e-6f * a) << theta;
    EXPECT_NEAR(defaults->pdf(kContext, wi, wo, wl), explicitDefaults->pdf(kContext, wi, wo, wl), 1e-6f) << theta;
    EXPECT_GT(std::abs(tinted->eval(kContext, wi, wo, wl)[0] - a), 0.01f * a) << theta;
  }
}

TEST(Principled, SceneMistakesAreErrors) {
  EXPECT_NE(loadError(R"(<float name="metalic" value="1"/>)").find("metalic"), std::string::npos);
  EXPECT_NE(loadError(R"(<float name="eta" value="1.4"/> <float name="specular" value="0.5"/>)").find("not both"),
            std::string::npos);
  EXPECT_NE(loadError(R"(<float name="roughness" value="1.5"/>)").find("roughness"), std::string::npos);
  EXPECT_NE(loadError(R"(<float name="eta" value="-1"/>)").find("eta"), std::string::npos);
  EXPECT_EQ(loadError(R"(<float name="spec_trans" value="1"/> <float name="eta" value="1.33"/>)"), "");
}

TEST(Principled, TexturedParametersAreTakenAtTheShadingPoint) {
  // A checkerboard of base colours and of roughnesses: at each point the BSDF is the one with
  // that point's constants.
  const std::string constants = R"(<float name="metallic" value="0.4"/> <float name="clearcoat" value="0.5"/>
    <float name="spec_trans" value="0.3"/> <float name="sheen" value="0.6"/> <float name="sheen_tint" value="0.5"/>)";
  auto textured = loadPrincipled(constants + R"(
    <texture type="checkerboard" name="base_color"><rgb name="color0" value="0.8, 0.3, 0.1"/>
      <rgb name="color1" value="0.1, 0.4, 0.7"/></texture>
    <texture type="checkerboard" name="roughness"><float name="color0" value="0.7"/>
      <float name="color1" value="0.3"/></texture>)");  // single values take the colours swapped
  auto first = loadPrincipled(
      constants + R"(<rgb name="base_color" value="0.8, 0.3, 0.1"/> <float name="roughness" value="0.3"/>)");
  auto second = loadPrincipled(
      constants + R"(<rgb name="base_color" value="0.1, 0.4, 0.7"/> <float name="roughness" value="0.7"/>)");
  ASSERT_TRUE(textured && first && second);
  const Wavelengths wl = testWavelengths();
  const BSDFContext inFirst{Vec2(0.25f, 0.25f), Vec3(), Vec3()}, inSecond{Vec2(0.75f, 0.25f), Vec3(), Vec3()};
  const Vec3 wi = directionAt(35.0f), wo = directionAt(50.0f, 160.0f), below = directionAt(150.0f, 200.0f);
  for (const Vec3& out : {wo, below}) {
    for (int i = 0; i < kSpectrumSamples; ++i) {
      EXPECT_FLOAT_EQ(textured->eval(inFirst, wi, out, wl)[i], first->eval(inFirst, wi, out, wl)[i]);
      EXPECT_FLOAT_EQ(textured->eval(inSecond, wi, out, wl)[i], second->eval(inSecond, wi, out, wl)[i]);
    }
    EXPECT_FLOAT_EQ(textured->pdf(inFirst, wi, out, wl), first->pdf(inFirst, wi, out, wl));
    EXPECT_FLOAT_EQ(textured->pdf(inSecond, wi, out, wl), second->pdf(inSecond, wi, out, wl));
  }
  EXPECT_NE(textured->eval(inFirst, wi, wo, wl)[0], textured->eval(inSecond, wi, wo, wl)[0]);
}

TEST(Principled, AVertexsQueriesAreTheSeparateCalls) {
  // queryVertex works the textured material out once; its answers must be those of eval, pdf and
  // sample, for both principled BSDFs, on either side.
  const std::string textures =
      R"(<texture type="checkerboard" name="base_color"><rgb name="color0" value="0.8, 0.3, 0.1"/>
      <rgb name="color1" value="0.1, 0.4, 0.7"/></texture>
    <texture type="checkerboard" name="roughness"><float name="color0" value="0.3"/>
      <float name="color1" value="0.7"/></texture> <float name="spec_trans" value="0.4"/>)";
  const Wavelengths wl = testWavelengths();
  for (const char* type : {"principled", "principledthin"}) {
    auto bsdf = loadBSDF(type, textures);
    ASSERT_TRUE(bsdf) << type;
    for (Vec2 uv : {Vec2(0.25f, 0.25f), Vec2(0.75f, 0.25f)}) {
      const BSDFContext ctx{uv, Vec3(), Vec3()};
      for (const Vec3& wi : {directionAt(35.0f), directionAt(140.0f, 20.0f)}) {
        const Vec3 wo = directionAt(50.0f, 160.0f);
        BSDFVertexRequest request;
        request.woLights = &wo;
        request.woLightCount = 1;
        BSDFEvalPdf toLight;
        request.toLights = &toLight;
        request.lightPdf = true;
        request.sample = true;
        request.uComponent = 0.6f;
        request.u = Vec2(0.3f, 0.7f);
        const BSDFVertexQueries q = bsdf->queryVertex(ctx, wi, wl, request);
        const std::optional<BSDFSample> separate = bsdf->sample(ctx, wi, wl, 0.6f, Vec2(0.3f, 0.7f));
        for (int i = 0; i < kSpectrumSamples; ++i) EXPECT_EQ(toLight.value[i], bsdf->eval(ctx, wi, wo, wl)[i]);
        EXPECT_EQ(toLight.pdf, bsdf->pdf(ctx, wi, wo, wl));
        ASSERT_EQ(q.sampled.has_value(), separate.has_value()) << type;
        if (!separate) continue;
        EXPECT_EQ(q.sampled->wo.x, separate->wo.x);
        EXPECT_EQ(q.sampled->pdf, separate->pdf);
        EXPECT_EQ(q.sampled->weight[0], separate->weight[0]);
      }
    }
  }
}
