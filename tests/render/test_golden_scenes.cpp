// Golden statistics of every scene Columba ships (scenes/ and examples/): each is rendered small,
// and its mean colour and a 4 x 4 grid of mean luminances are compared with tests/golden/scenes.json.
// These are regression values, not independent answers (those are the closed-form and
// cross-estimator tests); what they catch is a change of the picture nobody meant. The stored
// values are means over eight seeds, with the standard deviation a single render shows: a
// render passes when every value lies within kSigmas of them (plus a small floor), so a change
// of sampling that keeps the expectation passes and a change of the expectation beyond a few
// percent does not. After a change of the picture that is meant, regenerate them with
//   COLUMBA_UPDATE_GOLDEN=1 ./columba_tests --gtest_filter='GoldenScenes.*'
// and say why in the commit.
#include <gtest/gtest.h>

#include <cmath>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <map>
#include <nlohmann/json.hpp>

#include "builtin/builtin_plugins.h"
#include "feather/feather_generator.h"
#include "feather/rock_dove.h"
#include "render/renderer.h"
#include "scene/scene.h"
#include "support/temp_dir_test.h"

using namespace columba;
using columba::testing::TempDirTest;
namespace fs = std::filesystem;

namespace {

const fs::path kGoldenFile = fs::path(COLUMBA_SOURCE_DIR) / "tests" / "golden" / "scenes.json";
constexpr int kGrid = 4;
constexpr int kSeedsForGolden = 8;
// A value passes within this many of its single-render standard deviations...
constexpr double kSigmas = 5.0;
// ...plus this fraction of the scene's mean luminance (for cells whose spread is near zero).
constexpr double kFloor = 0.01;

struct Statistics {
  std::vector<double> values;  // mean R, G, B, then the grid's luminances row by row
};

Statistics statistics(const Image& image) {
  Statistics s;
  double rgb[3] = {0, 0, 0};
  std::vector<double> cells(kGrid * kGrid, 0.0);
  for (int y = 0; y < image.height; ++y)
    for (int x = 0; x < image.width; ++x) {
      const float* c = image.pixel(x, y);
      for (int k = 0; k < 3; ++k) rgb[k] += c[k];
      int cell = (y * kGrid / image.height) * kGrid + x * kGrid / image.width;
      cells[cell] += (0.2126 * c[0] + 0.7152 * c[1] + 0.0722 * c[2]) * kGrid * kGrid;
    }
  const double pixels = double(image.width) * image.height;
  for (double v : rgb) s.values.push_back(v / pixels);
  for (double v : cells) s.values.push_back(v / pixels);
  return s;
}

struct ShippedScene {
  std::string name;  // the key in the golden file
  fs::path file;
  Defines defines;
};

class GoldenScenes : public TempDirTest {
 protected:
  std::string path(const std::string& name) const { return (dir_ / name).string(); }

  std::vector<ShippedScene> scenes() {
    const fs::path source(COLUMBA_SOURCE_DIR);
    FeatherGenerationOptions feather;
    feather.binary = true;
    generateFeatherPly(feather, path("feather.ply"));
    FeatherGenerationOptions neck = feather;
    neck.neck = true;
    neck.feathers = 8;
    generateFeatherPly(neck, path("neck.ply"));
    const Defines small = {{"res", "32"}, {"spp", "16"}};
    const Defines neckView = {{"feathers", path("neck.ply")}, {"width", "40"}, {"height", "30"}, {"spp", "8"}};
    std::vector<ShippedScene> list;
    for (const char* name : {"bsdf_visualization_normal", "bsdf_visualization_oblique", "bsdf_visualization_sampled"})
      list.push_back({name, source / "scenes" / (std::string(name) + ".xml"), small});
    list.push_back({"feather_linear_light",
                    source / "scenes" / "feather_linear_light.xml",
                    {{"feather", path("feather.ply")}, {"res", "32"}, {"spp", "8"}}});
    for (const char* name : {"neck_direction1", "neck_direction2", "neck_omnidirectional"})
      list.push_back({name, source / "scenes" / (std::string(name) + ".xml"), neckView});
    list.push_back({"tiny_feather", source / "examples" / "tiny_feather.xml", {{"res", "32"}, {"spp", "8"}}});
    list.push_back(
        {"three_mirrors", source / "examples" / "three_mirrors.xml", {{"res", "32"}, {"spp", "16"}, {"view", "60"}}});
    writeRockDove(RockDoveOptions{}, path("rock_dove"));
    const Defines birdView = {
        {"bird", path("rock_dove/rock_dove.xml")}, {"width", "40"}, {"height", "30"}, {"spp", "8"}};
    for (const char* name : {"rock_dove", "rock_dove_omnidirectional", "rock_dove_direction1", "rock_dove_direction2"})
      list.push_back({name, source / "scenes" / (std::string(name) + ".xml"), birdView});
    return list;
  }

  static Statistics render(const ShippedScene& shipped, uint64_t seed) {
    ParsedScene parsed = loadSceneFile(shipped.file.string(), shipped.defines, builtinPlugins());
    Scene scene(parsed, SourceLocation{shipped.file.string(), 0});
    RenderSettings settings;
    settings.seed = seed;
    RenderStats stats;
    return statistics(renderImage(scene, settings, stats));
  }
};

// Mean and standard deviation of each value over kSeedsForGolden renders.
nlohmann::json goldenEntry(const std::vector<Statistics>& runs) {
  const size_t n = runs.front().values.size();
  std::vector<double> mean(n, 0.0), deviation(n, 0.0);
  for (const Statistics& r : runs)
    for (size_t i = 0; i < n; ++i) mean[i] += r.values[i] / runs.size();
  for (const Statistics& r : runs)
    for (size_t i = 0; i < n; ++i)
      deviation[i] += (r.values[i] - mean[i]) * (r.values[i] - mean[i]) / (runs.size() - 1);
  for (double& d : deviation) d = std::sqrt(d);
  return {{"mean", mean}, {"deviation", deviation}};
}

}  // namespace

TEST_F(GoldenScenes, EveryShippedSceneMatchesItsGoldenStatisticsSlow) {
  if (std::getenv("COLUMBA_UPDATE_GOLDEN")) {
    nlohmann::json golden;
    for (const ShippedScene& shipped : scenes()) {
      std::vector<Statistics> runs;
      for (int seed = 1; seed <= kSeedsForGolden; ++seed) runs.push_back(render(shipped, 100 + seed));
      golden[shipped.name] = goldenEntry(runs);
    }
    std::ofstream(kGoldenFile) << golden.dump(1) << "\n";
    GTEST_SKIP() << "wrote " << kGoldenFile;
  }
  std::ifstream in(kGoldenFile);
  ASSERT_TRUE(in) << "cannot read " << kGoldenFile;
  nlohmann::json golden = nlohmann::json::parse(in);
  for (const ShippedScene& shipped : scenes()) {
    SCOPED_TRACE(shipped.name);
    ASSERT_TRUE(golden.contains(shipped.name)) << "no golden statistics for " << shipped.name;
    std::vector<double> mean = golden[shipped.name]["mean"], deviation = golden[shipped.name]["deviation"];
    Statistics now = render(shipped, 1);  // a seed none of the golden renders used
    ASSERT_EQ(now.values.size(), mean.size());
    const double sceneLuminance = 0.2126 * mean[0] + 0.7152 * mean[1] + 0.0722 * mean[2];
    for (size_t i = 0; i < mean.size(); ++i) {
      const char* what = i < 3 ? "mean R, G, B" : "grid cell luminance";
      EXPECT_NEAR(now.values[i], mean[i], kSigmas * deviation[i] + kFloor * sceneLuminance)
          << what << " #" << (i < 3 ? i : i - 3) << " (deviation of one render " << deviation[i] << ")";
    }
  }
}
