#include "shapes/trilinear_cell.h"

#include <algorithm>
#include <cmath>

#include "core/math.h"

namespace columba {

namespace {

double mix(double a, double b, double w) { return (1.0 - w) * a + w * b; }
double bilinear(double f00, double f10, double f01, double f11, double u, double v) {
  return mix(mix(f00, f10, u), mix(f01, f11, u), v);
}

// c[0] + c[1] t + c[2] t^2 + c[3] t^3.
struct Cubic {
  double c[4];
  double operator()(double t) const { return ((c[3] * t + c[2]) * t + c[1]) * t + c[0]; }
  double slope(double t) const { return (3.0 * c[3] * t + 2.0 * c[2]) * t + c[1]; }
};

// The zero of `f` in [lo, hi], where it is monotonic and changes sign (f(lo) = fLo != 0, f(hi) =
// fHi): Newton's steps kept inside the shrinking bracket, bisection where a step would leave it.
// Bisection alone reaches the tolerance in about 40 steps, so 64 bound the loop.
double zeroInBracket(const Cubic& f, double lo, double hi, double fLo, double fHi, double tolerance) {
  double t = lo + (hi - lo) * (fLo / (fLo - fHi));  // the secant: exact where f is linear
  if (!(t >= lo && t <= hi)) t = 0.5 * (lo + hi);
  for (int step = 0; step < 64; ++step) {
    const double ft = f(t);
    if (ft == 0.0) break;
    ((ft < 0.0) == (fLo < 0.0) ? lo : hi) = t;
    double next = t - ft / f.slope(t);
    if (!(next > lo && next < hi)) next = 0.5 * (lo + hi);
    const bool converged = std::abs(next - t) <= tolerance;
    t = next;
    if (converged) break;
  }
  return t;
}

}  // namespace

double TrilinearCell::value(const CellPoint& q) const {
  return mix(bilinear(f_[0], f_[1], f_[2], f_[3], q[0], q[1]), bilinear(f_[4], f_[5], f_[6], f_[7], q[0], q[1]), q[2]);
}

CellPoint TrilinearCell::gradient(const CellPoint& q) const {
  const auto& f = f_;
  return {bilinear(f[1] - f[0], f[3] - f[2], f[5] - f[4], f[7] - f[6], q[1], q[2]),
          bilinear(f[2] - f[0], f[3] - f[1], f[6] - f[4], f[7] - f[5], q[0], q[2]),
          bilinear(f[4] - f[0], f[5] - f[1], f[6] - f[2], f[7] - f[3], q[0], q[1])};
}

bool TrilinearCell::firstZero(const CellPoint& start, const CellPoint& direction, double length, double valueAtStart,
                              double valueAtEnd, double& t) const {
  // f = k0 + k1 x + k2 y + k3 xy + k4 z + k5 xz + k6 yz + k7 xyz; along the ray the constant and
  // linear terms are the value and the directional derivative at the start, the higher ones come
  // from the mixed terms alone.
  const auto& f = f_;
  const double k3 = f[3] - f[2] - f[1] + f[0], k5 = f[5] - f[4] - f[1] + f[0], k6 = f[6] - f[4] - f[2] + f[0];
  const double k7 = f[7] - f[6] - f[5] + f[4] - f[3] + f[2] + f[1] - f[0];
  const auto [ax, ay, az] = start;
  const auto [bx, by, bz] = direction;
  const CellPoint g = gradient(start);
  const Cubic cubic{{value(start), g[0] * bx + g[1] * by + g[2] * bz,
                     k3 * bx * by + k5 * bx * bz + k6 * by * bz + k7 * (bx * by * az + bx * ay * bz + ax * by * bz),
                     k7 * bx * by * bz}};

  // Between the zeros of its derivative the cubic is monotonic: the first piece that changes
  // sign holds the first zero.
  double ends[4] = {0.0, 0.0, 0.0, 0.0};
  int count = 1;
  double r0, r1;
  if (cubic.c[3] != 0.0 && solveQuadratic(3.0 * cubic.c[3], 2.0 * cubic.c[2], cubic.c[1], r0, r1)) {
    for (double r : {r0, r1})
      if (r > 0.0 && r < length) ends[count++] = r;
  } else if (cubic.c[3] == 0.0 && cubic.c[2] != 0.0) {
    const double r = -cubic.c[1] / (2.0 * cubic.c[2]);
    if (r > 0.0 && r < length) ends[count++] = r;
  }
  ends[count++] = length;
  double fLo = valueAtStart;
  for (int i = 0; i + 1 < count; ++i) {
    const double lo = ends[i], hi = ends[i + 1];
    const double fHi = i + 2 == count ? valueAtEnd : cubic(hi);
    if (fLo == 0.0) {
      t = lo;
      return true;
    }
    if (fLo * fHi <= 0.0) {
      t = zeroInBracket(cubic, lo, hi, fLo, fHi, 1e-12 * length);
      return true;
    }
    fLo = fHi;
  }
  return false;
}

}  // namespace columba
