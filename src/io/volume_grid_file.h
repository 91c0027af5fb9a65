#pragma once
// Mitsuba's grid volume file (`.vol`), which `gridvolume` and `sdfgrid` read.
//
// Little endian: the bytes 'V' 'O' 'L' and a version byte 3; int32 encoding (1: float32, the only
// one Mitsuba 3 reads); int32 resolutions x, y, z; int32 channel count; six floats, a bounding box
// (min x, y, z, max x, y, z) that Mitsuba 3's plug-ins ignore; then x * y * z * channels float32
// values, channels fastest, then x, then y, then z.
#include <array>
#include <cstddef>
#include <string>
#include <vector>

namespace columba {

struct VolumeGrid {
  int xres = 0, yres = 0, zres = 0, channels = 0;
  // The box the header says the grid spans (Mitsuba's use_grid_bbox places it there); unchecked.
  std::array<float, 3> boundsMin{}, boundsMax{};
  std::vector<float> values;  // (((z * yres) + y) * xres + x) * channels + channel

  float at(int x, int y, int z, int channel = 0) const {
    return values[((size_t(z) * size_t(yres) + size_t(y)) * size_t(xres) + size_t(x)) * size_t(channels) +
                  size_t(channel)];
  }
};

// The grid in `bytes`, the contents of the file `name`. Every problem is an InputError naming the
// file and what is wrong: the header, a resolution or channel count below 1, a data size other
// than the header's (checked before anything is allocated), a value that is not finite.
VolumeGrid parseVolumeGrid(const std::string& bytes, const std::string& name);
VolumeGrid readVolumeGrid(const std::string& path);

}  // namespace columba
