// Renders seen by a bird: a grey plate under an equal-quantum light catches the same in every cone
// (closed form albedo E / pi), a white plate under D65 catches 1 adapted to D65, and a render's cone
// catches are those of the spectrum the same render records in its bins. The human observer's
// render is the same bit for bit whatever the film says of adaptation.
#include <gtest/gtest.h>

#include <string>
#include <vector>

#include "support/error_test_support.h"
#include "support/render_test_support.h"
#include "vision/observer_response.h"

using namespace columba;
using namespace columba::testing;

namespace {
// A diffuse plate filling an 8 x 8 view, lit straight from above by a directional light whose
// irradiance element is `irradiance`; `film` is extra hdrfilm parameters.
std::string plate(const std::string& irradiance, const std::string& reflectance, const std::string& film,
                  int spp = 256) {
  return R"(<scene version="3.0.0"><integrator type="direct"/>
    <sensor type="perspective"><float name="fov" value="1"/>
      <transform name="to_world"><lookat origin="0, 0, 5" target="0, 0, 0" up="0, 1, 0"/></transform>
      <film type="hdrfilm"><integer name="width" value="8"/><integer name="height" value="8"/><rfilter type="box"/>
        )" +
         film +
         R"(</film>
      <sampler type="ldsampler"><integer name="sample_count" value=")" +
         std::to_string(spp) + R"("/></sampler></sensor>
    <shape type="rectangle"><transform name="to_world"><scale value="10"/></transform>
      <bsdf type="diffuse">)" +
         reflectance + R"(</bsdf></shape>
    <emitter type="directional"><vector name="direction" x="0" y="0" z="-1"/>)" +
         irradiance + R"(</emitter>
    </scene>)";
}

std::vector<double> meanCatches(const Image& image) {
  const size_t k = image.cones.count();
  std::vector<double> mean(k, 0.0);
  const size_t pixels = size_t(image.width) * size_t(image.height);
  for (size_t p = 0; p < pixels; ++p)
    for (size_t c = 0; c < k; ++c) mean[c] += image.cones.values[p * k + c] / double(pixels);
  return mean;
}
}  // namespace

TEST(ObserverRender, AGreyPlateUnderAnEqualQuantumLightCatchesAlikeInEveryCone) {
  const float albedo = 0.4f;
  const Image image = renderSceneString(
      plate(R"(<spectrum name="irradiance" value="300:3, 830:3"/>)", "<float name=\"reflectance\" value=\"0.4\"/>",
            R"(<string name="observer" value="bluetit"/><string name="adaptation" value="none"/>)"));
  ASSERT_EQ(image.cones.names, (std::vector<std::string>{"UVS", "SWS", "MWS", "LWS"}));
  const std::vector<double> q = meanCatches(image);
  const double expected = albedo * 3.0 / kPi;
  for (size_t c = 0; c < q.size(); ++c) EXPECT_NEAR(q[c], expected, 0.01 * expected) << image.cones.names[c];
}

TEST(ObserverRender, AWhitePlateUnderD65CatchesItsIrradianceAdaptedToD65) {
  // A single value is D65 of that luminance, Columba's (and Mitsuba's) white: RGB (1, 1, 1) E / pi,
  // and every cone adapted to D65 catches E / pi.
  const Image image =
      renderSceneString(plate(R"(<float name="irradiance" value="3"/>)", "<float name=\"reflectance\" value=\"1\"/>",
                              R"(<string name="observer" value="bluetit"/>)"));
  const std::vector<double> q = meanCatches(image);
  ASSERT_EQ(q.size(), 4u);
  for (size_t c = 0; c < q.size(); ++c) EXPECT_NEAR(q[c], 3.0 / kPi, 0.01 * 3.0 / kPi) << image.cones.names[c];
  const Vec3 rgb = meanColour(image, 0, 0, 8, 8);
  for (int c = 0; c < 3; ++c) EXPECT_NEAR(rgb[c], 3.0 / kPi, 0.01 * 3.0 / kPi) << c;
  // The PNG's false colour of a white every cone catches alike is that grey.
  const Image shown = falseColour(image);
  for (int c = 0; c < 3; ++c) EXPECT_NEAR(shown.rgb[c], 3.0 / kPi, 0.03 * 3.0 / kPi) << c;
}

TEST(ObserverRender, ConeCatchesAreThoseOfTheSpectrumTheRenderRecords) {
  // A coloured plate under a light that rises through the ultraviolet and falls into the red: the
  // catches the film records against the catches of the spectral bins (10 nm over 300-830 nm) of the
  // same render, integrated against the sensitivities bin by bin.
  RenderSettings settings;
  settings.spectralBins = 53;
  settings.spectralMin = 300.0f;
  settings.spectralMax = 830.0f;
  const Image image = renderSceneString(
      plate(R"(<spectrum name="irradiance" value="300:0.5, 420:2, 600:1.5, 830:0.5"/>)",
            R"(<rgb name="reflectance" value="0.2, 0.6, 0.3"/>)",
            R"(<string name="observer" value="bluetit"/><string name="adaptation" value="none"/>)", 1024),
      settings);
  const ObserverResponse response(namedObserver("bluetit"), Adaptation::None);
  const std::vector<double> q = meanCatches(image);
  ASSERT_EQ(q.size(), 4u);
  const size_t bins = image.spectral.count(), pixels = 64;
  for (size_t c = 0; c < q.size(); ++c) {
    double fromBins = 0.0;
    for (size_t b = 0; b < bins; ++b) {
      double binMean = 0.0;
      for (size_t p = 0; p < pixels; ++p) binMean += image.spectral.values[p * bins + b] / double(pixels);
      double sensitivity = 0.0;  // the integral of S over the bin
      for (int j = 0; j < 100; ++j)
        sensitivity += response.sensitivity(c, 300.0f + 10.0f * (float(b) + (float(j) + 0.5f) / 100.0f)) * 0.1;
      fromBins += binMean * sensitivity;
    }
    EXPECT_NEAR(q[c], fromBins, 0.02 * fromBins) << image.cones.names[c];
  }
}

TEST(ObserverRender, TheHumanObserversRenderIsUnchangedAndNamesAreChecked) {
  const std::string light = R"(<float name="irradiance" value="3"/>)";
  const std::string grey = "<float name=\"reflectance\" value=\"0.5\"/>";
  const Image plain = renderSceneString(plate(light, grey, ""));
  ::testing::internal::CaptureStderr();
  const Image human = renderSceneString(
      plate(light, grey, R"(<string name="observer" value="cie1931"/><string name="adaptation" value="none"/>)"));
  const std::string warning = ::testing::internal::GetCapturedStderr();
  EXPECT_TRUE(samePixels(plain, human));
  EXPECT_EQ(human.cones.count(), 0u);
  expectContains(warning, {"adaptation 'none' has no effect", "cie1931"});
  auto loadError = [](const std::string& xml) {
    try {
      loadSceneString(xml, "bird.xml", ".", {}, builtinPlugins());
    } catch (const InputError& e) {
      return std::string(e.what());
    }
    return std::string();
  };
  expectContains(loadError(plate(light, grey, R"(<string name="observer" value="budgie"/>)")),
                 {"bird.xml:5", "unknown observer 'budgie'", "bluetit", "cie1931"});
  expectContains(
      loadError(
          plate(light, grey, R"(<string name="observer" value="bluetit"/><string name="adaptation" value="D50"/>)")),
      {"bird.xml:5", "unknown adaptation 'D50'", "d65, none"});
}
