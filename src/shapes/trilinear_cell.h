#pragma once
// The trilinear interpolant of one cell of a sampled grid (a voxel of an SDF grid), and where it
// first vanishes along a ray. Cell coordinates q lie in [0, 1]^3; the value of corner i sits at
// (i & 1, (i >> 1) & 1, i >> 2).
#include <array>

namespace columba {

using CellPoint = std::array<double, 3>;

class TrilinearCell {
 public:
  explicit TrilinearCell(const std::array<double, 8>& corners) : f_(corners) {}

  // Nested lerps (1 - w) a + w b, exact at w = 0 and 1: two cells sharing a face compute bitwise
  // the same value on it from the same coordinates.
  double value(const CellPoint& q) const;
  // d/dq: each component a bilinear interpolant of the differences along the four edges parallel
  // to its axis.
  CellPoint gradient(const CellPoint& q) const;
  // Along q(t) = start + t direction the interpolant is a cubic in t. Its first zero in
  // [0, length], given its values at the two ends (`value` at the points where the ray crosses the
  // cell's faces, so that neighbouring cells agree there); false when there is none.
  bool firstZero(const CellPoint& start, const CellPoint& direction, double length, double valueAtStart,
                 double valueAtEnd, double& t) const;

 private:
  std::array<double, 8> f_;
};

}  // namespace columba
