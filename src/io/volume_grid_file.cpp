#include "io/volume_grid_file.h"

#include <fmt/format.h>

#include <cmath>
#include <cstdint>
#include <cstring>
#include <fstream>
#include <iterator>

#include "core/error.h"

namespace columba {

namespace {

constexpr size_t kHeaderBytes = 48;  // magic and version (4), five int32 (20), six floats (24)
constexpr int kFloat32Encoding = 1;

int32_t readInt32(const std::string& bytes, size_t at) {
  uint32_t value = 0;
  for (size_t i = 0; i < 4; ++i) value |= uint32_t(uint8_t(bytes[at + i])) << (8 * i);
  return int32_t(value);
}

}  // namespace

VolumeGrid parseVolumeGrid(const std::string& bytes, const std::string& name) {
  if (bytes.size() < kHeaderBytes)
    throw InputError({}, name + ": " + std::to_string(bytes.size()) +
                             " bytes, too short for the 48-byte header of a grid volume (.vol) file");
  if (bytes.compare(0, 3, "VOL") != 0) throw InputError({}, name + ": not a grid volume (.vol) file (no 'VOL' header)");
  if (uint8_t(bytes[3]) != 3)
    throw InputError({}, name + ": grid volume file version " + std::to_string(uint8_t(bytes[3])) +
                             " is not supported (only version 3)");
  const int32_t encoding = readInt32(bytes, 4);
  if (encoding != kFloat32Encoding)
    throw InputError({}, name + ": grid volume encoding " + std::to_string(encoding) +
                             " is not supported (only 1, float32, as in Mitsuba 3)");
  VolumeGrid grid;
  grid.xres = readInt32(bytes, 8);
  grid.yres = readInt32(bytes, 12);
  grid.zres = readInt32(bytes, 16);
  grid.channels = readInt32(bytes, 20);
  for (int axis = 0; axis < 3; ++axis) {
    std::memcpy(&grid.boundsMin[axis], bytes.data() + 24 + 4 * axis, 4);  // x86-64 is little endian
    std::memcpy(&grid.boundsMax[axis], bytes.data() + 36 + 4 * axis, 4);
  }
  if (grid.xres < 1 || grid.yres < 1 || grid.zres < 1)
    throw InputError({}, name + ": the resolution " + std::to_string(grid.xres) + " x " + std::to_string(grid.yres) +
                             " x " + std::to_string(grid.zres) + " has an axis below 1");
  if (grid.channels < 1)
    throw InputError({}, name + ": " + std::to_string(grid.channels) + " channels, at least 1 needed");
  // Each factor is below 2^31: their product in double is finite, and exact wherever it could
  // match a file's size. It is compared with that size before anything is allocated.
  const double count = double(grid.xres) * grid.yres * grid.zres * grid.channels;
  const size_t available = (bytes.size() - kHeaderBytes) / sizeof(float);
  if (count != double(available) || (bytes.size() - kHeaderBytes) % sizeof(float) != 0)
    throw InputError({}, name + ": the header's " + std::to_string(grid.xres) + " x " + std::to_string(grid.yres) +
                             " x " + std::to_string(grid.zres) + " x " + std::to_string(grid.channels) +
                             " values need " + fmt::format("{:.0f}", double(kHeaderBytes) + count * sizeof(float)) +
                             " bytes, but the file has " + std::to_string(bytes.size()) +
                             (count > double(available) ? " (truncated)" : ""));
  grid.values.resize(available);
  std::memcpy(grid.values.data(), bytes.data() + kHeaderBytes, available * sizeof(float));  // x86-64 is little endian
  for (size_t i = 0; i < available; ++i)
    if (!std::isfinite(grid.values[i])) {
      const size_t channel = i % size_t(grid.channels), cell = i / size_t(grid.channels);
      const size_t x = cell % size_t(grid.xres), y = cell / size_t(grid.xres) % size_t(grid.yres),
                   z = cell / (size_t(grid.xres) * size_t(grid.yres));
      throw InputError({}, name + ": the value at x " + std::to_string(x) + ", y " + std::to_string(y) + ", z " +
                               std::to_string(z) + ", channel " + std::to_string(channel) + " is " +
                               std::to_string(grid.values[i]) + ", not a finite number");
    }
  return grid;
}

VolumeGrid readVolumeGrid(const std::string& path) {
  std::ifstream file(path, std::ios::binary);
  if (!file) throw InputError({}, path + ": cannot open the grid volume file");
  std::string bytes((std::istreambuf_iterator<char>(file)), std::istreambuf_iterator<char>());
  if (file.bad()) throw InputError({}, path + ": cannot read the grid volume file");
  return parseVolumeGrid(bytes, path);
}

}  // namespace columba
