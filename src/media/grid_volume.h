#pragma once
// `gridvolume`: values on a grid of voxels read from a Mitsuba `.vol` file, interpolated
// trilinearly (or taken from the nearest voxel) within the unit cube that `to_world` places.
#include <algorithm>
#include <vector>
#include "io/volume_grid_file.h"
#include "media/volume.h"

namespace columba {

class GridVolume final : public Volume {
 public:
  enum class Filter { Trilinear, Nearest };
  // How the trilinear filter finds the neighbours of the voxels on the cube's faces: the face's
  // own (clamp; Mitsuba's mirror gives the same there) or the opposite face's (repeat).
  enum class Wrap { Clamp, Repeat };
  // A grid of one channel (a value at every wavelength) or three (linear sRGB, upsampled to a
  // spectrum per voxel, unbounded). Throws std::invalid_argument for another channel count.
  GridVolume(const VolumeGrid& grid, Filter filter, Wrap wrap, const Transform& toWorld);
  // The largest value of the voxels that the filter reaches from within the box.
  float maxValue(const Vec3& lo, const Vec3& hi) const override;
  // Half a voxel per cell up to 8 voxels along an axis, so that each cell lies within one span
  // of the trilinear filter and bounds it tightly; 16 cells beyond.
  std::array<int, 3> majorantResolution() const override;
  // The largest value of the whole grid.
  float maxValue() const { return max_; }
  float largestGivenValue() const override { return largestGiven_; }

 protected:
  Spectrum evalLocal(const Vec3& p, const Wavelengths& wl) const override;

 private:
  Spectrum voxel(int x, int y, int z, const Wavelengths& wl) const;
  // No value interpolated from voxel i exceeds it: the value, or a colour's scale.
  float voxelBound(size_t i) const { return spectra_.empty() ? values_[i] : spectra_[i].scale; }
  int xres_, yres_, zres_;
  Filter filter_;
  Wrap wrap_;
  std::vector<float> values_;         // one channel: a value per voxel
  std::vector<RGBSpectrum> spectra_;  // three channels: a spectrum per voxel
  float max_ = 0.0f;
  float largestGiven_ = 0.0f;  // of the file's values, every channel
};

std::shared_ptr<Object> makeGridVolume(const Properties& props);

}  // namespace columba
