// The majorant grid of a heterogeneous medium: each cell's bound holds for every value of the
// volume within it (trilinear and nearest filters, clamp and repeat, one and three channels), the
// DDA's segments tile the ray in order, and tracking against them is unbiased: delta and ratio
// tracking through a grid with one dense voxel give exp(-integral of sigma_t), integrated finely.
#include <gtest/gtest.h>

#include <chrono>
#include <cmath>
#include <fstream>

#include "core/rng.h"
#include "media/const_volume.h"
#include "media/grid_volume.h"
#include "media/heterogeneous_medium.h"
#include "media/isotropic_phase.h"
#include "media/majorant_tracking.h"
#include "support/render_test_support.h"
#include "support/temp_dir_test.h"

using namespace columba;

namespace {

const Wavelengths kWl = Wavelengths::fixed({450.0f, 520.0f, 610.0f, 680.0f});

// A grid of random values in [0, 1) with one voxel of `hot`.
VolumeGrid randomGrid(int xres, int yres, int zres, int channels, float hot, uint64_t seed) {
  VolumeGrid grid;
  grid.xres = xres;
  grid.yres = yres;
  grid.zres = zres;
  grid.channels = channels;
  PCG32 rng(seed);
  for (int i = 0; i < xres * yres * zres * channels; ++i) grid.values.push_back(rng.nextFloat());
  grid.values[size_t(xres * yres + xres + 1) * size_t(channels)] = hot;
  return grid;
}

// A cube of the grid turned and stretched into the scene.
const Transform kPlacement = Transform::translate(Vec3(-1.0f, 0.5f, 2.0f)) * Transform::rotate(Vec3(1, 2, 3), 30.0f) *
                             Transform::scale(Vec3(2.0f, 1.0f, 3.0f));

}  // namespace

TEST(MajorantGrid, EveryCellBoundsEveryValueWithinIt) {
  for (const auto& [res, channels] :
       {std::pair(std::array{5, 3, 7}, 1), std::pair(std::array{20, 9, 2}, 1), std::pair(std::array{4, 11, 3}, 3)})
    for (auto filter : {GridVolume::Filter::Trilinear, GridVolume::Filter::Nearest})
      for (auto wrap : {GridVolume::Wrap::Clamp, GridVolume::Wrap::Repeat}) {
        const GridVolume volume(randomGrid(res[0], res[1], res[2], channels, 50.0f, 7), filter, wrap, Transform());
        const MajorantGrid grid(volume);
        const std::array<int, 3> cells = grid.resolution();
        for (int a = 0; a < 3; ++a) EXPECT_EQ(cells[a], res[a] <= 8 ? 2 * res[a] : 16);
        PCG32 rng(11);
        float tightest = 0.0f;  // the largest value met over its cell's bound, which should be near 1
        for (int i = 0; i < 200000; ++i) {
          const Vec3 p(rng.nextFloat(), rng.nextFloat(), rng.nextFloat());
          const std::array<int, 3> cell{int(p.x * cells[0]), int(p.y * cells[1]), int(p.z * cells[2])};
          const float bound = grid.bound(cell);
          const Spectrum value = volume.eval(p, kWl);
          ASSERT_LE(value.maxValue(), bound * (1.0f + 1e-5f)) << p.x << " " << p.y << " " << p.z;
          if (bound > 0.0f) tightest = std::max(tightest, value.maxValue() / bound);
        }
        EXPECT_GT(tightest, 0.9f);
      }
}

TEST(MajorantGrid, TheDDAsSegmentsTileTheRayInOrderUnderTheirCellsBounds) {
  const GridVolume volume(randomGrid(6, 13, 4, 1, 50.0f, 3), GridVolume::Filter::Trilinear, GridVolume::Wrap::Clamp,
                          kPlacement);
  const HeterogeneousMedium medium(std::make_shared<GridVolume>(volume), std::make_shared<GridVolume>(volume), 2.0f,
                                   std::make_shared<IsotropicPhase>());
  PCG32 rng(5);
  for (int i = 0; i < 2000; ++i) {
    // From a point near the cube toward another: some rays miss it, some start or end inside.
    const Vec3 from =
        kPlacement.point(Vec3(rng.nextFloat(), rng.nextFloat(), rng.nextFloat()) * 1.6f - Vec3(0.3f, 0.3f, 0.3f));
    const Vec3 to =
        kPlacement.point(Vec3(rng.nextFloat(), rng.nextFloat(), rng.nextFloat()) * 1.6f - Vec3(0.3f, 0.3f, 0.3f));
    const Ray ray{from, to - from, 0.0f, 1.0f};
    const auto inside = volume.clip(ray);
    MajorantIterator segments = medium.majorant(ray, kWl);
    float t = inside ? inside->first : 0.0f;
    int count = 0;
    while (const auto segment = segments.next()) {
      ++count;
      EXPECT_EQ(segment->tmin, t);
      EXPECT_GE(segment->tmax, segment->tmin);
      for (float f : {0.01f, 0.5f, 0.99f}) {
        const Vec3 p = ray.at(segment->tmin + f * (segment->tmax - segment->tmin));
        EXPECT_LE(medium.coefficients(p, kWl).sigmaT[0], segment->sigmaMaj[0] * (1.0f + 1e-5f));
      }
      t = segment->tmax;
    }
    if (!inside) {
      EXPECT_EQ(count, 0);
      continue;
    }
    EXPECT_NEAR(t, inside->second, 1e-5f);
    EXPECT_LE(count, 12 + 16 + 8 + 1);  // a cell entered across each face, and the first
  }
}

TEST(MajorantGrid, AVolumeOfOneValueIsOneSegment) {
  const HeterogeneousMedium medium(std::make_shared<ConstVolume>(SpectralDistribution::constant(3.0f), kPlacement),
                                   std::make_shared<ConstVolume>(SpectralDistribution::constant(0.5f), std::nullopt),
                                   2.0f, std::make_shared<IsotropicPhase>());
  MajorantIterator segments =
      medium.majorant(Ray{kPlacement.point(Vec3(-1, 0.5f, 0.5f)), kPlacement.vector(Vec3(1, 0, 0))}, kWl);
  const auto segment = segments.next();
  ASSERT_TRUE(segment);
  EXPECT_NEAR(segment->tmin, 1.0f, 1e-5f);
  EXPECT_NEAR(segment->tmax, 2.0f, 1e-5f);
  EXPECT_EQ(segment->sigmaMaj[0], 6.0f);
  EXPECT_FALSE(segments.next());
}

// Delta tracking passes a ray with probability exp(-integral of sigma_t), and ratio tracking's mean
// weight is the same, through a grid of random values with one voxel 30 times the largest of them.
TEST(MajorantGrid, TrackingThroughTheCellsIsUnbiased) {
  auto sigmaT = std::make_shared<GridVolume>(randomGrid(7, 5, 6, 1, 30.0f, 9), GridVolume::Filter::Trilinear,
                                             GridVolume::Wrap::Clamp, kPlacement);
  const HeterogeneousMedium medium(sigmaT, sigmaT, 0.3f, std::make_shared<IsotropicPhase>());
  // Near the dense voxel (x 1, y 1, z 1 of the cube) and through thin parts only.
  const Ray rays[] = {
      {kPlacement.point(Vec3(-0.2f, 0.3f, 0.05f)), kPlacement.vector(Vec3(1.4f, 0.4f, 0.6f)), 0.0f, 1.0f},
      {kPlacement.point(Vec3(1.1f, 0.9f, 0.9f)), kPlacement.vector(Vec3(-1.2f, -0.3f, -0.2f)), 0.0f, 1.0f}};
  for (const Ray& ray : rays) {
    // The optical depth within the cube (the grid's values hold beyond it, but the medium does
    // not) by the midpoint rule over 200,000 steps.
    const auto inside = sigmaT->clip(ray);
    ASSERT_TRUE(inside);
    const int steps = 200000;
    double depth = 0.0;
    const double dt = double(inside->second - inside->first) / steps;
    for (int i = 0; i < steps; ++i)
      depth += medium.coefficients(ray.at(float(inside->first + (i + 0.5) * dt)), kWl).sigmaT[0] * dt * length(ray.d);
    const double expected = std::exp(-depth);
    PCG32 rng(21);
    const int runs = 100000;
    double passed = 0.0, ratioSum = 0.0, ratioSquares = 0.0;
    for (int i = 0; i < runs; ++i) {
      bool real = false;
      (void)trackMajorant(medium, ray, kWl, rng,
                          [&](const Vec3&, const MediumCoefficients& c, const Spectrum& sigmaMaj, const Spectrum&) {
                            real = rng.nextFloat() < c.sigmaT[0] / sigmaMaj[0];
                            return !real;
                          });
      passed += real ? 0.0 : 1.0;
      double weight = 1.0;
      (void)trackMajorant(medium, ray, kWl, rng,
                          [&](const Vec3&, const MediumCoefficients& c, const Spectrum& sigmaMaj, const Spectrum&) {
                            weight *= std::max(0.0, 1.0 - double(c.sigmaT[0]) / sigmaMaj[0]);
                            return weight > 0.0;
                          });
      ratioSum += weight;
      ratioSquares += weight * weight;
    }
    const double deltaMean = passed / runs, deltaError = std::sqrt(deltaMean * (1.0 - deltaMean) / runs);
    const double ratioMean = ratioSum / runs,
                 ratioError = std::sqrt(std::max(0.0, ratioSquares / runs - ratioMean * ratioMean) / runs);
    EXPECT_GT(depth, 0.5);
    EXPECT_NEAR(deltaMean, expected, 4.0 * deltaError + 1e-4) << "optical depth " << depth;
    EXPECT_NEAR(ratioMean, expected, 4.0 * ratioError + 1e-4) << "optical depth " << depth;
  }
}

// A 4 x 4 x 4 grid of ones with one voxel of 1e30 (304 bytes) used to make every ray through the
// cube walk 2^20 null collisions: a 24 x 24 image at 4 spp ran for minutes. Now only rays into the
// cells the dense voxel reaches are slowed; the image comes in well under a second or two.
class HostileGrid : public columba::testing::TempDirTest {};

TEST_F(HostileGrid, OneHugeVoxelRendersInBoundedTime) {
  std::string bytes = "VOL";
  bytes += char(3);
  for (int v : {1, 4, 4, 4, 1}) bytes.append(reinterpret_cast<const char*>(&v), 4);
  for (float v : {0.0f, 0.0f, 0.0f, 1.0f, 1.0f, 1.0f}) bytes.append(reinterpret_cast<const char*>(&v), 4);
  for (int i = 0; i < 64; ++i) {
    const float v = i == 21 ? 1e30f : 1.0f;
    bytes.append(reinterpret_cast<const char*>(&v), 4);
  }
  std::ofstream(dir_ / "hot.vol", std::ios::binary) << bytes;
  const std::string xml = R"(<scene version="3.0.0"><integrator type="volpath"/>
    <sensor type="perspective"><float name="fov" value="40"/>
      <transform name="to_world"><lookat origin="0.5, -3, 0.5" target="0.5, 0.5, 0.5" up="0, 0, 1"/></transform>
      <film type="hdrfilm"><integer name="width" value="12"/><integer name="height" value="12"/></film>
      <sampler type="independent"><integer name="sample_count" value="1"/></sampler></sensor>
    <emitter type="constant"><rgb name="radiance" value="1"/></emitter>
    <medium type="heterogeneous" id="smoke"><float name="albedo" value="0.8"/>
      <volume type="gridvolume" name="sigma_t"><string name="filename" value=")" +
                          (dir_ / "hot.vol").string() + R"("/></volume></medium>
    <shape type="cube"><transform name="to_world"><scale value="0.5"/><translate x="0.5" y="0.5" z="0.5"/></transform>
      <bsdf type="null"/><ref name="interior" id="smoke"/></shape></scene>)";
  RenderSettings settings;
  settings.threads = 2;
  ::testing::internal::CaptureStderr();
  const auto start = std::chrono::steady_clock::now();
  const Image image = columba::testing::renderSceneString(xml, settings);
  const double seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  ::testing::internal::GetCapturedStderr();
  EXPECT_LT(seconds, 3.0);
  for (float v : image.rgb) {
    EXPECT_TRUE(std::isfinite(v));
    EXPECT_GE(v, 0.0f);
  }
}
