#include <gtest/gtest.h>

#include <unistd.h>
#include <CLI/CLI.hpp>
#include <algorithm>
#include <cmath>
#include <filesystem>
#include <fstream>
#include <map>
#include <sstream>

#include "app/feather_command.h"
#include "builtin/builtin_plugins.h"
#include "feather/feather_generator.h"
#include "feather/neck_layout.h"
#include "scene/scene_loader.h"
#include "support/feather_test_util.h"

using namespace columba;
using namespace columba::test;

namespace {

class FeatherGeneratorTest : public ::testing::Test {
 protected:
  std::filesystem::path dir() const {
    return std::filesystem::temp_directory_path() / ("columba_feather_gen_" + std::to_string(getpid()));
  }
  std::string path(const std::string& name) {
    std::filesystem::create_directories(dir());
    return (dir() / name).string();
  }
  void TearDown() override { std::filesystem::remove_all(dir()); }

  static std::string contents(const std::string& file) {
    std::ifstream in(file, std::ios::binary);
    std::stringstream ss;
    ss << in.rdbuf();
    return ss.str();
  }
};

FeatherGenerationOptions neckOptions(int feathers, int barbs, uint64_t seed) {
  FeatherGenerationOptions o;
  o.neck = true;
  o.feathers = feathers;
  o.barbsPerSide = barbs;
  o.seed = seed;
  return o;
}

}  // namespace

TEST_F(FeatherGeneratorTest, SingleFeatherReloadsThroughTheFeatherShape) {
  for (bool binary : {false, true}) {
    FeatherGenerationOptions o;
    o.binary = binary;
    std::string file = path(binary ? "single.bin.ply" : "single.ply");
    FeatherGenerationSummary s = generateFeatherPly(o, file);
    FeatherPlyData ply = readFeatherPly(file);
    EXPECT_EQ(ply.barbCount(), s.faces);
    EXPECT_EQ(s.faces, s.barbs + 1);  // and the rachis
    EXPECT_EQ(ply.barbIndices.size(), s.faces * kBarbVertices);
    EXPECT_EQ(ply.positions.size(), s.vertices);
    EXPECT_NEAR(s.tilingBarbWidth, FeatherShapeParams().barbWidth, 0.002f);  // the default barb count tiles
    // About 1.2 long, centred near the origin, facing +z, green.
    Vec3 lo(1e9f, 1e9f, 1e9f), hi = -lo;
    double nz = 0;
    for (size_t i = 0; i < ply.positions.size(); ++i) {
      lo = minv(lo, ply.positions[i]);
      hi = maxv(hi, ply.positions[i]);
      nz += ply.normals[i].z;
      EXPECT_GT(ply.barbuleHeight[i], 0.58f);
      // The file convention: model H 1.25 +-4 % and mu -0.35 written as 0.5 and 0.35.
      EXPECT_NEAR(ply.barbuleH[i], 0.5f, 0.024f);
      EXPECT_FLOAT_EQ(ply.barbuleMu[i], 0.35f);
    }
    EXPECT_NEAR(hi.y - lo.y, 1.2f, 0.15f);
    EXPECT_LT(std::abs(0.5f * (hi.y + lo.y)), 0.15f);
    EXPECT_LT(std::abs(0.5f * (hi.x + lo.x)), 0.15f);
    EXPECT_GT(nz / double(ply.normals.size()), 0.99);
    FeatherShape shape(std::move(ply), FeatherShapeParams());
    EXPECT_EQ(shape.primitiveCount(), s.faces * kBarbSegments);
  }
}

TEST_F(FeatherGeneratorTest, OutputDependsOnlyOnTheSeed) {
  std::string a = path("a.ply"), b = path("b.ply"), c = path("c.ply");
  generateFeatherPly(neckOptions(8, 6, 42), a);
  generateFeatherPly(neckOptions(8, 6, 42), b);
  generateFeatherPly(neckOptions(8, 6, 43), c);
  EXPECT_EQ(contents(a), contents(b));
  EXPECT_NE(contents(a), contents(c));
}

TEST_F(FeatherGeneratorTest, UnwritableOutputLeavesNothingBehind) {
  std::string file = path("missing_dir/out.ply");
  EXPECT_THROW(generateFeatherPly(FeatherGenerationOptions(), file), std::runtime_error);
  EXPECT_FALSE(std::filesystem::exists(std::filesystem::path(file).parent_path()));
}

// Beyond what a PLY's 32-bit vertex numbers reach, refused before anything is laid out or written
// (a single feather of 2e9 barbs grew its file without end, a neck of 1e8 feathers ran out of
// memory laying them out).
TEST_F(FeatherGeneratorTest, MoreFacesThanAFeatherPlyHoldsAreRefused) {
  FeatherGenerationOptions single;
  single.barbsPerSide = 2000000000;
  std::string file = path("big.ply");
  try {
    generateFeatherPly(single, file);
    ADD_FAILURE() << "2e9 barbs per side were accepted";
  } catch (const std::invalid_argument& e) {
    EXPECT_NE(std::string(e.what()).find("at most 16777215 barbs per side"), std::string::npos) << e.what();
  }
  single.barbsPerSide = int(kMaxFeatherFaces / 2 + 1);
  EXPECT_THROW(generateFeatherPly(single, file), std::invalid_argument);
  try {
    generateFeatherPly(neckOptions(100000000, 0, 1), file);
    ADD_FAILURE() << "1e8 feathers were accepted";
  } catch (const std::invalid_argument& e) {
    EXPECT_NE(std::string(e.what()).find("100000000 feathers"), std::string::npos) << e.what();
  }
  EXPECT_TRUE(std::filesystem::is_empty(dir()));
}

TEST_F(FeatherGeneratorTest, ACancelledGenerationLeavesNoFile) {
  std::atomic<bool> cancel{true};
  FeatherGenerationOptions o = neckOptions(4, 10, 1);
  o.cancel = &cancel;
  FeatherGenerationSummary s = generateFeatherPly(o, path("cancelled.ply"));
  EXPECT_FALSE(s.written);
  EXPECT_TRUE(std::filesystem::is_empty(dir()));
}

TEST_F(FeatherGeneratorTest, NeckFeathersOverlapLikeRoofTiles) {
  const int feathers = 30, barbs = 12;
  std::string file = path("neck.ply");
  FeatherGenerationOptions o = neckOptions(feathers, barbs, 5);
  o.binary = true;
  FeatherGenerationSummary s = generateFeatherPly(o, file);
  EXPECT_EQ(s.feathers, size_t(feathers));
  FeatherPlyData ply = readFeatherPly(file);
  int green = 0, purple = 0;
  for (float h : ply.barbuleHeight) {
    green += h > 0.59f;
    purple += h < 0.52f;
  }
  EXPECT_GT(green, int(ply.barbuleHeight.size() / 10));
  EXPECT_GT(purple, int(ply.barbuleHeight.size() / 10));

  // Few barbs: widen them so that they close the vanes.
  FeatherShapeParams params;
  params.barbWidth = s.tilingBarbWidth;
  FeatherShape shape(std::move(ply), params);
  EmbreeScene scene(shape);
  NeckLayout layout = layOutNeck(feathers, 5);
  PCG32 rng(1);
  int rays = 0, layered = 0, ordered = 0;
  for (int i = 0; i < 2000; ++i) {
    // Straight down onto the middle of the neck.
    Vec3 o(lerp(rng.nextFloat(), -0.5f, 1.5f), lerp(rng.nextFloat(), 0.0f, 1.5f), 5.0f);
    Ray ray{o, Vec3(0, 0, -1)};
    std::vector<size_t> crossed;  // feathers, in the order the ray meets them
    for (int k = 0; k < 200; ++k) {
      auto hit = scene.intersect(ray);
      if (!hit) break;
      size_t feather = hit->first.primID / kBarbSegments / (2 * barbs + 1);
      if (crossed.empty() || crossed.back() != feather) crossed.push_back(feather);
      ray = hit->second.spawnRay(ray.d);
    }
    if (crossed.empty()) continue;
    ++rays;
    if (crossed.size() < 2) continue;
    ++layered;
    // Roof tiles: the feather on top is rooted higher up the neck than the one below it.
    ordered += layout.feathers[crossed[0]].base.y < layout.feathers[crossed[1]].base.y;
  }
  EXPECT_GT(rays, 1900);
  EXPECT_GT(layered, rays / 2);
  EXPECT_GT(ordered, layered * 9 / 10) << ordered << " of " << layered;
}

TEST_F(FeatherGeneratorTest, CommandWritesTheFileAndValidatesItsOptions) {
  std::string out = path("cli.ply");
  auto run = [](std::vector<std::string> args) {
    CLI::App app("columba");
    addFeatherCommand(app);
    std::reverse(args.begin(), args.end());  // CLI11 takes the arguments in reverse order
    app.parse(args);
  };
  run({"feather", "--neck", "--feathers", "4", "--barbs", "3", "--binary", "--seed", "9", "-o", out});
  FeatherPlyData ply = readFeatherPly(out);
  EXPECT_EQ(ply.barbCount(), 4u * (2u * 3u + 1u));
  for (const auto& entry : std::filesystem::directory_iterator(dir()))
    EXPECT_EQ(entry.path().filename(), "cli.ply") << "left behind: " << entry.path();
  EXPECT_THROW(run({"feather", "--single", "--neck", "-o", out}), CLI::ParseError);
  EXPECT_THROW(run({"feather", "--single"}), CLI::ParseError);
  EXPECT_THROW(run({"feather", "-o", out}), CLI::ParseError);
  EXPECT_THROW(run({"feather", "--single", "--feathers", "3", "-o", out}), CLI::ParseError);
}

TEST_F(FeatherGeneratorTest, GeneratedFeatherLoadsFromASceneFile) {
  FeatherGenerationOptions o;
  o.barbsPerSide = 8;
  generateFeatherPly(o, path("feather.ply"));
  auto load = [&](const std::string& shapeParams) {
    std::string xml =
        "<scene version='2.0.0'>\n<shape type='feather'>\n"
        "  <string name='filename' value='feather.ply'/>\n" +
        shapeParams + "  <bsdf type='diffuse'/>\n</shape>\n</scene>\n";
    return loadSceneString(xml, "feather.xml", dir().string(), {}, builtinPlugins());
  };
  ParsedScene parsed = load(
      "  <float name='barbwidth' value='0.02'/>\n  <float name='span' value='0.3'/>\n"
      "  <transform name='to_world'><scale value='0.035'/></transform>\n");
  ASSERT_EQ(parsed.objects.size(), 1u);
  auto shape = std::dynamic_pointer_cast<FeatherShape>(parsed.objects[0]);
  ASSERT_TRUE(shape);
  EXPECT_TRUE(shape->bsdf);
  EXPECT_EQ(shape->barbCount(), 17u);
  EXPECT_NEAR(shape->radius(), 0.035f * 0.01f / std::sin(0.78f), 1e-7f);
  try {
    load("  <float name='barbwidth' value='-1'/>\n");
    FAIL() << "a negative barbwidth was accepted";
  } catch (const InputError& e) {
    EXPECT_NE(std::string(e.what()).find("feather.xml:4"), std::string::npos) << e.what();
  }
  EXPECT_THROW(load("  <float name='barbwidht' value='0.01'/>\n"), InputError);
}

TEST_F(FeatherGeneratorTest, ColourOptionsReachTheFile) {
  auto heights = [](const std::string& file) {
    FeatherPlyData ply = readFeatherPly(file);
    return std::pair(*std::min_element(ply.barbuleHeight.begin(), ply.barbuleHeight.end()),
                     *std::max_element(ply.barbuleHeight.begin(), ply.barbuleHeight.end()));
  };
  FeatherGenerationOptions single;
  single.barbsPerSide = 10;
  single.greenHeight = 0.45f;
  generateFeatherPly(single, path("thin.ply"));
  auto [thinLo, thinHi] = heights(path("thin.ply"));
  EXPECT_GE(thinLo, 0.45f - kBarbThicknessSpread - 1e-6f);
  EXPECT_LE(thinHi, 0.45f + kBarbThicknessSpread + 1e-6f);
  // Each feather's spread comes on top of the barbs'.
  FeatherGenerationOptions neck = neckOptions(12, 4, 5);
  neck.greenHeight = 0.66f, neck.purpleHeight = 0.48f, neck.heightSpread = 0.03f;
  generateFeatherPly(neck, path("neck.ply"));
  auto [lo, hi] = heights(path("neck.ply"));
  EXPECT_GE(lo, 0.48f - 0.03f - kBarbThicknessSpread - 1e-6f);
  EXPECT_LT(lo, 0.48f - kBarbThicknessSpread);  // some feather thinner than any barb's spread
  EXPECT_LE(hi, 0.66f + 0.03f + kBarbThicknessSpread + 1e-6f);
  EXPECT_GT(hi, 0.66f + kBarbThicknessSpread);
  // Purple from the top of the neck down, sharply: every barbule at the purple thickness.
  FeatherGenerationOptions purple = neckOptions(6, 3, 5);
  purple.purpleBelow = -10.0f, purple.colourBlend = 0.0f;
  generateFeatherPly(purple, path("purple.ply"));
  auto [pLo, pHi] = heights(path("purple.ply"));
  EXPECT_GE(pLo, kPurpleCortexThickness - kBarbThicknessSpread - 1e-6f);
  EXPECT_LE(pHi, kPurpleCortexThickness + kBarbThicknessSpread + 1e-6f);
  // The defaults write what the generator always wrote: the same file as without the options.
  FeatherGenerationOptions defaults = neckOptions(6, 3, 5), given = defaults;
  given.greenHeight = kGreenCortexThickness, given.purpleHeight = kPurpleCortexThickness;
  generateFeatherPly(defaults, path("a.ply"));
  generateFeatherPly(given, path("b.ply"));
  EXPECT_EQ(contents(path("a.ply")), contents(path("b.ply")));
}

TEST_F(FeatherGeneratorTest, ColourOptionsThatMakeNoFeathersAreErrors) {
  auto message = [&](FeatherGenerationOptions o) {
    try {
      generateFeatherPly(o, path("bad.ply"));
    } catch (const std::invalid_argument& e) {
      return std::string(e.what());
    }
    return std::string();
  };
  FeatherGenerationOptions o;
  o.greenHeight = -0.1f;
  EXPECT_NE(message(o).find("the height must be a number of micrometres, at least 0, not -0.1"), std::string::npos);
  o = FeatherGenerationOptions();
  o.heightSpread = 0.7f;
  EXPECT_NE(message(o).find("a height spread of 0.7 um"), std::string::npos) << message(o);
  o = neckOptions(4, 3, 1);
  o.colourBlend = std::nanf("");
  EXPECT_NE(message(o).find("colour blend"), std::string::npos);
  EXPECT_FALSE(std::filesystem::exists(path("bad.ply")));
  // The neck's options need a neck.
  CLI::App app("columba");
  addFeatherCommand(app);
  std::vector<std::string> args = {"feather", "--single", "--purple-height", "0.5", "-o", path("x.ply")};
  std::reverse(args.begin(), args.end());
  EXPECT_THROW(app.parse(args), CLI::ParseError);
}

TEST_F(FeatherGeneratorTest, APurpleStackIsWrittenWhereTheBarbulesAreMorePurpleThanGreen) {
  FeatherGenerationOptions o = neckOptions(12, 4, 5);
  o.purpleStack = 3;
  generateFeatherPly(o, path("stacks.ply"));
  FeatherPlyData ply = readFeatherPly(path("stacks.ply"));
  ASSERT_EQ(ply.layerStack.size(), ply.barbuleHeight.size());
  // Half way between the colours' thicknesses lies the switch; each barb's own spread blurs it.
  const float middle = 0.5f * (kGreenCortexThickness + kPurpleCortexThickness);
  int purple = 0, green = 0;
  for (size_t i = 0; i < ply.layerStack.size(); ++i) {
    const float h = ply.barbuleHeight[i];
    if (h < middle - kBarbThicknessSpread) {
      EXPECT_EQ(ply.layerStack[i], 3) << "vertex " << i << ", height " << h;
    } else if (h > middle + kBarbThicknessSpread) {
      EXPECT_EQ(ply.layerStack[i], 0) << "vertex " << i << ", height " << h;
    }
    purple += ply.layerStack[i] == 3;
    green += ply.layerStack[i] == 0;
  }
  EXPECT_GT(purple, 1000);
  EXPECT_GT(green, 1000);
  EXPECT_EQ(purple + green, int(ply.layerStack.size()));
  // Without a purple stack the file has no stack property, as before.
  FeatherGenerationOptions plain = neckOptions(12, 4, 5);
  generateFeatherPly(plain, path("plain.ply"));
  EXPECT_TRUE(readFeatherPly(path("plain.ply")).layerStack.empty());
  o.neck = false;
  EXPECT_THROW(generateFeatherPly(o, path("single.ply")), std::invalid_argument);
}
