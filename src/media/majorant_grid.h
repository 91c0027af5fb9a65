#pragma once
// Majorants along a ray: bounds on a medium's extinction, piece by piece, against which tracking
// draws tentative collisions (majorant_tracking.h). A heterogeneous medium keeps a coarse grid of
// bounds over its extinction volume's unit cube, so that a few dense voxels raise the majorant only
// in the cells near them; one majorant for the whole volume would make every ray through the
// thin rest walk through a null collision per unit of the densest voxel's optical depth (pbrt-v4's
// MajorantGrid and DDAMajorantIterator, Mitsuba 3's majorant grid).
#include <array>
#include <optional>
#include <vector>
#include "core/spectrum.h"
#include "core/vector.h"
#include "media/volume.h"

namespace columba {

// The part (tmin, tmax) of a ray where the medium may interact, with the majorant there.
struct MajorantSegment {
  float tmin = 0.0f, tmax = 0.0f;
  Spectrum sigmaMaj;
};

// Upper bounds of a volume over the cells of a grid on its unit cube (Volume::majorantResolution
// cells per axis): each cell holds the largest value the volume takes anywhere within it.
class MajorantGrid {
 public:
  explicit MajorantGrid(const Volume& volume);
  const std::array<int, 3>& resolution() const { return res_; }
  float bound(const std::array<int, 3>& cell) const {
    return bounds_[(size_t(cell[2]) * size_t(res_[1]) + size_t(cell[1])) * size_t(res_[0]) + size_t(cell[0])];
  }

 private:
  std::array<int, 3> res_;
  std::vector<float> bounds_;
};

// The majorant segments along a ray, in order of t: one (a homogeneous medium, a volume of one
// value) or the cells of a majorant grid the ray crosses, found by a 3-D DDA (Amanatides and Woo).
class MajorantIterator {
 public:
  MajorantIterator() = default;  // none: the ray misses the medium
  MajorantIterator(float tmin, float tmax, const Spectrum& sigmaMaj) : tmin_(tmin), tmax_(tmax), single_(sigmaMaj) {}
  // The cells of `grid` crossed from tmin to tmax (both within the unit cube) by the ray o + t d of
  // the grid's space, each cell's bound times `scale`.
  MajorantIterator(const MajorantGrid& grid, float scale, const Vec3& o, const Vec3& d, float tmin, float tmax);
  // The next segment; nullopt after the last.
  std::optional<MajorantSegment> next();

 private:
  float tmin_ = 0.0f, tmax_ = 0.0f;  // what is left of the ray
  Spectrum single_;                  // the one segment's majorant, without a grid
  const MajorantGrid* grid_ = nullptr;
  float scale_ = 1.0f;
  std::array<int, 3> cell_{}, step_{}, end_{};      // the cell, +-1 along the ray, the index past the last
  std::array<float, 3> nextCrossing_{}, deltaT_{};  // t of the next face crossed, t across a cell
};

}  // namespace columba
