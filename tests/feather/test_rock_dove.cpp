// The procedural rock dove: deterministic, its feathers outside the body and covering it.
#include <gtest/gtest.h>

#include <algorithm>
#include <filesystem>
#include <fstream>
#include <iterator>

#include "builtin/builtin_plugins.h"
#include "feather/rock_dove.h"
#include "io/feather_ply.h"
#include "scene/scene.h"
#include "shapes/feather_shape.h"
#include "support/temp_dir_test.h"

using namespace columba;
using columba::testing::TempDirTest;
namespace fs = std::filesystem;

namespace {

Vec3 apply(const Matrix4& m, const Vec3& p) {
  return Vec3(float(m.m[0][0] * p.x + m.m[0][1] * p.y + m.m[0][2] * p.z + m.m[0][3]),
              float(m.m[1][0] * p.x + m.m[1][1] * p.y + m.m[1][2] * p.z + m.m[1][3]),
              float(m.m[2][0] * p.x + m.m[2][1] * p.y + m.m[2][2] * p.z + m.m[2][3]));
}

bool sameMatrix(const Matrix4& a, const Matrix4& b) { return a.m == b.m; }

}  // namespace

TEST(RockDove, TheLayoutIsDeterministicForASeed) {
  const RockDoveBody body;
  RockDoveOptions options;
  const RockDovePlumage a = layOutRockDove(body, options), b = layOutRockDove(body, options);
  ASSERT_EQ(a.feathers.size(), b.feathers.size());
  ASSERT_GT(a.feathers.size(), 1000u);
  for (size_t i = 0; i < a.feathers.size(); ++i) {
    EXPECT_TRUE(sameMatrix(a.feathers[i].toWorld, b.feathers[i].toWorld)) << i;
    EXPECT_EQ(a.feathers[i].height, b.feathers[i].height) << i;
  }
  options.seed = 2;
  const RockDovePlumage c = layOutRockDove(body, options);
  EXPECT_FALSE(c.feathers.size() == a.feathers.size() && sameMatrix(c.feathers[0].toWorld, a.feathers[0].toWorld));
}

TEST(RockDove, NeckFeathersAreIridescentGreenAboveAndPurpleBelow) {
  const RockDoveBody body;
  const RockDovePlumage plumage = layOutRockDove(body, RockDoveOptions{});
  double upper = 0, lower = 0;
  int upperCount = 0, lowerCount = 0;
  for (const PlacedFeather& f : plumage.feathers) {
    if (f.plumage != Plumage::Iridescent) continue;
    EXPECT_GE(f.height, 0.51f - 0.012f - 1e-6f);
    EXPECT_LE(f.height, 0.60f + 0.012f + 1e-6f);
    const Vec3 base = apply(f.toWorld, Vec3(0.0f, -0.6f, 0.0f));
    const float t = body.neckFraction(base);
    if (t > 0.7f) upper += f.height, ++upperCount;
    if (t < 0.2f) lower += f.height, ++lowerCount;
  }
  ASSERT_GT(upperCount, 20);
  ASSERT_GT(lowerCount, 20);
  EXPECT_GT(upper / upperCount, 0.58);  // green
  EXPECT_LT(lower / lowerCount, 0.53);  // purple
}

class RockDoveFiles : public TempDirTest {};

TEST_F(RockDoveFiles, NoBarbOfAnyFeatherLiesInsideTheBody) {
  // Every vertex of every barb, placed as its instance places it, outside the body's ellipsoids
  // (the layout keeps only a few outline points of each feather outside).
  RockDoveOptions options;
  writeRockDove(options, dir_.string());
  std::vector<FeatherPlyData> templates;
  for (int k = 0; k < options.templates; ++k)
    templates.push_back(readFeatherPly((dir_ / ("rock_dove_feather_" + std::to_string(k) + ".ply")).string()));
  const RockDoveBody body;
  const RockDovePlumage plumage = layOutRockDove(body, options);
  size_t inside = 0, checked = 0;
  float deepest = 0.0f;
  for (const PlacedFeather& f : plumage.feathers)
    for (const Vec3& v : templates[size_t(f.templateIndex)].positions) {
      const float value = body.inside(apply(f.toWorld, v));
      ++checked;
      if (value < 0.0f) ++inside, deepest = std::min(deepest, value);
      if (value < -0.04f) {
        Vec3 q = apply(f.toWorld, v);
        std::printf("DEEP %s %.2f %.2f %.2f %.3f\n", body.parts()[f.part].name.c_str(), q.x, q.y, q.z, value);
      }
    }
  // A barb may dip a hair under the skin between the outline points: at most 1 in 1000 vertices,
  // and by no more than 2 % of a radius (the implicit value is about twice the relative depth).
  EXPECT_LE(double(inside) / double(checked), 1e-3) << inside << " of " << checked;
  std::printf("%zu of %zu barb vertices inside the body, the deepest at %g\n", inside, checked, deepest);
  EXPECT_GT(deepest, -0.04f);
}

TEST_F(RockDoveFiles, FromTheDefaultViewFewRaysThatHitTheBirdReachItsSkinSlow) {
  writeRockDove(RockDoveOptions{}, dir_.string());
  const fs::path scene = fs::path(COLUMBA_SOURCE_DIR) / "scenes" / "rock_dove.xml";
  for (const char* turn : {"0", "60"}) {
    SCOPED_TRACE(turn);
    ParsedScene parsed =
        loadSceneFile(scene.string(), {{"bird", (dir_ / "rock_dove.xml").string()}, {"turn", turn}}, builtinPlugins());
    Scene s(parsed, SourceLocation{scene.string(), 0});
    const RockDoveBody body;
    const Sensor& sensor = s.sensor();
    const int width = sensor.film().width(), height = sensor.film().height();
    size_t bird = 0, skin = 0;
    for (int y = 0; y < height; y += 4)
      for (int x = 0; x < width; x += 4) {
        std::optional<Ray> ray = sensor.generateRay(Vec2(x + 0.5f, y + 0.5f));
        if (!ray) continue;
        std::optional<SurfaceInteraction> hit = s.intersect(*ray);
        if (!hit) continue;
        if (dynamic_cast<const FeatherShape*>(hit->shape)) {
          ++bird;
          continue;
        }
        // A sphere of the body: skin where a feathered part's surface is and the face is not
        // bare (the eye rings and the cere); the beak and eyes otherwise.
        ++bird;
        if (std::abs(body.inside(hit->p)) < 1e-2f && !body.face(hit->p, true)) {
          ++skin;
          for (const BodyPart& part : body.parts())
            if (std::abs(part.shape.implicit(hit->p)) < 1e-2f)
              std::printf("SKIN %s %.2f %.2f %.2f\n", part.name.c_str(), hit->p.x, hit->p.y, hit->p.z);
        }
      }
    ASSERT_GT(bird, 1000u);
    std::printf("turn %s: %zu of %zu rays that hit the bird reach its skin\n", turn, skin, bird);
    EXPECT_LE(double(skin) / double(bird), 0.01) << skin << " of " << bird << " rays that hit the bird";
  }
}

TEST_F(RockDoveFiles, PurpleFeathersAreCopiesOfTemplatesThatChooseTheirOwnLayerStack) {
  RockDoveOptions options;
  options.featherScale = 3.0f;  // few feathers: quick
  options.purpleStack = 1;
  options.barbule = {{"layers_1", "melanin:0.1, keratin:0.1"}};
  writeRockDove(options, dir_.string());
  for (int k = 0; k < options.templates; ++k) {
    const FeatherPlyData plain = readFeatherPly((dir_ / ("rock_dove_feather_" + std::to_string(k) + ".ply")).string());
    const FeatherPlyData purple =
        readFeatherPly((dir_ / ("rock_dove_feather_" + std::to_string(k) + "_purple.ply")).string());
    EXPECT_EQ(plain.largestLayerStack, 0);  // every vertex chooses stack 0
    EXPECT_EQ(purple.largestLayerStack, 1);
    ASSERT_EQ(purple.layerStack.size(), plain.layerStack.size());
    EXPECT_EQ(std::count(purple.layerStack.begin(), purple.layerStack.end(), 1),
              std::ptrdiff_t(purple.layerStack.size()));
    EXPECT_EQ(purple.positions.size(), plain.positions.size());  // the same barbs
  }
  // Exactly the purple iridescent feathers are copies of the purple templates.
  const RockDovePlumage plumage = layOutRockDove(RockDoveBody(), options);
  const std::ptrdiff_t purple =
      std::count_if(plumage.feathers.begin(), plumage.feathers.end(),
                    [](const PlacedFeather& f) { return f.plumage == Plumage::Iridescent && f.purple; });
  std::ifstream in(dir_ / "rock_dove.xml");
  const std::string xml((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
  size_t copies = 0;
  for (size_t at = xml.find("<ref id=\"dove-purple-"); at != std::string::npos;
       at = xml.find("<ref id=\"dove-purple-", at + 1))
    ++copies;
  EXPECT_GT(purple, 10);
  EXPECT_EQ(copies, size_t(purple));
  // The scene loads without a word: the BSDF has the stack the purple copies choose.
  const fs::path scene = fs::path(COLUMBA_SOURCE_DIR) / "scenes" / "rock_dove.xml";
  ::testing::internal::CaptureStderr();
  ParsedScene parsed = loadSceneFile(scene.string(), {{"bird", (dir_ / "rock_dove.xml").string()}}, builtinPlugins());
  Scene s(parsed, SourceLocation{scene.string(), 0});
  EXPECT_EQ(::testing::internal::GetCapturedStderr(), "");
  // Without a purple stack: no copies, and templates without the property, as before.
  const fs::path plainDir = dir_ / "plain";
  writeRockDove(RockDoveOptions{}, plainDir.string());
  EXPECT_FALSE(fs::exists(plainDir / "rock_dove_feather_0_purple.ply"));
  EXPECT_TRUE(readFeatherPly((plainDir / "rock_dove_feather_0.ply").string()).layerStack.empty());
}
