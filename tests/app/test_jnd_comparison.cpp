// columba compare --jnd: the colour distance a bird sees between two renders' cone catches, pixel by
// pixel and between regions, against the receptor-noise-limited distance of the same catches; and a
// human's, CIEDE2000 between RGB renders, against its closed form for greys.
#include <gtest/gtest.h>

#include <fmt/format.h>

#include <cmath>
#include <filesystem>

#include "io/image.h"
#include "support/cli_test_support.h"
#include "support/temp_dir_test.h"
#include "vision/colour_distance.h"

namespace fs = std::filesystem;
using namespace columba;
using columba::testing::CommandResult;
using columba::testing::run;

namespace {
class JndComparison : public columba::testing::TempDirTest {
 protected:
  // A 2 x 1 image of the blue tit's four cones, as a render with that observer records it.
  std::string coneImage(const std::string& name, std::vector<float> catches) {
    Image image(2, 1);
    image.cones.names = {"UVS", "SWS", "MWS", "LWS"};
    image.cones.values = std::move(catches);
    const std::string path = (dir_ / name).string();
    writeEXR(path, image, {{"Observer", "bluetit: quantum catches of UVS, SWS, MWS, LWS"}});
    return path;
  }
};
}  // namespace

TEST_F(JndComparison, PixelsAndRegionsAreAsFarApartAsTheirCatchesAre) {
  // Pixel 0 differs only in the LWS cone (e times more), pixel 1 not at all.
  const std::string a = coneImage("a.exr", {1, 1, 1, 1, 0.2f, 0.4f, 0.6f, 0.8f});
  const std::string b = coneImage("b.exr", {1, 1, 1, float(std::exp(1.0)), 0.2f, 0.4f, 0.6f, 0.8f});
  const Observer o = namedObserver("bluetit");
  const double expected = chromaticDistance(o, {{1, 1, 1, 1}, {}}, {{1, 1, 1, std::exp(1.0)}, {}});
  ASSERT_GT(expected, 1.0);
  CommandResult r = run("compare --jnd " + a + " " + b + " -o " + (dir_ / "maps/dS.exr").string());
  ASSERT_EQ(r.status, 0) << r.output;
  EXPECT_NE(r.output.find(fmt::format("over 2 of 2 pixels")), std::string::npos) << r.output;
  EXPECT_NE(r.output.find(fmt::format("largest {:.3f} JND", expected)), std::string::npos) << r.output;
  const Image map = readEXR((dir_ / "maps/dS.exr").string());
  EXPECT_NEAR(map.rgb[0], expected, 1e-4 * expected);
  EXPECT_EQ(map.rgb[3], 0.0f);
  EXPECT_TRUE(fs::exists(dir_ / "maps/dS.png"));
  // Regions: A's pixel 1 against B's pixel 0, from their (here single-pixel) mean catches.
  const double across = chromaticDistance(o, {{0.2, 0.4, 0.6, 0.8}, {}}, {{1, 1, 1, std::exp(1.0)}, {}});
  r = run("compare --jnd " + a + " " + b + " --region 1,0,2,1 --region-b 0,0,1,1");
  ASSERT_EQ(r.status, 0) << r.output;
  EXPECT_NE(r.output.find(fmt::format("dS = {:.3f} JND", across)), std::string::npos) << r.output;
}

TEST_F(JndComparison, ImagesWithoutConesAndBadRegionsAreRefused) {
  const std::string a = coneImage("a.exr", {1, 1, 1, 1, 1, 1, 1, 1});
  Image rgb(2, 1);
  const std::string plain = (dir_ / "rgb.exr").string();
  writeEXR(plain, rgb);
  CommandResult r = run("compare --jnd " + a + " " + plain);
  EXPECT_NE(r.status, 0);
  EXPECT_NE(r.output.find("has no UVS channel"), std::string::npos) << r.output;
  r = run("compare --jnd " + a + " " + a + " --region 0,0,3,1");
  EXPECT_NE(r.status, 0);
  EXPECT_NE(r.output.find("--region [0, 3) x [0, 1) does not lie inside '" + a + "', which is 2 x 1 pixels"),
            std::string::npos)
      << r.output;
  r = run("compare --jnd " + a + " " + a + " --region 1,0,1,1");
  EXPECT_NE(r.status, 0);
  EXPECT_NE(r.output.find("--region '1,0,1,1' is not a non-empty rectangle of pixels"), std::string::npos) << r.output;
  r = run("compare --jnd " + a + " " + a + " --observer budgie");
  EXPECT_NE(r.status, 0);
  EXPECT_NE(r.output.find("unknown observer 'budgie'"), std::string::npos) << r.output;
  r = run("compare " + a + " " + a + " --region 0,0,1,1");
  EXPECT_NE(r.status, 0);
  EXPECT_NE(r.output.find("add --jnd"), std::string::npos) << r.output;
}

// Greys differ in lightness only: L* 50 and 60 (Y = ((L* + 16) / 116)^3 of the white RGB 1) are
// dE*ab = 10 apart, and CIEDE2000 divides by S_L = 1 + 0.015 (55 - 50)^2 / sqrt(20 + (55 - 50)^2).
TEST_F(JndComparison, RendersWithoutConesAreComparedAsAHumanSeesThem) {
  auto grey = [&](const std::string& name, float lightness) {
    const float y = std::pow((lightness + 16.0f) / 116.0f, 3.0f);
    Image image(2, 1);
    for (float& v : image.rgb) v = y;
    const std::string path = (dir_ / name).string();
    writeEXR(path, image);
    return path;
  };
  const std::string a = grey("a.exr", 50.0f), b = grey("b.exr", 60.0f);
  const double sl = 1.0 + 0.015 * 25.0 / std::sqrt(45.0);
  CommandResult r = run("compare --jnd " + a + " " + b + " -o " + (dir_ / "dE.exr").string());
  ASSERT_EQ(r.status, 0) << r.output;
  EXPECT_NE(r.output.find("cie1931 observer"), std::string::npos) << r.output;
  EXPECT_NE(r.output.find(fmt::format("largest {:.3f}", 10.0 / sl)), std::string::npos) << r.output;
  EXPECT_NEAR(readEXR((dir_ / "dE.exr").string()).rgb[0], 10.0 / sl, 1e-3);
  r = run("compare --jnd " + a + " " + b + " --region 0,0,2,1 --observer cie1931");
  ASSERT_EQ(r.status, 0) << r.output;
  EXPECT_NE(r.output.find(fmt::format("dE2000 = {:.3f}, dE*ab = 10.000 (about 4.35 JND", 10.0 / sl)), std::string::npos)
      << r.output;
}

// A region given for A alone is read from B too: it must lie inside B, however much larger A is
// (a 64 x 64 A against a 2 x 1 B read past B's pixels, and a 2048-square one crashed).
TEST_F(JndComparison, ARegionMustLieInsideEachImageItIsReadFrom) {
  const std::string small = coneImage("small.exr", {1, 1, 1, 1, 1, 1, 1, 1});
  Image image(64, 64);
  image.cones.names = {"UVS", "SWS", "MWS", "LWS"};
  image.cones.values.assign(64 * 64 * 4, 1.0f);
  const std::string large = (dir_ / "large.exr").string();
  writeEXR(large, image, {{"Observer", "bluetit: quantum catches of UVS, SWS, MWS, LWS"}});
  for (const char* observer : {"", " --observer cie1931"}) {
    CommandResult r = run("compare --jnd " + large + " " + small + " --region 0,0,64,64" + observer);
    EXPECT_NE(r.status, 0) << r.output;
    EXPECT_NE(r.output.find("--region (read from both images without --region-b) [0, 64) x [0, 64) does not lie "
                            "inside '" +
                            small + "', which is 2 x 1 pixels"),
              std::string::npos)
        << r.output;
    r = run("compare --jnd " + large + " " + small + " --region 0,0,2,2 --region-b 0,0,2,2" + observer);
    EXPECT_NE(r.status, 0) << r.output;
    EXPECT_NE(r.output.find("--region-b [0, 2) x [0, 2) does not lie inside '" + small + "'"), std::string::npos)
        << r.output;
    r = run("compare --jnd " + large + " " + small + " --region 0,0,2,1" + observer);
    EXPECT_EQ(r.status, 0) << r.output;
  }
}

// The map of distances never replaces an image the comparison reads, by either of its names.
TEST_F(JndComparison, TheMapIsNotWrittenOverAnInput) {
  const std::string a = coneImage("a.exr", {1, 1, 1, 1, 1, 1, 1, 1});
  const std::string b = coneImage("b.exr", {1, 1, 1, 2, 1, 1, 1, 1});
  const auto before = fs::file_size(a);
  for (const std::string& output : {a, b, (dir_ / "sub/../a.exr").string()}) {
    const CommandResult r = run("compare --jnd " + a + " " + b + " -o " + output);
    EXPECT_NE(r.status, 0) << r.output;
    EXPECT_NE(r.output.find("which the comparison reads"), std::string::npos) << r.output;
  }
  // The PNG beside the map is the input: x.png as A (an EXR named .png is still refused as A's file).
  const std::string png = (dir_ / "a.png").string();
  fs::copy_file(a, png);
  const CommandResult r = run("compare --jnd " + png + " " + b + " -o " + (dir_ / "a.exr").string());
  EXPECT_NE(r.status, 0) << r.output;
  EXPECT_NE(r.output.find("cannot write the map of distances to '" + png + "'"), std::string::npos) << r.output;
  EXPECT_EQ(fs::file_size(a), before);
  EXPECT_EQ(readEXR(a).cones.values[3], 1.0f);
}

// Catches are compared as the observer they were rendered for: --observer naming another (avg.v's
// noise on the blue tit's catches printed "avg.v observer: dS = ...") is refused, naming both, and
// so are two images rendered for different observers.
TEST_F(JndComparison, CatchesAreNotRelabelledAsAnotherObserver) {
  const std::string a = coneImage("a.exr", {1, 1, 1, 1, 1, 1, 1, 1});
  const std::string b = coneImage("b.exr", {1, 1, 1, 2, 1, 1, 1, 1});
  CommandResult r = run("compare --jnd " + a + " " + b + " --observer avg.v");
  EXPECT_NE(r.status, 0) << r.output;
  EXPECT_NE(r.output.find("'" + a +
                          "' records the catches of the bluetit observer (its Observer attribute), not "
                          "of --observer avg.v"),
            std::string::npos)
      << r.output;
  Image image(2, 1);
  image.cones.names = {"UVS", "SWS", "MWS", "LWS"};
  image.cones.values.assign(8, 1.0f);
  const std::string violet = (dir_ / "violet.exr").string();
  writeEXR(violet, image, {{"Observer", "avg.v: quantum catches of UVS, SWS, MWS, LWS"}});
  r = run("compare --jnd " + a + " " + violet);
  EXPECT_NE(r.status, 0) << r.output;
  EXPECT_NE(r.output.find("'" + violet + "' records the catches of the avg.v observer"), std::string::npos) << r.output;
  // The observer the images record, named or not, and the human observer's RGB, are compared.
  EXPECT_EQ(run("compare --jnd " + a + " " + b + " --observer bluetit").status, 0);
  EXPECT_EQ(run("compare --jnd " + a + " " + violet + " --observer cie1931").status, 0);
}
