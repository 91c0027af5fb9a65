// gridvolume's placement and edges as Mitsuba 3 gives them: use_grid_bbox, wrap_mode, max_value.
#include <gtest/gtest.h>

#include <cstring>
#include <fstream>

#include "core/error.h"
#include "core/properties.h"
#include "media/grid_volume.h"
#include "support/error_test_support.h"
#include "support/temp_dir_test.h"

using namespace columba;
using namespace columba::testing;

namespace {
const Wavelengths kWl = Wavelengths::fixed({450.0f, 500.0f, 550.0f, 600.0f});

// A one-channel .vol file of `values` along x (y and z of one voxel), its header's box lo to hi.
std::string volBytes(const std::vector<float>& values, std::array<float, 3> lo, std::array<float, 3> hi) {
  std::string bytes = "VOL";
  bytes += char(3);
  auto int32 = [&](int v) { bytes.append(reinterpret_cast<const char*>(&v), 4); };
  auto float32 = [&](float v) { bytes.append(reinterpret_cast<const char*>(&v), 4); };
  int32(1);
  int32(int(values.size()));
  int32(1);
  int32(1);
  int32(1);
  for (float v : lo) float32(v);
  for (float v : hi) float32(v);
  for (float v : values) float32(v);
  return bytes;
}

class GridVolumeFile : public TempDirTest {
 protected:
  Properties grid(const std::string& file, const std::string& wrap = "") {
    Properties props;
    props.tag = "volume";
    props.type = "gridvolume";
    props.location = SourceLocation{"scene.xml", 5};
    props.setString("filename", (dir_ / file).string());
    if (!wrap.empty()) props.setString("wrap_mode", wrap);
    return props;
  }
  void setBool(Properties& props, const std::string& name, bool value) {
    Properties::Value v;
    v.kind = Properties::ValueKind::Boolean;
    v.boolean = value;
    v.location = props.location;
    props.set(name, v);
  }
  std::shared_ptr<GridVolume> make(const Properties& props) {
    return std::dynamic_pointer_cast<GridVolume>(makeGridVolume(props));
  }
};
}  // namespace

TEST_F(GridVolumeFile, RepeatTakesTheOppositeFacesVoxelWithinHalfAVoxelOfAFace) {
  std::ofstream(dir_ / "ramp.vol", std::ios::binary) << volBytes({1, 2, 3, 4}, {0, 0, 0}, {1, 1, 1});
  auto clamp = make(grid("ramp.vol")), mirror = make(grid("ramp.vol", "mirror")),
       repeat = make(grid("ramp.vol", "repeat"));
  // x = 0.05: 0.3 of a voxel before the first centre. Clamp and mirror hold the first voxel's 1;
  // repeat blends the last voxel's 4 (weight 0.3) with the first's 1 (0.7): 1.9.
  const Vec3 nearFace(0.05f, 0.5f, 0.5f), inside(0.5f, 0.5f, 0.5f);
  EXPECT_NEAR(clamp->eval(nearFace, kWl)[0], 1.0f, 1e-6f);
  EXPECT_NEAR(mirror->eval(nearFace, kWl)[0], 1.0f, 1e-6f);
  EXPECT_NEAR(repeat->eval(nearFace, kWl)[0], 1.9f, 1e-5f);
  // x = 0.95 near the other face: repeat blends 4 (0.7) with 1 (0.3): 3.1.
  EXPECT_NEAR(repeat->eval(Vec3(0.95f, 0.5f, 0.5f), kWl)[0], 3.1f, 1e-5f);
  // Between the centres all three agree: 2.5 halfway along.
  for (const auto& v : {clamp, mirror, repeat}) EXPECT_NEAR(v->eval(inside, kWl)[0], 2.5f, 1e-6f);
  std::string message;
  try {
    make(grid("ramp.vol", "tile"));
  } catch (const InputError& e) {
    message = e.what();
  }
  expectContains(message, {"scene.xml:5", "wrap_mode must be 'clamp', 'repeat' or 'mirror'", "tile"});
}

TEST_F(GridVolumeFile, UseGridBBoxPlacesTheCubeOnTheHeadersBox) {
  std::ofstream(dir_ / "box.vol", std::ios::binary) << volBytes({1, 2, 3, 4}, {2, -1, 0}, {4, 1, 0.5f});
  Properties props = grid("box.vol");
  setBool(props, "use_grid_bbox", true);
  auto placed = make(props);
  // A ray along x from x = -10 at (y, z) = (0, 0.25) is inside from x = 2 to 4.
  auto range = placed->clip(Ray{Vec3(-10, 0, 0.25f), Vec3(1, 0, 0)});
  ASSERT_TRUE(range);
  EXPECT_NEAR(range->first, 12.0f, 1e-4f);
  EXPECT_NEAR(range->second, 14.0f, 1e-4f);
  EXPECT_FALSE(placed->clip(Ray{Vec3(-10, 0, 0.75f), Vec3(1, 0, 0)}));
  // Halfway along the box: 2.5; without use_grid_bbox the unit cube holds the same ramp.
  EXPECT_NEAR(placed->eval(Vec3(3, 0, 0.25f), kWl)[0], 2.5f, 1e-5f);
  EXPECT_NEAR(make(grid("box.vol"))->eval(Vec3(0.5f, 0.5f, 0.5f), kWl)[0], 2.5f, 1e-5f);
  // An empty box is refused, naming it.
  std::ofstream(dir_ / "flat.vol", std::ios::binary) << volBytes({1, 2}, {0, 0, 0}, {1, 0, 1});
  Properties flat = grid("flat.vol");
  setBool(flat, "use_grid_bbox", true);
  std::string message;
  try {
    make(flat);
  } catch (const InputError& e) {
    message = e.what();
  }
  expectContains(message, {"scene.xml:5", "use_grid_bbox", "(0, 0, 0) to (1, 0, 1)", "empty or not finite"});
}

TEST_F(GridVolumeFile, MaxValueIsCheckedAndTheMajorantsComeFromTheVoxels) {
  std::ofstream(dir_ / "ramp.vol", std::ios::binary) << volBytes({1, 2, 3, 4}, {0, 0, 0}, {1, 1, 1});
  EXPECT_EQ(make(grid("ramp.vol"))->maxValue(), 4.0f);
  Properties higher = grid("ramp.vol");
  higher.setFloat("max_value", 10.0);
  EXPECT_EQ(make(higher)->maxValue(), 4.0f);
  Properties lower = grid("ramp.vol");
  lower.setFloat("max_value", 2.0);
  ::testing::internal::CaptureStderr();
  EXPECT_EQ(make(lower)->maxValue(), 4.0f);
  expectContains(::testing::internal::GetCapturedStderr(), {"max_value 2 is below the grid's largest value 4"});
}

TEST_F(GridVolumeFile, RepeatTilesFarOutsideTheCubeAndValuesTooLargeAreRefused) {
  std::ofstream(dir_ / "ramp.vol", std::ios::binary) << volBytes({1, 2, 3, 4}, {0, 0, 0}, {1, 1, 1});
  auto repeat = make(grid("ramp.vol", "repeat"));
  // A whole number of periods away the value is the same, however far (no integer overflow).
  EXPECT_NEAR(repeat->eval(Vec3(3.5f, 0.5f, 0.5f), kWl)[0], 2.5f, 1e-4f);
  EXPECT_NEAR(repeat->eval(Vec3(-6.95f, 0.5f, 0.5f), kWl)[0], 1.9f, 1e-3f);
  EXPECT_TRUE(std::isfinite(repeat->eval(Vec3(3e9f, 0.5f, 0.5f), kWl)[0]));
  // A value whose doubled colour would overflow is refused, naming the voxel.
  std::ofstream(dir_ / "huge.vol", std::ios::binary) << volBytes({1, 2e38f}, {0, 0, 0}, {1, 1, 1});
  std::string message;
  try {
    make(grid("huge.vol"));
  } catch (const InputError& e) {
    message = e.what();
  }
  expectContains(message, {"scene.xml:5", "huge.vol", "x 1, y 0, z 0", "2e+38", "must lie in [0,"});
}
