#include "support/bsdf_test_support.h"

#include <gtest/gtest.h>

#include <cmath>
#include "builtin/builtin_plugins.h"
#include "core/sampling.h"
#include "scene/scene.h"

namespace columba::testing {

Wavelengths testWavelengths() { return Wavelengths::fixed({430.0f, 520.0f, 610.0f, 700.0f}); }

Vec3 directionAt(float thetaDegrees, float phiDegrees) {
  float theta = degToRad(thetaDegrees), phi = degToRad(phiDegrees);
  return Vec3(std::sin(theta) * std::cos(phi), std::sin(theta) * std::sin(phi), std::cos(theta));
}

double sidakThreshold(double familyAlpha, int tests) { return 1.0 - std::pow(1.0 - familyAlpha, 1.0 / tests); }

ChiSquareGrid chiSquareGrid(float alpha) {
  if (alpha < 0.2f) return {80, 40, 32};
  if (alpha < 0.5f) return {40, 40, 16};
  return {};
}

ChiSquareResult chiSquareBSDF(const BSDF& bsdf, const Vec3& wi, ChiSquareGrid grid, int sampleCount, uint64_t seed) {
  const BSDFContext ctx;
  const Wavelengths wl = testWavelengths();
  return chiSquareDirectionTest(
      [&](PCG32& rng) -> std::optional<Vec3> {
        float uComponent = rng.nextFloat();
        Vec2 u(rng.nextFloat(), rng.nextFloat());
        auto s = bsdf.sample(ctx, wi, wl, uComponent, u);
        if (!s || s->delta) return std::nullopt;
        return s->wo;
      },
      [&](const Vec3& wo) { return double(bsdf.pdf(ctx, wi, wo, wl)); }, sampleCount, grid.thetaBins, grid.phiBins,
      grid.quadrature, seed);
}

double maxWeightError(const BSDF& bsdf, const Vec3& wi, int sampleCount) {
  const BSDFContext ctx;
  const Wavelengths wl = testWavelengths();
  PCG32 rng(3, 5);
  double worst = 0.0;
  for (int n = 0; n < sampleCount; ++n) {
    float uComponent = rng.nextFloat();
    Vec2 u(rng.nextFloat(), rng.nextFloat());
    auto s = bsdf.sample(ctx, wi, wl, uComponent, u);
    if (!s || s->delta) continue;
    float pdf = bsdf.pdf(ctx, wi, s->wo, wl);
    Spectrum expected = bsdf.eval(ctx, wi, s->wo, wl) / pdf;
    for (int i = 0; i < kSpectrumSamples; ++i)
      worst = std::max(worst, std::abs(double(s->weight[i]) - expected[i]) / std::max(1e-3, double(expected[i])));
    worst = std::max(worst, std::abs(double(s->pdf) - pdf) / pdf);
  }
  return worst;
}

Spectrum sampledAlbedo(const BSDF& bsdf, const Vec3& wi, int sampleCount, uint64_t seed) {
  const BSDFContext ctx;
  const Wavelengths wl = testWavelengths();
  PCG32 rng(seed, 1);
  Spectrum sum(0.0f);
  for (int n = 0; n < sampleCount; ++n) {
    float uComponent = rng.nextFloat();
    Vec2 u(rng.nextFloat(), rng.nextFloat());
    if (auto s = bsdf.sample(ctx, wi, wl, uComponent, u)) sum += s->weight;
  }
  return sum / float(sampleCount);
}

Spectrum integratedAlbedo(const BSDF& bsdf, const Vec3& wi, int sampleCount, uint64_t seed) {
  const BSDFContext ctx;
  const Wavelengths wl = testWavelengths();
  PCG32 rng(seed, 2);
  Spectrum sum(0.0f);
  for (int n = 0; n < sampleCount; ++n) {
    Vec3 wo = sampleCosineHemisphere(Vec2(rng.nextFloat(), rng.nextFloat()));
    float pdf = 0.5f * cosineHemispherePdf(wo.z);  // either hemisphere with probability 1/2
    if (!(pdf > 0.0f)) continue;
    if (rng.nextFloat() < 0.5f) wo.z = -wo.z;
    sum += bsdf.eval(ctx, wi, wo, wl) / pdf;
  }
  return sum / float(sampleCount);
}

namespace {
void setValue(Properties& props, const std::string& name, Properties::Value value) {
  value.location = SourceLocation{"test.xml", 1};
  props.set(name, std::move(value));
}
}  // namespace

void setFloat(Properties& props, const std::string& name, float value) {
  Properties::Value v;
  v.kind = Properties::ValueKind::Float;
  v.number = value;
  setValue(props, name, v);
}

void setInt(Properties& props, const std::string& name, int value) {
  Properties::Value v;
  v.kind = Properties::ValueKind::Integer;
  v.number = value;
  setValue(props, name, v);
}

void setString(Properties& props, const std::string& name, const std::string& value) {
  Properties::Value v;
  v.kind = Properties::ValueKind::String;
  v.text = value;
  setValue(props, name, v);
}

void setBool(Properties& props, const std::string& name, bool value) {
  Properties::Value v;
  v.kind = Properties::ValueKind::Boolean;
  v.boolean = value;
  setValue(props, name, v);
}

void addNested(Properties& props, std::shared_ptr<Object> object) {
  Properties::Child child;
  child.object = std::move(object);
  child.location = SourceLocation{"test.xml", 2};
  child.tag = "bsdf";
  props.addChild(std::move(child));
}

std::shared_ptr<BSDF> loadBSDF(const std::string& type, const std::string& parameters) {
  ParsedScene parsed =
      loadSceneString("<scene version=\"3.0.0\">\n<bsdf type=\"" + type + "\">\n" + parameters + "\n</bsdf></scene>",
                      type + ".xml", ".", {}, builtinPlugins());
  EXPECT_EQ(parsed.objects.size(), 1u);
  return std::dynamic_pointer_cast<BSDF>(parsed.objects.at(0));
}

std::string loadBSDFError(const std::string& type, const std::string& parameters) {
  try {
    loadBSDF(type, parameters);
  } catch (const InputError& e) {
    return e.what();
  }
  return "";
}

void expectValuesAlongMitsubasTestArc(const BSDF& bsdf, const double (&values)[20], const double (&pdfs)[20],
                                      double valueTolerance, double pdfTolerance) {
  const Vec3 wi(1.0f, 0.0f, 1.0f);
  for (int i = 0; i < 20; ++i) {
    double theta = i / 19.0 * kPiDouble / 2.0;
    Vec3 wo(float(std::sin(theta)), 0.0f, float(std::cos(theta)));
    EXPECT_NEAR(bsdf.eval({}, wi, wo, testWavelengths())[0], values[i], valueTolerance * values[i]) << i;
    EXPECT_NEAR(bsdf.pdf({}, wi, wo, testWavelengths()), pdfs[i], pdfTolerance * pdfs[i]) << i;
  }
}

}  // namespace columba::testing
