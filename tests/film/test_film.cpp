// hdrfilm: Mitsuba's crop window renders just those pixels of the full film, each bit for bit as in
// the full render; crops that do not fit are errors naming the file, line and value.
#include <gtest/gtest.h>

#include "support/error_test_support.h"

#include <cstring>
#include <string>

#include "support/render_test_support.h"

using namespace columba;
using namespace columba::testing;

namespace {

// A sphere on a plane under an area light, seen through a 37 x 29 film with a Gaussian filter
// (whose footprint reaches past each pixel, so a crop's border pixels depend on their neighbours'
// positions) and the path integrator; `film` is extra hdrfilm parameters.
std::string sceneWithFilm(const std::string& film) {
  return R"(<scene version="3.0.0">
  <integrator type="path"><integer name="max_depth" value="3"/></integrator>
  <sensor type="perspective"><float name="fov" value="50"/>
    <transform name="to_world"><lookat origin="0, -3, 1.2" target="0, 0, 0.6" up="0, 0, 1"/></transform>
    <film type="hdrfilm"><integer name="width" value="37"/><integer name="height" value="29"/>
)" + film +
         R"(
    </film>
    <sampler type="ldsampler"><integer name="sample_count" value="4"/></sampler></sensor>
  <shape type="sphere"><point name="center" x="0" y="0" z="0.5"/><float name="radius" value="0.5"/>
    <bsdf type="roughplastic"><rgb name="diffuse_reflectance" value="0.6, 0.2, 0.1"/></bsdf></shape>
  <shape type="rectangle"><transform name="to_world"><scale value="1.5"/></transform><bsdf type="diffuse"/></shape>
  <shape type="rectangle"><transform name="to_world"><scale value="0.4"/><rotate x="1" angle="180"/><translate z="2.5"/></transform>
    <emitter type="area"><spectrum name="radiance" value="8"/></emitter></shape>
</scene>)";
}

std::string loadError(const std::string& xml) {
  try {
    loadSceneString(xml, "film.xml", ".", {}, builtinPlugins());
  } catch (const InputError& e) {
    return e.what();
  }
  return "";
}

}  // namespace

TEST(FilmCrop, RendersThatWindowOfTheFullFilmBitForBit) {
  RenderSettings settings;
  settings.seed = 3;
  const Image full = renderSceneString(sceneWithFilm(""), settings);
  ASSERT_EQ(full.width, 37);
  ASSERT_EQ(full.height, 29);
  const Image crop = renderSceneString(sceneWithFilm(R"(<integer name="crop_offset_x" value="5"/>
      <integer name="crop_offset_y" value="7"/><integer name="crop_width" value="20"/>
      <integer name="crop_height" value="11"/>)"),
                                       settings);
  ASSERT_EQ(crop.width, 20);
  ASSERT_EQ(crop.height, 11);
  int lit = 0;
  for (int y = 0; y < crop.height; ++y)
    for (int x = 0; x < crop.width; ++x) {
      EXPECT_EQ(std::memcmp(crop.pixel(x, y), full.pixel(x + 5, y + 7), 3 * sizeof(float)), 0)
          << "pixel (" << x << ", " << y << ") of the crop";
      lit += crop.pixel(x, y)[0] > 0.0f;
    }
  EXPECT_GT(lit, crop.width * crop.height / 2);  // the comparison is of an image, not of black
}

TEST(FilmCrop, SizeDefaultsToTheWholeFilmWhateverTheOffset) {
  // As in Mitsuba, crop_width and crop_height default to the film's size, so an offset alone
  // makes a window that does not fit.
  expectContains(loadError(sceneWithFilm(R"(<integer name="crop_offset_x" value="5"/>)")),
                 {"film.xml:", "crop_width", "1..32", "not 37"});
  const Image crop = renderSceneString(
      sceneWithFilm(R"(<integer name="crop_offset_y" value="20"/><integer name="crop_height" value="9"/>)"));
  EXPECT_EQ(crop.width, 37);
  EXPECT_EQ(crop.height, 9);
}

TEST(FilmCrop, WindowsOutsideTheFilmAreErrorsNamingFileLineAndValue) {
  expectContains(loadError(sceneWithFilm(R"(<integer name="crop_offset_x" value="-1"/>)")),
                 {"film.xml:6", "crop_offset_x", "not -1"});
  expectContains(loadError(sceneWithFilm(R"(<integer name="crop_offset_y" value="29"/>)")),
                 {"film.xml:6", "crop_offset_y", "0..28", "not 29"});
  expectContains(loadError(sceneWithFilm(R"(<integer name="crop_width" value="0"/>)")),
                 {"film.xml:6", "crop_width", "not 0"});
  expectContains(loadError(sceneWithFilm(R"(<integer name="crop_height" value="30"/>)")),
                 {"film.xml:6", "crop_height", "1..29", "not 30"});
  expectContains(
      loadError(sceneWithFilm(R"(<integer name="crop_offset_y" value="10"/><integer name="crop_height" value="20"/>)")),
      {"film.xml:6", "crop_height", "1..19", "not 20"});
}

TEST(FilmFormats, PixelFormatChoosesTheColourOfTheEXRFile) {
  const std::string crop = R"(<integer name="crop_width" value="2"/><integer name="crop_height" value="2"/>)";
  EXPECT_EQ(renderSceneString(sceneWithFilm(crop)).exrColour, EXRColour::RGB);
  EXPECT_EQ(renderSceneString(sceneWithFilm(crop + R"(<string name="pixel_format" value="luminance"/>)")).exrColour,
            EXRColour::Luminance);
  EXPECT_EQ(renderSceneString(sceneWithFilm(crop + R"(<string name="pixel_format" value="xyz"/>
      <string name="file_format" value="exr"/>)"))
                .exrColour,
            EXRColour::XYZ);
  EXPECT_EQ(renderSceneString(sceneWithFilm(crop + R"(<string name="file_format" value="openexr"/>)")).exrColour,
            EXRColour::RGB);
}

TEST(FilmFormats, AlphaFormatsAreWrittenWithoutAlphaAndSaySo) {
  const std::string crop = R"(<integer name="crop_width" value="2"/><integer name="crop_height" value="2"/>)";
  struct Case {
    const char* format;
    EXRColour colour;
    const char* without;
  };
  for (const Case& c :
       {Case{"rgba", EXRColour::RGB, "'rgb'"}, Case{"luminance_alpha", EXRColour::Luminance, "'luminance'"},
        Case{"xyza", EXRColour::XYZ, "'xyz'"}}) {
    ::testing::internal::CaptureStderr();
    Image image = renderSceneString(sceneWithFilm(crop + "<string name=\"pixel_format\" value=\"" + c.format + "\"/>"));
    std::string warning = ::testing::internal::GetCapturedStderr();
    EXPECT_EQ(image.exrColour, c.colour) << c.format;
    EXPECT_NE(warning.find("no alpha channel"), std::string::npos) << warning;
    EXPECT_NE(warning.find(c.without), std::string::npos) << warning;
  }
}

TEST(FilmFormats, FormatsColumbaCannotWriteAreErrorsNamingFileLineAndValue) {
  expectContains(loadError(sceneWithFilm(R"(<string name="pixel_format" value="spectrum"/>)")),
                 {"film.xml:6", "rgb, luminance or xyz", "'spectrum'"});
  expectContains(loadError(sceneWithFilm(R"(<string name="file_format" value="rgbe"/>)")),
                 {"film.xml:6", "file_format", "'rgbe'"});
}

TEST(FilmBorder, SampleBorderFalseIsTheDefaultAndTrueWarnsNamingTheLine) {
  RenderSettings settings;
  settings.seed = 5;
  const std::string crop = R"(<integer name="crop_width" value="6"/><integer name="crop_height" value="5"/>)";
  const Image plain = renderSceneString(sceneWithFilm(crop), settings);
  ::testing::internal::CaptureStderr();
  const Image off =
      renderSceneString(sceneWithFilm(crop + R"(<boolean name="sample_border" value="false"/>)"), settings);
  EXPECT_EQ(::testing::internal::GetCapturedStderr(), "");
  EXPECT_TRUE(samePixels(plain, off));
  ::testing::internal::CaptureStderr();
  const Image on = renderSceneString(sceneWithFilm(crop + R"(<boolean name="sample_border" value="true"/>)"), settings);
  const std::string warning = ::testing::internal::GetCapturedStderr();
  expectContains(warning, {"<test scene>:6", "sample_border true is not supported"});
  EXPECT_TRUE(samePixels(plain, on));
}
