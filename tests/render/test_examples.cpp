// The example scene shipped in examples/ loads and renders, and its feather PLY is what
// docs/feather-ply.md describes.
#include <gtest/gtest.h>

#include <cmath>
#include <filesystem>

#include "builtin/builtin_plugins.h"
#include "io/feather_ply.h"
#include "render/renderer.h"
#include "scene/scene.h"

using namespace columba;
namespace fs = std::filesystem;

namespace {
const fs::path kExamples = fs::path(COLUMBA_SOURCE_DIR) / "examples";
}  // namespace

TEST(Examples, TinyFeatherPlyHasEightBarbsWithPerVertexValues) {
  FeatherPlyData ply = readFeatherPly((kExamples / "tiny_feather.ply").string());
  EXPECT_EQ(ply.barbCount(), 8u);
  EXPECT_EQ(ply.positions.size(), 8u * kBarbVertices);
  ASSERT_EQ(ply.barbuleH.size(), ply.positions.size());
  ASSERT_EQ(ply.barbuleMu.size(), ply.positions.size());
  ASSERT_EQ(ply.barbuleHeight.size(), ply.positions.size());
  EXPECT_FLOAT_EQ(ply.barbuleH[0], 0.5f);
  EXPECT_FLOAT_EQ(ply.barbuleMu[0], 0.35f);
  EXPECT_FLOAT_EQ(ply.barbuleHeight[0], 0.6f);
  for (const Vec3& n : ply.normals) EXPECT_NEAR(n.z, 1.0f, 1e-6f);
}

TEST(Examples, TinyFeatherSceneLoadsAndRenders) {
  const fs::path path = kExamples / "tiny_feather.xml";
  ParsedScene parsed = loadSceneFile(path.string(), {{"res", "48"}, {"spp", "4"}}, builtinPlugins());
  Scene scene(parsed, SourceLocation{path.string(), 0});
  RenderSettings settings;
  RenderStats stats;
  Image image = renderImage(scene, settings, stats);
  EXPECT_TRUE(stats.complete);
  ASSERT_EQ(image.width, 48);
  double sum = 0;
  for (float v : image.rgb) {
    ASSERT_TRUE(std::isfinite(v));
    sum += v;
  }
  EXPECT_GT(sum / image.rgb.size(), 1e-3);
  // The feather covers the middle of the frame, and it is lit.
  const float* centre = image.pixel(24, 24);
  EXPECT_GT(centre[0] + centre[1] + centre[2], 0.0f);
}
