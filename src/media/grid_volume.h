#pragma once
// `gridvolume`: values on a grid of voxels read from a Mitsuba `.vol` file, interpolated
// trilinearly (or taken from the nearest voxel) within the unit cube that `to_world` places.
#include <vector>
#include "io/volume_grid_file.h"
#include "media/volume.h"

namespace columba {

class GridVolume final : public Volume {
 public:
  enum class Filter { Trilinear, Nearest };
  // A grid of one channel (a value at every wavelength) or three (linear sRGB, upsampled to a
  // spectrum per voxel, unbounded). Throws std::invalid_argument for another channel count.
  GridVolume(const VolumeGrid& grid, Filter filter, const Transform& toWorld);
  float maxValue() const override { return max_; }

 protected:
  Spectrum evalLocal(const Vec3& p, const Wavelengths& wl) const override;

 private:
  Spectrum voxel(int x, int y, int z, const Wavelengths& wl) const;
  int xres_, yres_, zres_;
  Filter filter_;
  std::vector<float> values_;         // one channel: a value per voxel
  std::vector<RGBSpectrum> spectra_;  // three channels: a spectrum per voxel
  float max_ = 0.0f;
};

std::shared_ptr<Object> makeGridVolume(const Properties& props);

}  // namespace columba
