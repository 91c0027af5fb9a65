#include <gtest/gtest.h>

#include <cmath>

#include "bsdfs/bumpmap.h"
#include "bsdfs/diffuse.h"
#include "builtin/builtin_plugins.h"
#include "io/image.h"
#include "scene/scene.h"
#include "support/bsdf_test_support.h"
#include "support/image_test_support.h"
#include "support/temp_dir_test.h"
#include "textures/bitmap_texture.h"

using namespace columba;
using namespace columba::testing;

namespace {

void expectNear(const Vec3& a, const Vec3& b, float tolerance, const std::string& what) {
  for (int i = 0; i < 3; ++i) EXPECT_NEAR(a[i], b[i], tolerance) << what << " component " << i;
}

class BumpMap : public TempDirTest {
 protected:
  // Heights 0 (left texel) and 1 (right texel), read raw: between the texel centres h rises by 1 over
  // half the image, dh/du = 2.
  std::shared_ptr<const BitmapTexture> ramp(Transform toUV = Transform()) {
    const std::string path = writeTwoTexelEXR((dir_ / "ramp.exr").string(), 0.0f, 1.0f);
    return std::make_shared<BitmapTexture>(readImagePixels(path, false), true, TextureFilter::Bilinear,
                                           TextureWrap::Clamp, toUV);
  }
  SurfaceInteraction hitFrom(const std::string& shape, const Ray& ray) {
    ParsedScene parsed = loadSceneString("<scene version=\"3.0.0\">" + shape + "</scene>", (dir_ / "t.xml").string(),
                                         dir_.string(), {}, builtinPlugins());
    Scene scene(parsed, {"<test>", 0});
    auto hit = scene.intersect(ray);
    EXPECT_TRUE(hit.has_value()) << shape;
    return hit ? *hit : SurfaceInteraction();
  }
};

}  // namespace

TEST_F(BumpMap, BilinearHeightsHaveTheirSlopes) {
  EXPECT_NEAR(ramp()->evalFloatGradient(Vec2(0.5f, 0.5f)).x, 2.0f, 1e-5f);
  EXPECT_NEAR(ramp()->evalFloatGradient(Vec2(0.5f, 0.5f)).y, 0.0f, 1e-6f);
  // to_uv scaling u by 2 makes the height change twice as fast in u.
  EXPECT_NEAR(ramp(Transform::scale(Vec3(2, 1, 1)))->evalFloatGradient(Vec2(0.25f, 0.5f)).x, 4.0f, 1e-5f);
}

TEST_F(BumpMap, ShapesGiveTheirPositionDerivatives) {
  // Rectangle: uv = ((x + 1) / 2, (y + 1) / 2) in its local frame, here scaled by 3.
  SurfaceInteraction r = hitFrom(R"(<shape type="rectangle"><transform name="to_world"><scale value="3"/></transform>
      </shape>)",
                                 Ray{Vec3(0.5f, 0.2f, 2.0f), Vec3(0, 0, -1)});
  expectNear(r.dpdu, Vec3(6, 0, 0), 1e-5f, "rectangle dp/du");
  expectNear(r.dpdv, Vec3(0, 6, 0), 1e-5f, "rectangle dp/dv");
  // Unit sphere at its point (1, 0, 0): u = phi / (2 pi), v = theta / pi.
  SurfaceInteraction s = hitFrom(R"(<shape type="sphere"/>)", Ray{Vec3(3, 0, 0), Vec3(-1, 0, 0)});
  expectNear(s.dpdu, Vec3(0, 2 * kPi, 0), 1e-4f, "sphere dp/du");
  expectNear(s.dpdv, Vec3(0, 0, -kPi), 1e-4f, "sphere dp/dv");
  // Cylinder from (0, 0, 0) to (0, 0, 2): u = phi / (2 pi), v along the axis.
  SurfaceInteraction c = hitFrom(R"(<shape type="cylinder"><point name="p1" x="0" y="0" z="2"/></shape>)",
                                 Ray{Vec3(3, 0, 0.5f), Vec3(-1, 0, 0)});
  expectNear(c.dpdu, Vec3(0, 2 * kPi, 0), 1e-4f, "cylinder dp/du");
  expectNear(c.dpdv, Vec3(0, 0, 2), 1e-5f, "cylinder dp/dv");
  // A triangle whose uvs stretch u over 2 units of x and v over 3 units of y.
  std::ofstream(dir_ / "tri.obj") << "v 0 0 0\nv 2 0 0\nv 0 3 0\nvt 0 0\nvt 1 0\nvt 0 1\nf 1/1 2/2 3/3\n";
  SurfaceInteraction t = hitFrom(R"(<shape type="obj"><string name="filename" value="tri.obj"/>
      <boolean name="flip_tex_coords" value="false"/></shape>)",
                                 Ray{Vec3(0.3f, 0.4f, 1.0f), Vec3(0, 0, -1)});
  expectNear(t.dpdu, Vec3(2, 0, 0), 1e-5f, "mesh dp/du");
  expectNear(t.dpdv, Vec3(0, 3, 0), 1e-5f, "mesh dp/dv");
  EXPECT_NEAR(t.uv.x, 0.15f, 1e-5f);
  EXPECT_NEAR(t.uv.y, 0.4f / 3.0f, 1e-5f);
}

TEST_F(BumpMap, ARampTiltsTheNormalAsTheDisplacedSurfaceDoes) {
  // On a rectangle (dp/du = (2, 0, 0), dp/dv = (0, 2, 0) locally) with scale s, the displaced
  // derivatives are (2, 0, 2 s) and (0, 2, 0): the normal is (-s, 0, 1) / sqrt(1 + s^2).
  const float scale = 0.5f;
  BumpMapBSDF bumped(std::make_shared<DiffuseBSDF>(SpectralDistribution::constant(0.5f)), ramp(), scale);
  BSDFContext ctx{Vec2(0.5f, 0.5f), Vec3(2, 0, 0), Vec3(0, 2, 0)};
  const Vec3 n = normalize(Vec3(-scale, 0, 1));
  expectNear(bumped.perturbedFrame(ctx).n, n, 1e-5f, "normal");
  const Wavelengths wl = testWavelengths();
  const Vec3 wi = directionAt(10, 180);
  for (Vec3 wo : {directionAt(40, 180), directionAt(30, 90), directionAt(20, 0)})
    EXPECT_NEAR(bumped.eval(ctx, wi, wo, wl)[0], 0.5f * kInvPi * std::max(0.0f, dot(wo, n)), 1e-6f);
  // Without position derivatives (a shape that gives none) the frame is left as it is.
  expectNear(bumped.perturbedFrame(BSDFContext{Vec2(0.5f, 0.5f), Vec3(), Vec3()}).n, Vec3(0, 0, 1), 0.0f,
             "no derivatives");
}

TEST_F(BumpMap, SamplingMatchesThePdf) {
  BumpMapBSDF bumped(std::make_shared<DiffuseBSDF>(SpectralDistribution::constant(0.5f)), ramp(), 0.7f);
  // chiSquareBSDF evaluates at uv = (0, 0) with no derivatives given: use a context-carrying wrapper.
  struct AtPoint : BSDF {
    const BSDF& inner;
    BSDFContext ctx{Vec2(0.5f, 0.5f), Vec3(2, 0, 0), Vec3(0, 2, 0)};
    explicit AtPoint(const BSDF& b) : inner(b) {}
    Spectrum eval(const BSDFContext&, const Vec3& wi, const Vec3& wo, const Wavelengths& wl) const override {
      return inner.eval(ctx, wi, wo, wl);
    }
    float pdf(const BSDFContext&, const Vec3& wi, const Vec3& wo, const Wavelengths& wl) const override {
      return inner.pdf(ctx, wi, wo, wl);
    }
    std::optional<BSDFSample> sample(const BSDFContext&, const Vec3& wi, const Wavelengths& wl, float uc,
                                     Vec2 u) const override {
      return inner.sample(ctx, wi, wl, uc, u);
    }
  } atPoint(bumped);
  const double threshold = sidakThreshold(0.01, 3);
  for (float theta : {0.0f, 45.0f, 75.0f}) {
    ChiSquareResult r = chiSquareBSDF(atPoint, directionAt(theta, 30));
    EXPECT_GT(r.pValue, threshold) << theta << ": " << r.message;
  }
  EXPECT_LT(maxWeightError(atPoint, directionAt(45, 30)), 1e-4);
}
