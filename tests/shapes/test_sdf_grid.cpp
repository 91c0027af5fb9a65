// The `sdfgrid` shape: grids written here field by field in Mitsuba's .vol format (independently of
// the reader), intersected through the scene as a renderer traces them.
#include <gtest/gtest.h>

#include <cmath>
#include <cstring>
#include <fstream>
#include <functional>
#include <limits>

#include "builtin/builtin_plugins.h"
#include "scene/scene.h"
#include "support/error_test_support.h"
#include "support/render_test_support.h"
#include "support/temp_dir_test.h"

using namespace columba;

namespace {

using Field = std::function<double(double x, double y, double z)>;

struct VolHeader {
  std::string magic = "VOL";
  int version = 3, encoding = 1;
  int xres, yres, zres, channels = 1;
};

void putInt(std::string& out, int32_t v) {
  for (int i = 0; i < 4; ++i) out.push_back(char((uint32_t(v) >> (8 * i)) & 0xFF));
}
void putFloat(std::string& out, float f) {
  int32_t bits;
  std::memcpy(&bits, &f, 4);
  putInt(out, bits);
}

// The header, then `field` at the samples (x / (xres - 1), y / (yres - 1), z / (zres - 1)), x
// fastest, each value repeated in every channel.
std::string volFile(const VolHeader& h, const Field& field) {
  std::string out = h.magic;
  out.push_back(char(h.version));
  for (int v : {h.encoding, h.xres, h.yres, h.zres, h.channels}) putInt(out, v);
  for (float b : {0.f, 0.f, 0.f, 1.f, 1.f, 1.f}) putFloat(out, b);
  for (int z = 0; z < h.zres; ++z)
    for (int y = 0; y < h.yres; ++y)
      for (int x = 0; x < h.xres; ++x)
        for (int c = 0; c < h.channels; ++c)
          putFloat(out, float(field(double(x) / (h.xres - 1), double(y) / (h.yres - 1), double(z) / (h.zres - 1))));
  return out;
}

class SDFGrid : public columba::testing::TempDirTest {
 protected:
  std::string writeGrid(const std::string& name, const VolHeader& h, const Field& field) {
    std::string path = (dir_ / name).string();
    std::ofstream(path, std::ios::binary) << volFile(h, field);
    return path;
  }
  // A scene of one sdfgrid reading `path`, with `extra` inside the shape element.
  std::unique_ptr<Scene> scene(const std::string& path, const std::string& extra = "") {
    ParsedScene parsed = loadSceneString(R"(<scene version="3.0.0"><shape type="sdfgrid">
      <string name="filename" value=")" + path +
                                             "\"/>" + extra + "</shape></scene>",
                                         "<test>", ".", {}, builtinPlugins());
    return std::make_unique<Scene>(parsed, SourceLocation{"<test>", 0});
  }
  // The InputError message of loading such a scene ("" when it loads).
  std::string loadError(const std::string& path, const std::string& extra = "") {
    try {
      scene(path, extra);
    } catch (const InputError& e) {
      return e.what();
    }
    return "";
  }
};

const Vec3 kCentre(0.5f, 0.5f, 0.5f);
constexpr double kRadius = 0.3;
double sphereField(double x, double y, double z) {
  return std::sqrt(sqr(x - 0.5) + sqr(y - 0.5) + sqr(z - 0.5)) - kRadius;
}

// Directions spread evenly over the sphere (a Fibonacci lattice).
std::vector<Vec3> directions(int count) {
  std::vector<Vec3> out;
  for (int i = 0; i < count; ++i) {
    float z = 1.0f - 2.0f * (i + 0.5f) / count, r = std::sqrt(1.0f - z * z), phi = 2.39996323f * i;
    out.emplace_back(r * std::cos(phi), r * std::sin(phi), z);
  }
  return out;
}

// The plane x = 3/8, which the trilinear interpolant represents exactly (the samples too: a
// quarter-step grid along x).
double planeField(double x, double, double) { return x - 0.375; }
const VolHeader kPlaneGrid{"VOL", 3, 1, 5, 5, 6};

// The exact hit distance of a ray on the plane x = 3/8.
float planeDistance(const Ray& r) { return float((0.375 - double(r.o.x)) / double(r.d.x)); }

}  // namespace

TEST_F(SDFGrid, SphereIsHitFromEveryDirectionWithinTheInterpolationError) {
  std::string path = writeGrid("sphere.vol", {"VOL", 3, 1, 33, 33, 33}, sphereField);
  for (const char* normals : {"analytic", "smooth"}) {
    auto s = scene(path, std::string("<string name=\"normals\" value=\"") + normals + "\"/>");
    double worstDistance = 0, worstCosine = 1;
    int rays = 0;
    for (const Vec3& dir : directions(300)) {
      // Aimed at the centre and beside it, at up to 0.8 of the radius.
      Vec3 side = normalize(cross(dir, Vec3(0.3f, 0.5f, 0.8f)));
      for (float offset : {0.0f, 0.12f, 0.24f}) {
        Ray ray{kCentre + dir * 2.0f + side * offset, -dir};
        auto hit = s->intersect(ray);
        ASSERT_TRUE(hit.has_value()) << normals << " direction " << dir.x << " " << dir.y << " " << dir.z;
        double expected = 2.0 - std::sqrt(sqr(kRadius) - sqr(double(offset)));
        worstDistance = std::max(worstDistance, std::abs(hit->t - expected));
        Vec3 radial = normalize(hit->p - kCentre);
        worstCosine = std::min({worstCosine, double(dot(hit->ng, radial)), double(dot(hit->shading.n, radial))});
        ++rays;
      }
    }
    std::printf("%s normals: %d rays, worst distance error %.2e, worst normal cosine %.6f\n", normals, rays,
                worstDistance, worstCosine);
    // Interpolating |p - c| - r linearly along each of three axes errs by up to 3 h^2 / (8 r),
    // h = 1/32; the offset rays meet the surface at a cosine of 0.6, which stretches that along them.
    EXPECT_LT(worstDistance, 3.0 * sqr(1.0 / 32) / (8 * kRadius) / 0.6);
    EXPECT_GT(worstCosine, 0.995);
  }
}

TEST_F(SDFGrid, SmoothNormalsFollowTheSphereCloserThanAnalyticOnes) {
  std::string path = writeGrid("sphere.vol", {"VOL", 3, 1, 9, 9, 9}, sphereField);
  double meanAngle[2] = {0, 0};
  const std::vector<Vec3> dirs = directions(400);
  for (int smooth = 0; smooth < 2; ++smooth) {
    auto s = scene(path, smooth ? "" : R"(<string name="normals" value="analytic"/>)");
    for (const Vec3& dir : dirs) {
      auto hit = s->intersect(Ray{kCentre + dir * 2.0f, -dir});
      ASSERT_TRUE(hit.has_value());
      meanAngle[smooth] += std::acos(std::min(1.0f, dot(hit->shading.n, normalize(hit->p - kCentre)))) / dirs.size();
    }
  }
  std::printf("mean normal error on a 9^3 grid: analytic %.4f rad, smooth %.4f rad\n", meanAngle[0], meanAngle[1]);
  // The analytic normal kinks at every voxel face; the smooth one blends across them.
  EXPECT_LT(meanAngle[1], meanAngle[0]);
}

TEST_F(SDFGrid, PlaneIsHitExactlyWithItsNormal) {
  std::string path = writeGrid("plane.vol", kPlaneGrid, planeField);
  for (const char* normals : {"analytic", "smooth"}) {
    SCOPED_TRACE(normals);
    auto s = scene(path, std::string("<string name=\"normals\" value=\"") + normals + "\"/>");
    const Ray rays[] = {
        {Vec3(-1, 0.3f, 0.4f), normalize(Vec3(1, 0.2f, 0.1f))},
        // Across voxels in y and z before the hit, from outside the grid.
        {Vec3(-0.5f, 0.05f, 0.05f), normalize(Vec3(1, 0.5f, 0.6f))},
        // Grazing: a two-thousandth of a radian from the plane, hit half a unit away.
        {Vec3(0.375f - 2.5e-4f, -0.2f, 0.5f), normalize(Vec3(5e-4f, 1, 0))},
        // Within the face y = 1/2 between two rows of voxels.
        {Vec3(-1, 0.5f, 0.6f), Vec3(1, 0, 0)},
        // Starting inside the grid, on either side of the plane.
        {Vec3(0.1f, 0.5f, 0.5f), Vec3(1, 0, 0)},
        {Vec3(0.9f, 0.3f, 0.3f), normalize(Vec3(-1, 0.1f, -0.1f))},
    };
    for (const Ray& ray : rays) {
      auto hit = s->intersect(ray);
      ASSERT_TRUE(hit.has_value()) << ray.o.x << " " << ray.o.y << " " << ray.o.z;
      EXPECT_FLOAT_EQ(hit->t, planeDistance(ray));
      EXPECT_EQ(hit->ng.x, 1.0f);
      EXPECT_EQ(hit->ng.y, 0.0f);
      EXPECT_EQ(hit->ng.z, 0.0f);
      EXPECT_FLOAT_EQ(hit->shading.n.x, 1.0f);
      EXPECT_EQ(hit->uv.x, 0.0f);
      EXPECT_EQ(lengthSquared(hit->dpdu), 0.0f);
    }
    // Away from the plane inside the grid, beside the grid, and stopping short of the plane.
    EXPECT_FALSE(s->intersect(Ray{Vec3(0.2f, 0.5f, 0.5f), Vec3(-1, 0, 0)}).has_value());
    EXPECT_FALSE(s->intersect(Ray{Vec3(-1, 1.5f, 0.5f), Vec3(1, 0, 0)}).has_value());
    EXPECT_FALSE(s->intersect(Ray{Vec3(-1, 0.5f, 0.5f), Vec3(1, 0, 0), 0.0f, 1.3f}).has_value());
  }
}

TEST_F(SDFGrid, TheFirstOfTwoZerosInAVoxelIsHit) {
  // One voxel whose field (x-½)(y-½) - 0.04 + ½(x-½)(y-½)(z-½) is cubic along the diagonal
  // x = y = z = s: u² + u³/2 - 0.04 with u = s - ½, negative between its two zeros in the voxel.
  auto field = [](double x, double y, double z) {
    return (x - 0.5) * (y - 0.5) - 0.04 + 0.5 * (x - 0.5) * (y - 0.5) * (z - 0.5);
  };
  auto zeroOfU = [](double lo, double hi) {  // bisection on u^2 + u^3/2 - 0.04
    auto g = [](double u) { return u * u + 0.5 * u * u * u - 0.04; };
    for (int i = 0; i < 200; ++i) {
      double mid = 0.5 * (lo + hi);
      ((g(mid) > 0) == (g(lo) > 0) ? lo : hi) = mid;
    }
    return 0.5 * (lo + hi);
  };
  const double first = zeroOfU(-0.5, 0.0), second = zeroOfU(0.0, 0.5);
  auto s = scene(writeGrid("saddle.vol", {"VOL", 3, 1, 2, 2, 2}, field));
  const Vec3 diagonal = normalize(Vec3(1, 1, 1));
  const float sqrt3 = std::sqrt(3.0f);
  auto fromOutside = s->intersect(Ray{Vec3(-0.5f, -0.5f, -0.5f), diagonal});
  ASSERT_TRUE(fromOutside.has_value());
  EXPECT_NEAR(fromOutside->t, (first + 1.0) * sqrt3, 2e-6);
  // From the voxel's centre, between the zeros, the second one is next.
  auto fromBetween = s->intersect(Ray{Vec3(0.5f, 0.5f, 0.5f), diagonal});
  ASSERT_TRUE(fromBetween.has_value());
  EXPECT_NEAR(fromBetween->t, second * sqrt3, 2e-6);
}

TEST_F(SDFGrid, ToWorldPlacesTheUnitCubeAndTurnsNormalsAsMitsubaDoes) {
  // Scaled by (2, 3, 4) then moved by (1, 2, 3): the plane x = 3/8 goes to x = 1.75.
  auto s = scene(writeGrid("plane.vol", kPlaneGrid, planeField),
                 R"(<transform name="to_world"><scale x="2" y="3" z="4"/><translate x="1" y="2" z="3"/></transform>)");
  auto hit = s->intersect(Ray{Vec3(0, 3.5f, 5), Vec3(1, 0, 0)});
  ASSERT_TRUE(hit.has_value());
  EXPECT_FLOAT_EQ(hit->t, 1.75f);
  EXPECT_FLOAT_EQ(hit->ng.x, 1.0f);
  // Outside the placed cube (y beyond 2 + 3) there is nothing.
  EXPECT_FALSE(s->intersect(Ray{Vec3(0, 5.2f, 5), Vec3(1, 0, 0)}).has_value());

  // The plane x + y = 1 stretched by 2 along x is x/2 + y = 1: normals go by the inverse transpose.
  auto slanted =
      scene(writeGrid("slanted.vol", {"VOL", 3, 1, 3, 3, 3}, [](double x, double y, double) { return x + y - 1.0; }),
            R"(<string name="normals" value="analytic"/>
                          <transform name="to_world"><scale x="2" y="1" z="1"/></transform>)");
  auto slantedHit = slanted->intersect(Ray{Vec3(1, -1, 0.5f), Vec3(0, 1, 0)});
  ASSERT_TRUE(slantedHit.has_value());
  EXPECT_NEAR(slantedHit->t, 1.5f, 1e-6f);
  Vec3 expected = normalize(Vec3(0.5f, 1, 0));
  EXPECT_NEAR(dot(slantedHit->ng, expected), 1.0f, 1e-6f);
}

TEST_F(SDFGrid, FlipNormalsTurnsBothNormalsInward) {
  auto s = scene(writeGrid("plane.vol", kPlaneGrid, planeField), R"(<boolean name="flip_normals" value="true"/>)");
  auto hit = s->intersect(Ray{Vec3(-1, 0.5f, 0.5f), Vec3(1, 0, 0)});
  ASSERT_TRUE(hit.has_value());
  EXPECT_EQ(hit->ng.x, -1.0f);
  EXPECT_FLOAT_EQ(hit->shading.n.x, -1.0f);
}

TEST_F(SDFGrid, BadFilesAreRefusedNamingTheFileAndTheProblem) {
  using columba::testing::expectContains;
  auto expectRefused = [&](const std::string& name, const VolHeader& h, std::initializer_list<const char*> parts,
                           const Field& field = planeField) {
    SCOPED_TRACE(name);
    std::string path = writeGrid(name, h, field);
    std::string message = loadError(path);
    expectContains(message, parts);
    expectContains(message, {path.c_str(), "<test>:"});
  };
  expectRefused("magic.vol", {"VOX", 3, 1, 2, 2, 2}, {"not a grid volume", "'VOL'"});
  expectRefused("version.vol", {"VOL", 2, 1, 2, 2, 2}, {"version 2"});
  expectRefused("encoding.vol", {"VOL", 3, 2, 2, 2, 2}, {"encoding 2"});
  expectRefused("channels.vol", {"VOL", 3, 1, 2, 2, 2, 3}, {"3 channels"});
  expectRefused("flat.vol", {"VOL", 3, 1, 4, 1, 4}, {"4 x 1 x 4", "at least 2"});
  expectRefused("negative.vol", {"VOL", 3, 1, 2, -2, 2}, {"2 x -2 x 2"});
  expectRefused("nan.vol", {"VOL", 3, 1, 3, 2, 2}, {"x 1, y 0, z 1", "nan", "not a finite"},
                [](double x, double, double z) { return x == 0.5 && z == 1 ? NAN : x - 0.5; });
  expectRefused("nosurface.vol", {"VOL", 3, 1, 2, 2, 2}, {"same sign"}, [](double, double, double) { return 1.0; });
  // Truncated and overlong data, and a header cut short.
  std::string full = volFile({"VOL", 3, 1, 3, 3, 3}, planeField);
  struct Damaged {
    const char* name;
    std::string bytes;
    const char* problem;
  };
  for (const Damaged& file : {Damaged{"truncated.vol", full.substr(0, full.size() - 5), "(truncated)"},
                              Damaged{"long.vol", full + "xxxx", "156 bytes, but the file has 160"},
                              Damaged{"short.vol", full.substr(0, 20), "too short"}}) {
    SCOPED_TRACE(file.name);
    std::string path = (dir_ / file.name).string();
    std::ofstream(path, std::ios::binary) << file.bytes;
    expectContains(loadError(path), {path.c_str(), file.problem});
  }
  expectContains(loadError((dir_ / "missing.vol").string()), {"missing.vol"});
}

TEST_F(SDFGrid, ParametersMitsubaRefusesAreRefused) {
  using columba::testing::expectContains;
  std::string path = writeGrid("plane.vol", kPlaneGrid, planeField);
  expectContains(loadError(path, R"(<string name="normals" value="flat"/>)"), {"'flat'", "normals", "<test>:"});
  expectContains(loadError(path, "\n<emitter type=\"area\"/>"), {"<test>:3", "area emitter"});
}

TEST_F(SDFGrid, RendersThroughASceneFile) {
  std::string path = writeGrid("sphere.vol", {"VOL", 3, 1, 17, 17, 17}, sphereField);
  // The sphere of radius 0.3 seen from 3 units away fills the middle of a 0.6-wide view; a white
  // environment lights it. Diffuse 0.5 under uniform unit radiance reflects 0.5.
  Image image = columba::testing::renderSceneString(R"(<scene version="3.0.0"><integrator type="direct"/>
    <sensor type="perspective"><float name="fov" value="15"/>
      <transform name="to_world"><lookat origin="0.5, 0.5, 3.5" target="0.5, 0.5, 0.5" up="0, 1, 0"/></transform>
      <film type="hdrfilm"><integer name="width" value="16"/><integer name="height" value="16"/>
        <rfilter type="box"/></film>
      <sampler type="independent"><integer name="sample_count" value="64"/></sampler></sensor>
    <emitter type="constant"><spectrum name="radiance" value="1"/></emitter>
    <shape type="sdfgrid"><string name="filename" value=")" +
                                                    path + R"("/>
      <bsdf type="diffuse"><spectrum name="reflectance" value="0.5"/></bsdf></shape></scene>)");
  Vec3 centre = columba::testing::meanColour(image, 6, 6, 10, 10),
       corner = columba::testing::meanColour(image, 0, 0, 2, 2);
  std::printf("centre %.3f %.3f %.3f, corner %.3f %.3f %.3f\n", centre.x, centre.y, centre.z, corner.x, corner.y,
              corner.z);
  EXPECT_NEAR(corner.y, 1.0f, 0.1f);
  EXPECT_NEAR(centre.y / corner.y, 0.5f, 0.03f);
}
