// Which value of a barbule parameter a feather renders with: the feather's own per-vertex values
// win over the BSDF's constants (docs/feather-ply.md, "Which value wins"), and a constant that
// therefore has no effect is warned of, once, naming its line; a texture wins over the feather's
// values, and a mesh_attribute texture reads them.
#include <gtest/gtest.h>

#include <string>
#include "feather/feather_generator.h"
#include "support/feather_test_util.h"
#include "support/render_test_support.h"
#include "support/temp_dir_test.h"

using namespace columba;
using columba::testing::samePixels;

namespace {

class FeatherParameterPrecedenceTest : public columba::testing::TempDirTest {
 protected:
  // A generated single feather, green (cortex 0.60 um).
  std::string generatedFeather() {
    std::string file = (dir_ / "feather.ply").string();
    generateFeatherPly(FeatherGenerationOptions(), file);
    return file;
  }

  // Eight straight barbs side by side along y, cortex `height` (um) at every vertex.
  std::string straightBarbs(float height) {
    return columba::test::writeStraightBarbs((dir_ / "barbs.ply").string(), height);
  }

  // A scene of `feathers` feathers read from `file`, all with the BSDF whose parameters are
  // `bsdf`, on the lines after the scene's first.
  static std::string scene(const std::string& file, const std::string& bsdf, int feathers = 1) {
    std::string xml = R"(<scene version="3.0.0">
<integrator type="direct"/>
<sensor type="perspective"><float name="fov" value="40"/>
  <transform name="to_world"><lookat origin="0, 0, 1.2" target="0, 0, 0" up="0, 1, 0"/></transform>
  <film type="hdrfilm"><integer name="width" value="12"/><integer name="height" value="12"/></film>
  <sampler type="independent"><integer name="sample_count" value="4"/></sampler></sensor>
<emitter type="directional"><vector name="direction" x="0.2" y="0.3" z="-1"/><spectrum name="irradiance" value="3"/></emitter>
<bsdf type="barbulebsdf" id="barbules">
)" + bsdf + "\n</bsdf>\n";
    for (int i = 0; i < feathers; ++i)
      xml +=
          "<shape type=\"feather\"><string name=\"filename\" value=\"" + file + "\"/><ref id=\"barbules\"/></shape>\n";
    return xml + "</scene>";
  }

  // What loading `xml` prints on stderr.
  std::string loadingWarnings(const std::string& xml) {
    ::testing::internal::CaptureStderr();
    ParsedScene parsed = loadSceneString(xml, "scene.xml", dir_.string(), {}, builtinPlugins());
    return ::testing::internal::GetCapturedStderr();
  }

  static int occurrences(const std::string& text, const std::string& part) {
    int n = 0;
    for (size_t at = text.find(part); at != std::string::npos; at = text.find(part, at + 1)) ++n;
    return n;
  }
};

// The BSDF's parameters start on line 9 of scene().
constexpr const char* kFirstBsdfLine = "scene.xml:9: ";

TEST_F(FeatherParameterPrecedenceTest, AHeightTheFileOverridesWarnsOnceNamingItsLine) {
  const std::string feather = generatedFeather();
  const std::string warnings =
      loadingWarnings(scene(feather, R"(<float name="height" value="0.45"/>)", /*feathers=*/2));
  EXPECT_EQ(occurrences(warnings, "warning:"), 1) << warnings;
  EXPECT_NE(warnings.find(kFirstBsdfLine), std::string::npos) << warnings;
  EXPECT_NE(warnings.find("barbulebsdf, parameter 'height': no effect on the feather '" + feather + "'"),
            std::string::npos)
      << warnings;
}

TEST_F(FeatherParameterPrecedenceTest, APresetsOverriddenParametersAreNamedInOneWarning) {
  const std::string warnings =
      loadingWarnings(scene(generatedFeather(), R"(<string name="preset" value="dove-purple"/>)"));
  EXPECT_EQ(occurrences(warnings, "warning:"), 1) << warnings;
  EXPECT_NE(warnings.find("parameters 'H', 'mu', 'height' (from preset 'dove-purple'): no effect"), std::string::npos)
      << warnings;
}

TEST_F(FeatherParameterPrecedenceTest, NoWarningForParametersThatTakeEffect) {
  // b and phi_0 are never per vertex.
  EXPECT_EQ(
      loadingWarnings(scene(generatedFeather(), R"(<float name="b" value="0.3"/><float name="phi_0" value="-0.3"/>)")),
      "");
  // A file thickness of 0 leaves the BSDF's own height: it is not warned of, mu (given by the file) is.
  const std::string warnings = loadingWarnings(
      scene(straightBarbs(0.0f), "<float name=\"height\" value=\"0.45\"/>\n<float name=\"mu\" value=\"-0.3\"/>"));
  EXPECT_EQ(occurrences(warnings, "warning:"), 1) << warnings;
  EXPECT_NE(warnings.find("scene.xml:10: barbulebsdf, parameter 'mu'"), std::string::npos) << warnings;
}

TEST_F(FeatherParameterPrecedenceTest, AWarnedValueHasNoEffectAndAnUnwarnedOneDoes) {
  using columba::testing::renderSceneString;
  auto render = [&](const std::string& file, const char* height) {
    ::testing::internal::CaptureStderr();
    Image image = renderSceneString(scene(file, std::string("<float name=\"height\" value=\"") + height + "\"/>"));
    return std::make_pair(image, ::testing::internal::GetCapturedStderr());
  };
  const std::string generated = generatedFeather();
  auto [thin, thinWarnings] = render(generated, "0.45");
  auto [thick, thickWarnings] = render(generated, "0.70");
  EXPECT_NE(thinWarnings.find("parameter 'height'"), std::string::npos);
  EXPECT_TRUE(samePixels(thin, thick));

  const std::string unset = straightBarbs(0.0f);
  auto [thinOwn, thinOwnWarnings] = render(unset, "0.45");
  auto [thickOwn, thickOwnWarnings] = render(unset, "0.70");
  EXPECT_EQ(thinOwnWarnings.find("warning:"), std::string::npos) << thinOwnWarnings;
  EXPECT_FALSE(samePixels(thinOwn, thickOwn));
}

// A render of `file` with the BSDF parameters `bsdf`, and what it printed.
std::pair<Image, std::string> renderWithWarnings(const std::string& xml) {
  ::testing::internal::CaptureStderr();
  Image image = columba::testing::renderSceneString(xml);
  return {image, ::testing::internal::GetCapturedStderr()};
}

// The share of green in the image's mean colour: what a change of film colour moves.
float greenShare(const Image& image) {
  Vec3 c = columba::testing::meanColour(image, 0, 0, image.width, image.height);
  return c.y / (c.x + c.y + c.z);
}

TEST_F(FeatherParameterPrecedenceTest, AThicknessTextureChangesTheFeathersHue) {
  const std::string feather = generatedFeather();
  auto thickness = [&](const char* um) {
    return scene(feather, std::string(R"(<texture type="rawconstant" name="height"><float name="value" value=")") + um +
                              "\"/></texture>");
  };
  auto [thin, thinWarnings] = renderWithWarnings(thickness("0.45"));
  auto [thick, thickWarnings] = renderWithWarnings(thickness("0.70"));
  EXPECT_EQ(thinWarnings + thickWarnings, "");
  EXPECT_GT(std::abs(greenShare(thin) - greenShare(thick)), 0.02f) << greenShare(thin) << " " << greenShare(thick);
  // A tilt texture takes effect too, where the constant does not.
  auto [tilted, tiltedWarnings] = renderWithWarnings(
      scene(feather, R"(<texture type="rawconstant" name="mu"><float name="value" value="-0.1"/></texture>)"));
  EXPECT_FALSE(samePixels(tilted, renderWithWarnings(scene(feather, "")).first));
}

TEST_F(FeatherParameterPrecedenceTest, AMeshAttributeTextureReadsTheFilesThicknessScaled) {
  auto fileThickness = [&](const std::string& file, const char* scale) {
    return scene(
        file,
        std::string(R"(<texture type="mesh_attribute" name="height"><string name="name" value="vertex_height"/>)") +
            "<float name=\"scale\" value=\"" + scale + "\"/></texture>");
  };
  // Scale 1 is what the feather renders without the texture, bit for bit.
  const std::string generated = generatedFeather();
  auto [asFile, warnings] = renderWithWarnings(fileThickness(generated, "1"));
  EXPECT_EQ(warnings, "");
  EXPECT_TRUE(samePixels(asFile, renderWithWarnings(scene(generated, "")).first));
  // Half the file's 0.6 um is a file of 0.3 um (both exact in floats).
  const Image halved = renderWithWarnings(fileThickness(straightBarbs(0.6f), "0.5")).first;
  const Image thinFile = renderWithWarnings(scene(straightBarbs(0.3f), "")).first;
  EXPECT_TRUE(samePixels(halved, thinFile));
  EXPECT_FALSE(samePixels(halved, renderWithWarnings(scene(straightBarbs(0.6f), "")).first));
}

}  // namespace
