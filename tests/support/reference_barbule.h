#pragma once
// Test-only reference of the barbule BSDF (Huang et al. 2022; docs/model.md), written plainly in
// the model's terms and in double precision: the cross-section's lit normals found by casting
// rays against the neighbouring ellipses, D_phi = rho / H, the R lobe from its formula, the TRT
// lobe as an adaptive Gauss-Legendre integral over the normal angle phi (dh = rho cos dphi) of a
// Gauss-Legendre mean over the longitudinal angle, and the coverage r with T = 1 - r. It shares no
// code with the production BSDF (no offset parametrisation, lanes, Taylor or polynomial shortcuts),
// so that tests can judge the production's approximations against it.
//
// Frame as in the model: z = vane normal, y = barbule axis, x across the barbules; in-plane
// coordinates (u, v) = (z, x), in-plane angles gamma = atan2(x, z) from u toward v. Normal angles
// phi are in the ellipse's own frame, turned by mu from the world's.
#include <cmath>
#include <vector>
#include "support/reference_thin_film.h"

namespace columba::reference {

struct Direction {
  double x = 0.0, y = 0.0, z = 1.0;
};

// Gauss-Legendre rule on [-1, 1] (nodes by Newton's method on the Legendre recurrence).
struct GaussRule {
  std::vector<double> nodes, weights;
};
GaussRule gaussLegendreRule(int n);
// Two rules whose agreement decides an adaptive subdivision.
struct RulePair {
  GaussRule low, high;
};

// Half-range of the longitudinal normal angles, 0.025 pi.
inline constexpr double kThetaD = 0.025 * M_PI;

struct BarbuleModel {
  double b = 0.25, phi0 = -0.37, phi1 = 2.64, mu = -0.35, H = 1.25;
  double heightUm = 0.6;
  double filmA = 1.532, filmB = 5890.0;  // film index by Cauchy: n = A + B / lambda^2 (nm)
  double nOutside = kAirIndex;
  double filmIndex(double lambdaNm) const { return filmA + filmB / (lambdaNm * lambdaNm); }
};

// Interval [lo, hi] of normal angles.
struct AngleInterval {
  double lo, hi;
};

// Mean over the longitudinal angles |theta| < thetaD with density proportional to
// (A cos(theta) + B sin(theta))+, the projected area of the normals at one phi from a direction
// with in-plane projection A and longitudinal component B.
struct LongitudinalMoments {
  double mass = 0.0;          // integral of (A cos + B sin)+ dtheta
  double mean = 0.0;          // mean theta
  double lo = 0.0, hi = 0.0;  // where the density is positive
  // The model's longitudinal shadowing S: the cross-section's projected area 2 A sin(thetaD)
  // over the visible normals' mass (1 unless the range is clipped).
  double shadowing() const { return mass > 0.0 ? 2.0 * A * std::sin(kThetaD) / mass : 0.0; }
  double A = 0.0, B = 0.0;
};
LongitudinalMoments longitudinalMoments(double A, double B);

class BarbuleReference {
 public:
  // The TRT integrals (over phi, and over theta inside) are adaptive Gauss-Legendre: a piece is
  // halved until its `baseNodes` and 2 `baseNodes` rules (half as many over theta, a range of at
  // most 9 degrees) agree to `tolerance` relative to the integral.
  explicit BarbuleReference(const BarbuleModel& model, int baseNodes = 8, double tolerance = 1e-6);

  // The spacing used: H, raised to the contact spacing where neighbours would overlap.
  double spacing() const { return H_; }
  static double contactSpacing(double b, double mu);

  // Point of the central ellipse (world in-plane coordinates) with local outward normal angle phi.
  void pointWithNormal(double phi, double& u, double& v) const;
  double radiusOfCurvature(double phi) const;
  bool onReflectiveArc(double phi) const;
  // Whether the ray from the point with normal phi toward the world in-plane angle gamma meets a
  // neighbouring barbule (the copies at +-H and +-2H).
  bool shadowed(double phi, double gamma) const;
  // Lit from gamma: faces it, lies on the reflective arc and no neighbour blocks it.
  bool lit(double phi, double gamma) const;
  // The lit normal angles, as intervals within the half facing gamma, (gamma - mu) +- pi/2.
  std::vector<AngleInterval> litNormals(double gamma) const;
  // Offset of the point with normal phi across the direction gamma (gamma turned by +90 degrees).
  double offset(double phi, double gamma) const;
  // Width of the lit offsets, and the same as the integral of rho cos(gamma - mu - phi) dphi.
  double litWidth(double gamma) const;
  double litWidthByIntegral(double gamma) const;
  // Coverage r: lit width over the projected period H |cos gamma|, at most 1; w below the vane
  // uses -w (the same line through the layer).
  double coverage(const Direction& w) const;

  // f_R per wavelength; the same with the film's reflectance replaced by its envelope (the scale
  // of an interference error); |d f_R / d ln(phase)|, what a relative error of the film's phase does
  // to it; the sum of |d f_R / dx| over the cosines x that an implementation computes as dot
  // products of unit vectors (omega_i . m for the film, the projections of omega_i and omega_o on
  // the normal's in-plane part for S) and over the normal angle phi_m times |omega_i + omega_o|
  // (the half vector normalises that sum), what a rounding of those by 1 does to it; and how far
  // the half vector's normal is from a jump of G or D (radians in phi, and in theta from thetaD,
  // negative outside), for tests to leave out ambiguous pairs.
  struct Reflection {
    std::vector<double> value, envelope, phaseSensitivity, roundingSensitivity;
    double phiMargin = 0.0, thetaMargin = 0.0;
  };
  Reflection reflection(const Direction& wi, const Direction& wo, const std::vector<double>& lambdas) const;

  // f_TRT per wavelength, `melanin` the melanin layer's reflectance at each wavelength; the width
  // of the offsets lit from both directions; and d f_TRT / dh at their ends, summed (what an error
  // in where those ends are does to it).
  struct TRT {
    std::vector<double> value, endDensity;
    double commonWidth = 0.0;
  };
  TRT trt(const Direction& wi, const Direction& wo, const std::vector<double>& lambdas,
          const std::vector<double>& melanin) const;
  // Width of the offsets across omega_i (its in-plane part) of the points lit from both directions.
  double commonWidth(const Direction& wi, const Direction& wo) const;
  // The normal angles lit from both in-plane directions, within the half facing gammaI.
  std::vector<AngleInterval> commonNormals(double gammaI, double gammaO) const;

 private:
  BarbuleModel m_;
  double H_;
  bool wholeEllipse_;
  RulePair rules_, thetaRules_;
  double tolerance_;
};

// gamma = atan2(x, z), the world in-plane angle of a direction.
inline double inPlaneAngle(const Direction& w) { return std::atan2(w.x, w.z); }

}  // namespace columba::reference
