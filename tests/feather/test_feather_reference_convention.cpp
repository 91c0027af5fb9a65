// Feather PLY values as the paper's own implementation reads them: the file-to-model conversion,
// the extra tilt near the ramus, the feather's defaults, the serrated strip edges, and the
// generator writing what it means in that convention.
#include <gtest/gtest.h>

#include <unistd.h>
#include <filesystem>

#include "bsdfs/barbulebsdf.h"
#include "builtin/builtin_plugins.h"
#include "feather/feather_generator.h"
#include "scene/scene_loader.h"
#include "support/bsdf_test_support.h"
#include "support/feather_test_util.h"

using namespace columba;
using namespace columba::test;

namespace {

// One straight barb along +x in the plane z = 0, normal +z, with constant file values (or none).
FeatherPlyData straightBarb(std::optional<std::array<float, 3>> fileValues) {
  FeatherPlyData ply;
  ply.path = "straight.ply";
  for (int k = 0; k < kBarbVertices; ++k) {
    ply.positions.push_back(Vec3(0.01f * float(k), 0.0f, 0.0f));
    ply.normals.push_back(Vec3(0, 0, 1));
    ply.barbIndices.push_back(uint32_t(k));
    if (!fileValues) continue;
    ply.barbuleH.push_back((*fileValues)[0]);
    ply.barbuleMu.push_back((*fileValues)[1]);
    ply.barbuleHeight.push_back((*fileValues)[2]);
  }
  return ply;
}

// The strip's half-angle at `axial` of segment `seg`.
float edgeAngle(const BarbStrip& s, float axial) {
  return std::asin(lerp(axial, s.halfWidthStart, s.halfWidthEnd) / s.radius);
}

// The hit of a ray coming down the strip normal onto the point at `angle`, `axial` of `seg`.
std::optional<std::pair<HitRecord, SurfaceInteraction>> hitAt(const EmbreeScene& scene, const FeatherShape& shape,
                                                              int seg, float axial, float angle) {
  BarbStrip s = shape.strip(size_t(seg));
  Vec3 target = s.point(axial, angle);
  return scene.intersect(Ray{target + s.normal(angle) * 0.02f, -s.normal(angle)});
}

}  // namespace

TEST(FeatherReferenceConvention, FileValuesReachTheBsdfAsTheOriginalConvertsThem) {
  // File H 0.5, mu 0.35, height 0.6: model H 1.25, mu -0.35, height 0.6 away from the ramus.
  FeatherShape shape(straightBarb(std::array<float, 3>{0.5f, 0.35f, 0.6f}), FeatherShapeParams());
  EmbreeScene scene(shape);
  BarbStrip s = shape.strip(10);
  auto hit = hitAt(scene, shape, 10, 0.5f, 0.5f * edgeAngle(s, 0.5f));
  ASSERT_TRUE(hit.has_value());
  EXPECT_NEAR(attribute(hit->second, "H"), 1.25f, 1e-6f);
  EXPECT_NEAR(attribute(hit->second, "mu"), -0.35f, 1e-6f);
  EXPECT_NEAR(attribute(hit->second, "height"), 0.6f, 1e-6f);
}

TEST(FeatherReferenceConvention, BarbulesTiltMoreNearTheRamusOnBothSides) {
  FeatherShapeParams params;
  params.ramusWidth = 0.0f;  // the tilt zone, not the shaft, is under test
  FeatherShape shape(straightBarb(std::array<float, 3>{0.5f, 0.35f, 0.6f}), params);
  EmbreeScene scene(shape);
  for (int seg : {3, 40}) {
    BarbStrip s = shape.strip(size_t(seg));
    const float zone = 0.1f * edgeAngle(s, 0.5f);
    // d / d_r = 0.25: mu = -0.35 + 0.5 (0.25 - 1) = -0.725 on either side; at and beyond the
    // zone's edge no extra tilt.
    for (float side : {-1.0f, 1.0f}) {
      auto near = hitAt(scene, shape, seg, 0.5f, side * 0.25f * zone);
      ASSERT_TRUE(near.has_value());
      EXPECT_NEAR(attribute(near->second, "mu"), -0.725f, 2e-3f) << "segment " << seg << ", side " << side;
      auto beyond = hitAt(scene, shape, seg, 0.5f, side * 1.5f * zone);
      ASSERT_TRUE(beyond.has_value());
      EXPECT_NEAR(attribute(beyond->second, "mu"), -0.35f, 1e-6f);
    }
  }
}

TEST(FeatherReferenceConvention, WithoutPerVertexValuesTheFeathersOwnDefaultsApply) {
  FeatherShape shape(straightBarb(std::nullopt), FeatherShapeParams());
  EmbreeScene scene(shape);
  BarbStrip s = shape.strip(20);
  auto hit = hitAt(scene, shape, 20, 0.5f, 0.5f * edgeAngle(s, 0.5f));
  ASSERT_TRUE(hit.has_value());
  // File H 0.5, mu 0.35, height 0.65 (not the BSDF's H, mu and height).
  EXPECT_NEAR(attribute(hit->second, "H"), 1.25f, 1e-6f);
  EXPECT_NEAR(attribute(hit->second, "mu"), -0.35f, 1e-6f);
  EXPECT_NEAR(attribute(hit->second, "height"), 0.65f, 1e-6f);
}

TEST(FeatherReferenceConvention, ZeroTiltOrThicknessLeavesTheBsdfsOwn) {
  FeatherShape shape(straightBarb(std::array<float, 3>{0.4f, 0.0f, 0.0f}), FeatherShapeParams());
  EmbreeScene scene(shape);
  BarbStrip s = shape.strip(20);
  auto hit = hitAt(scene, shape, 20, 0.5f, 0.5f * edgeAngle(s, 0.5f));
  ASSERT_TRUE(hit.has_value());
  EXPECT_NEAR(attribute(hit->second, "H"), 1.0f, 1e-6f);
  EXPECT_EQ(attribute(hit->second, "mu"), 0.0f);
  EXPECT_EQ(attribute(hit->second, "height"), 0.0f);
  // The barbule BSDF reads those zeros as its own mu and height.
  SurfaceAttributes spacingOnly;
  spacingOnly.set(kBarbuleSpacingAttribute, 1.0f);
  BarbuleParameters own;
  own.mu = -0.2f;
  own.height = 0.55f;
  BarbuleBSDF bsdf(own);
  const Wavelengths wl = Wavelengths::fixed({450.0f, 520.0f, 600.0f, 680.0f});
  const Vec3 wi = normalize(Vec3(0.3f, 0.1f, 1.0f)), wo = normalize(Vec3(-0.35f, -0.1f, 1.0f));
  const Spectrum atHit = bsdf.eval(hit->second.bsdfContext(), wi, wo, wl);
  const Spectrum withOwn = bsdf.eval(BSDFContext{TexturePoint(Vec2(), &spacingOnly), Vec3(), Vec3()}, wi, wo, wl);
  EXPECT_FALSE(withOwn.isZero());
  for (int k = 0; k < kSpectrumSamples; ++k) EXPECT_EQ(atHit[k], withOwn[k]);
}

TEST(FeatherReferenceConvention, ShadingFramesPointTowardTheRamusOnBothSides) {
  // s (across the barbules) toward the ramus on both sides, as in the original: one tilt then
  // gives mirror-image rows.
  FeatherShape shape(straightBarb(std::nullopt), FeatherShapeParams());
  EmbreeScene scene(shape);
  BarbStrip s = shape.strip(30);
  const float angle = 0.5f * edgeAngle(s, 0.5f);
  auto plus = hitAt(scene, shape, 30, 0.5f, angle), minus = hitAt(scene, shape, 30, 0.5f, -angle);
  ASSERT_TRUE(plus && minus);
  EXPECT_LT(dot(plus->second.shading.s, s.circumferential(angle)), -0.8f);
  EXPECT_GT(dot(minus->second.shading.s, s.circumferential(-angle)), 0.8f);
  // The cross-section planes (s, n) are mirror images in the plane of the axis and the normal.
  auto mirror = [&](const Vec3& v) { return v - 2.0f * dot(v, s.b) * s.b; };
  EXPECT_NEAR(length(mirror(plus->second.shading.s) - minus->second.shading.s), 0.0f, 1e-5f);
  EXPECT_NEAR(length(mirror(plus->second.shading.n) - minus->second.shading.n), 0.0f, 1e-5f);
}

TEST(FeatherReferenceConvention, BarbuleBsdfIsSymmetricUnderReversingTheBarbuleAxis) {
  // What lets the frame's t run back along the barbule on one side.
  Properties props;
  props.tag = "bsdf";
  props.type = "barbulebsdf";
  auto bsdf = std::dynamic_pointer_cast<BSDF>(makeBarbuleBSDF(props));
  BSDFContext ctx;
  PCG32 rng(3);
  const Wavelengths wl = columba::testing::testWavelengths();
  int nonZero = 0;
  for (int i = 0; i < 2000; ++i) {
    Vec3 wi = randomUnitVector(rng), wo = randomUnitVector(rng);
    Vec3 wiT(wi.x, -wi.y, wi.z), woT(wo.x, -wo.y, wo.z);  // the directions with t reversed
    Spectrum f = bsdf->eval(ctx, wi, wo, wl), fT = bsdf->eval(ctx, wiT, woT, wl);
    for (int k = 0; k < kSpectrumSamples; ++k) ASSERT_NEAR(f[k], fT[k], 1e-5f * (1.0f + f[k])) << i;
    nonZero += f[0] > 0.0f;
  }
  EXPECT_GT(nonZero, 100);
}

TEST(FeatherReferenceConvention, SerratedEdgesDropHitsByTheSawtoothRule) {
  FeatherShape shape(straightBarb(std::nullopt), FeatherShapeParams());
  EmbreeScene scene(shape);
  int kept = 0, dropped = 0;
  for (int seg : {2, 31, 60}) {
    BarbStrip s = shape.strip(size_t(seg));
    for (int i = 1; i < 60; ++i) {
      const float axial = (float(i) + 0.5f) / 60.0f;
      const float edge = edgeAngle(s, axial);
      for (float fraction : {0.5f, 0.9f, 0.955f, 0.97f, 0.99f}) {
        for (float side : {-1.0f, 1.0f}) {
          const float angle = side * fraction * edge;
          // The original's rule: beyond 0.94 phi_edge, a point is cut away when
          // fmod(3 z, L) > L (|phi| - phi_edge) / (0.94 phi_edge - phi_edge), z measured from the
          // segment's tip-ward vertex.
          const double z = (1.0 - double(axial)) * s.length;
          const bool cut = fraction > 0.94f && std::fmod(3.0 * z, double(s.length)) >
                                                   s.length * (fraction * edge - edge) / (0.94 * edge - edge);
          auto hit = hitAt(scene, shape, seg, axial, angle);
          EXPECT_EQ(hit.has_value(), !cut) << "segment " << seg << ", axial " << axial << ", fraction " << fraction;
          BarbStrip strip = shape.strip(size_t(seg));
          Vec3 target = strip.point(axial, angle);
          EXPECT_EQ(scene.occluded(Ray{target + strip.normal(angle) * 0.02f, -strip.normal(angle)}), !cut);
          (cut ? dropped : kept)++;
        }
      }
    }
  }
  EXPECT_GT(dropped, 50);
  EXPECT_GT(kept, 500);
}

TEST(FeatherReferenceConvention, GeneratedFeatherRoundTripsThroughTheFile) {
  namespace fs = std::filesystem;
  const fs::path dir = fs::temp_directory_path() / ("columba_convention_" + std::to_string(getpid()));
  fs::create_directories(dir);
  const std::string path = (dir / "feather.ply").string();
  FeatherGenerationOptions options;
  options.barbsPerSide = 12;
  FeatherGenerationSummary summary = generateFeatherPly(options, path);

  // The file holds the reference convention: H 1.25 +-4 % written as 0.5 +-4 %, mu -0.35 as 0.35.
  FeatherPlyData ply = readFeatherPly(path);
  ASSERT_TRUE(ply.hasBarbuleValues());
  for (size_t i = 0; i < ply.barbuleH.size(); ++i) {
    ASSERT_NEAR(ply.barbuleH[i], 0.5f, 0.5f * 0.041f) << i;
    ASSERT_EQ(ply.barbuleMu[i], 0.35f) << i;
    ASSERT_NEAR(ply.barbuleHeight[i], kGreenCortexThickness, 0.0081f) << i;
  }
  ASSERT_TRUE(ply.barbWidth.has_value());
  EXPECT_FLOAT_EQ(*ply.barbWidth, summary.tilingBarbWidth);

  // Rendered: the model values the generator meant.
  FeatherShape shape(std::move(ply), FeatherShapeParams());
  EmbreeScene scene(shape);
  int checked = 0;
  for (size_t barb = 1; barb < shape.barbCount(); barb += 5) {
    const int seg = 10;
    BarbStrip s = shape.strip(barb * kBarbSegments + seg);
    auto hit = hitAt(scene, shape, int(barb * kBarbSegments + seg), 0.5f, 0.5f * edgeAngle(s, 0.5f));
    if (!hit || hit->first.primID != barb * kBarbSegments + seg) continue;
    EXPECT_NEAR(attribute(hit->second, "H"), 1.25f, 1.25f * 0.041f);
    EXPECT_NEAR(attribute(hit->second, "mu"), -0.35f, 1e-6f);
    EXPECT_NEAR(attribute(hit->second, "height"), kGreenCortexThickness, 0.0081f);
    ++checked;
  }
  EXPECT_GT(checked, 2);

  // A scene without barbwidth takes the file's: the strip radius follows it.
  const std::string xml = "<scene version=\"3.0.0\"><shape type=\"feather\"><string name=\"filename\" value=\"" + path +
                          "\"/></shape></scene>";
  ParsedScene parsed = loadSceneString(xml, "test.xml", dir.string(), {}, builtinPlugins());
  auto loaded = std::dynamic_pointer_cast<FeatherShape>(parsed.objects.at(0));
  ASSERT_TRUE(loaded);
  EXPECT_NEAR(loaded->radius(), 0.5f * summary.tilingBarbWidth / std::sin(FeatherShapeParams().cover), 1e-7f);
  fs::remove_all(dir);
}

TEST(FeatherReferenceConvention, AMissingFileSaysHowToGenerateOne) {
  const std::string xml =
      "<scene version=\"3.0.0\"><shape type=\"feather\"><string name=\"filename\" value=\"no_such_neck.ply\"/>"
      "</shape></scene>";
  try {
    loadSceneString(xml, "test.xml", "/nonexistent", {}, builtinPlugins());
    FAIL() << "a missing feather PLY was accepted";
  } catch (const InputError& e) {
    const std::string message = e.what();
    EXPECT_NE(message.find("test.xml:1"), std::string::npos) << message;
    EXPECT_NE(message.find("no_such_neck.ply"), std::string::npos) << message;
    EXPECT_NE(message.find("columba feather --neck -o"), std::string::npos) << message;
  }
}
