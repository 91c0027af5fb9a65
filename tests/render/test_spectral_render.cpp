// Spectral renders: radiance per wavelength bin beside RGB, checked on a diffuse plane under a light
// of known spectrum (closed form: L(lambda) = albedo E(lambda) / pi).
#include <gtest/gtest.h>

#include <cstdio>
#include "support/render_test_support.h"

using namespace columba;
using namespace columba::testing;

TEST(SpectralRender, DiffusePlaneReturnsTheLightsSpectrumInItsBins) {
  // A tabulated irradiance (taken as given, not times D65), linear in wavelength, so each bin's
  // mean is its value at the bin's centre: E = 1 + (lambda - 400) / 300 * 2.
  const float albedo = 0.6f;
  std::string xml = plateUnderDirectionalLight(R"(<spectrum name="irradiance" value="400:1, 700:3"/>)", albedo);
  RenderSettings settings;
  settings.spectralBins = 6;
  settings.spectralMin = 400.0f;
  settings.spectralMax = 700.0f;
  Image image = renderSceneString(xml, settings);
  ASSERT_EQ(image.spectral.count(), 6u);
  ASSERT_EQ(image.spectral.values.size(), size_t(8 * 8 * 6));
  for (int b = 0; b < 6; ++b) {
    float centre = image.spectral.centres[b];
    EXPECT_FLOAT_EQ(centre, 425.0f + 50.0f * b);
    double mean = 0.0;
    for (int p = 0; p < 64; ++p) mean += image.spectral.values[size_t(p) * 6 + b] / 64.0;
    float expected = albedo * (1.0f + (centre - 400.0f) / 150.0f) / kPi;
    std::printf("bin %d (%.0f nm): %.5f, closed form %.5f\n", b, centre, mean, expected);
    EXPECT_NEAR(mean, expected, 0.02 * expected) << centre;
  }
  // Without bins, wavelengths are drawn in proportion to the RGB matching functions rather than
  // by the visible density: another sampling of the same image, equal in the mean.
  Image rgbOnly = renderSceneString(xml);
  EXPECT_EQ(rgbOnly.spectral.count(), 0u);
  EXPECT_NE(image.rgb, rgbOnly.rgb);
  for (int c = 0; c < 3; ++c) {
    double withBins = 0.0, without = 0.0;
    for (int p = 0; p < 64; ++p) {
      withBins += image.rgb[size_t(p) * 3 + c] / 64.0;
      without += rgbOnly.rgb[size_t(p) * 3 + c] / 64.0;
    }
    EXPECT_NEAR(without, withBins, 0.005 * withBins) << "channel " << c;
  }
}

// Without a range the bins cover what the film renders (an RGB film: 360-830 nm), so none is empty;
// a range beyond it is refused, naming it (its bins would read dark where nothing was drawn).
TEST(SpectralRender, TheBinsCoverWhatTheFilmRendersAndNoMore) {
  const std::string xml =
      plateUnderDirectionalLight(R"(<spectrum name="irradiance" value="360:1, 830:1"/>)", 0.6f, 1024);
  RenderSettings settings;
  settings.spectralBins = 5;
  const Image image = renderSceneString(xml, settings);
  ASSERT_EQ(image.spectral.count(), 5u);
  EXPECT_FLOAT_EQ(image.spectral.centres.front(), 360.0f + 47.0f);
  EXPECT_FLOAT_EQ(image.spectral.centres.back(), 830.0f - 47.0f);
  for (size_t b = 0; b < 5; ++b) {
    double mean = 0.0;
    for (size_t p = 0; p < 64; ++p) mean += image.spectral.values[p * 5 + b] / 64.0;
    EXPECT_NEAR(mean, 0.6 / kPi, 0.03 * 0.6 / kPi) << image.spectral.centres[b];
  }
  settings.spectralMin = 300.0f;
  settings.spectralMax = 700.0f;
  try {
    renderSceneString(xml, settings);
    FAIL() << "no error";
  } catch (const std::invalid_argument& e) {
    EXPECT_NE(std::string(e.what()).find("the spectral range 300-700 nm is not a range within the 360-830 nm this "
                                         "film renders"),
              std::string::npos)
        << e.what();
  }
}
