#include "media/majorant_grid.h"

#include <algorithm>
#include <cmath>
#include <limits>

namespace columba {

MajorantGrid::MajorantGrid(const Volume& volume) : res_(volume.majorantResolution()) {
  bounds_.resize(size_t(res_[0]) * size_t(res_[1]) * size_t(res_[2]));
  for (int z = 0; z < res_[2]; ++z)
    for (int y = 0; y < res_[1]; ++y)
      for (int x = 0; x < res_[0]; ++x) {
        const Vec3 lo(float(x) / float(res_[0]), float(y) / float(res_[1]), float(z) / float(res_[2]));
        const Vec3 hi(float(x + 1) / float(res_[0]), float(y + 1) / float(res_[1]), float(z + 1) / float(res_[2]));
        bounds_[(size_t(z) * size_t(res_[1]) + size_t(y)) * size_t(res_[0]) + size_t(x)] = volume.maxValue(lo, hi);
      }
}

MajorantIterator::MajorantIterator(const MajorantGrid& grid, float scale, const Vec3& o, const Vec3& d, float tmin,
                                   float tmax)
    : tmin_(tmin), tmax_(tmax), grid_(&grid), scale_(scale) {
  const std::array<int, 3>& res = grid.resolution();
  const Vec3 start = o + d * tmin;
  for (int a = 0; a < 3; ++a) {
    // In units of cells along this axis.
    const float p = start[a] * float(res[a]), v = d[a] * float(res[a]);
    if (!std::isfinite(p) || !std::isfinite(v)) {  // no ray: no cells (a cell index from NaN is undefined)
      tmin_ = tmax_;
      return;
    }
    cell_[a] = int(std::clamp(std::floor(p), 0.0f, float(res[a] - 1)));
    if (v == 0.0f) {
      nextCrossing_[a] = std::numeric_limits<float>::infinity();
      deltaT_[a] = 0.0f;
      step_[a] = 0;
      end_[a] = -2;  // never reached
    } else if (v > 0.0f) {
      nextCrossing_[a] = tmin + (float(cell_[a] + 1) - p) / v;
      deltaT_[a] = 1.0f / v;
      step_[a] = 1;
      end_[a] = res[a];
    } else {
      nextCrossing_[a] = tmin + (float(cell_[a]) - p) / v;
      deltaT_[a] = -1.0f / v;
      step_[a] = -1;
      end_[a] = -1;
    }
  }
}

std::optional<MajorantSegment> MajorantIterator::next() {
  if (!(tmin_ < tmax_)) return std::nullopt;
  if (!grid_) {
    const MajorantSegment segment{tmin_, tmax_, single_};
    tmin_ = tmax_;
    return segment;
  }
  // The axis whose face the ray crosses first leaves the cell.
  int axis = 0;
  if (nextCrossing_[1] < nextCrossing_[axis]) axis = 1;
  if (nextCrossing_[2] < nextCrossing_[axis]) axis = 2;
  // Rounding may put a face just behind the start (a ray entering on a cell's face): an empty
  // segment then, never one that runs backwards.
  const float exit = std::max(tmin_, std::min(tmax_, nextCrossing_[axis]));
  const MajorantSegment segment{tmin_, exit, Spectrum(scale_ * grid_->bound(cell_))};
  tmin_ = exit;
  cell_[axis] += step_[axis];
  nextCrossing_[axis] += deltaT_[axis];
  if (cell_[axis] == end_[axis]) tmin_ = tmax_;  // out of the grid
  return segment;
}

}  // namespace columba
