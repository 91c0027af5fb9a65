// The barbule BSDF's material is the user's: film index as a number, a named index, a spectrum or
// Cauchy coefficients; the melanin reflectance as a spectrum; presets with sources; and the
// shared checks, with errors naming the scene line.
#include <gtest/gtest.h>

#include <memory>
#include "bsdfs/barbulebsdf.h"
#include "builtin/builtin_plugins.h"
#include "optics/melanin.h"
#include "scene/scene_loader.h"

using namespace columba;

namespace {
std::shared_ptr<BarbuleBSDF> loadBarbule(const std::string& parameters) {
  ParsedScene parsed =
      loadSceneString("<scene version=\"3.0.0\">\n<bsdf type=\"barbulebsdf\">\n" + parameters + "\n</bsdf></scene>",
                      "barbule.xml", ".", {}, builtinPlugins());
  EXPECT_EQ(parsed.objects.size(), 1u);
  return std::dynamic_pointer_cast<BarbuleBSDF>(parsed.objects.at(0));
}

std::string loadError(const std::string& parameters) {
  try {
    loadBarbule(parameters);
  } catch (const InputError& e) {
    return e.what();
  }
  return "";
}

const Wavelengths kWavelengths = Wavelengths::fixed({430.0f, 520.0f, 610.0f, 700.0f});
const Vec3 kIn = normalize(Vec3(0.3f, 0.04f, 0.9f)), kOut = normalize(Vec3(-0.35f, -0.03f, 0.85f));

BarbuleBSDF::Lobes lobesOf(const BarbuleBSDF& bsdf) { return bsdf.evalLobes(BSDFContext{}, kIn, kOut, kWavelengths); }

void expectSameLobes(const BarbuleBSDF& a, const BarbuleBSDF& b, float relTol) {
  BarbuleBSDF::Lobes la = lobesOf(a), lb = lobesOf(b);
  for (int k = 0; k < kSpectrumSamples; ++k) {
    ASSERT_GT(la.reflection[k], 0.0f);
    EXPECT_NEAR(la.reflection[k], lb.reflection[k], relTol * la.reflection[k]) << k;
    EXPECT_NEAR(la.trt[k], lb.trt[k], relTol * la.trt[k]) << k;
  }
}
}  // namespace

TEST(BarbuleOptics, FilmIndexFormsAgree) {
  auto keratin = loadBarbule("");
  // Keratin's Cauchy coefficients given explicitly: the same film.
  auto cauchy = loadBarbule(R"(<float name="film_cauchy_a" value="1.532"/><float name="film_cauchy_b" value="5890"/>)");
  expectSameLobes(*keratin, *cauchy, 0.0f);
  // Keratin's index tabulated every 10 nm: the same film to the interpolation error.
  std::string table;
  for (int l = 350; l <= 840; l += 10)
    table += std::to_string(l) + ":" + std::to_string(1.532 + 5890.0 / (l * l)) + " ";
  auto tabulated = loadBarbule(R"(<spectrum name="film_ior" value=")" + table + R"("/>)");
  ASSERT_FALSE(tabulated->parameters().filmIOR.isConstant());
  expectSameLobes(*keratin, *tabulated, 2e-3f);
  // A number, a constant spectrum and a named index of the same value agree; they differ from keratin.
  auto number = loadBarbule(R"(<float name="film_ior" value="1.56"/>)");
  auto flat = loadBarbule(R"(<spectrum name="film_ior" value="1.56"/>)");
  auto text = loadBarbule(R"(<string name="film_ior" value="1.56"/>)");
  expectSameLobes(*number, *flat, 0.0f);
  expectSameLobes(*number, *text, 0.0f);
  EXPECT_NE(lobesOf(*number).reflection[0], lobesOf(*keratin).reflection[0]);
}

TEST(BarbuleOptics, MelaninSpectrumScalesTheTRTLobeOnly) {
  auto embedded = loadBarbule("");
  auto doubled = loadBarbule(R"(<spectrum name="melanin" value="300:0.1, 900:0.1"/>)");
  auto none = loadBarbule(R"(<float name="melanin" value="0"/>)");
  BarbuleBSDF::Lobes e = lobesOf(*embedded), d = lobesOf(*doubled), z = lobesOf(*none);
  for (int k = 0; k < kSpectrumSamples; ++k) {
    EXPECT_EQ(e.reflection[k], d.reflection[k]);
    EXPECT_EQ(z.trt[k], 0.0f);
    // TRT is proportional to the melanin reflectance at each wavelength.
    EXPECT_NEAR(d.trt[k] / e.trt[k], 0.1f / melaninReflectance(kWavelengths[k]), 1e-4f) << k;
  }
}

TEST(BarbuleOptics, PresetsSetThicknessAndShapeAndCanBeOverridden) {
  auto green = loadBarbule(R"(<string name="preset" value="dove-green"/>)");
  auto purple = loadBarbule(R"(<string name="preset" value="dove-purple"/>)");
  EXPECT_EQ(green->parameters().height, 0.58f);
  EXPECT_EQ(purple->parameters().height, 0.51f);
  EXPECT_EQ(purple->parameters().mu, -0.35f);
  auto overridden = loadBarbule(R"(<string name="preset" value="dove-green"/><float name="height" value="0.62"/>)");
  EXPECT_EQ(overridden->parameters().height, 0.62f);
  EXPECT_EQ(overridden->parameters().H, 1.25f);
  for (const BarbulePreset& preset : barbulePresets()) EXPECT_GT(std::string(preset.source).size(), 20u) << preset.name;
}

TEST(BarbuleOptics, InvalidMaterialsNameTheLine) {
  auto expectError = [](const std::string& parameters, std::initializer_list<const char*> parts) {
    std::string message = loadError(parameters);
    for (const char* part : parts) EXPECT_NE(message.find(part), std::string::npos) << message << " lacks " << part;
  };
  expectError(R"(<string name="preset" value="dove-blue"/>)",
              {"barbule.xml:3", "dove-blue", "dove-green, dove-purple"});
  expectError(R"(<float name="film_ior" value="1.5"/><float name="film_cauchy_a" value="1.5"/>)",
              {"barbule.xml:3", "either"});
  expectError(R"(<spectrum name="film_ior" value="400:1.5, 600:0.9"/>)", {"barbule.xml:3", "film_ior", "denser"});
  expectError(R"(<float name="film_cauchy_a" value="0.8"/>)", {"barbule.xml:3", "film_cauchy_a", "denser"});
  expectError(R"(<spectrum name="melanin" value="400:0.5, 600:1.5"/>)", {"barbule.xml:3", "melanin", "[0, 1]"});
}

TEST(BarbuleOptics, FilmThicknessInNanometresIsWarnedAbout) {
  ::testing::internal::CaptureStderr();
  auto bsdf = loadBarbule(R"(<float name="height" value="580"/>)");
  std::string warnings = ::testing::internal::GetCapturedStderr();
  EXPECT_EQ(bsdf->parameters().height, 580.0f);
  EXPECT_NE(warnings.find("barbule.xml:3"), std::string::npos) << warnings;
  EXPECT_NE(warnings.find("did you give nm?"), std::string::npos) << warnings;
  ::testing::internal::CaptureStderr();
  loadBarbule(R"(<float name="height" value="0.58"/>)");
  EXPECT_EQ(::testing::internal::GetCapturedStderr(), "");
}
