#pragma once
// Normal distribution of the barbule surface and its visible normals (DESIGN.md §5.3, §5.6).
//
// A normal m is described by its in-plane part, the unit 2D normal n = (n_u, n_v) of the
// cross-section ellipse (local normal angle phi), and its longitudinal angle theta out of the
// cross-section plane: m = (cos(theta) n_v, sin(theta), cos(theta) n_u). In these coordinates
// dm = cos(theta) dtheta dphi and
//   D(m) = D_phi(phi) D_theta(theta) / cos(theta),  D_phi = rho(phi) / H,  D_theta = 1 / (2 sin thetaD)
// on the reflective arc and |theta| < thetaD, where rho is the ellipse's radius of curvature.
//
// Visible normals from a direction w: the offset h is uniform over the lit arc (density
// rho cos(gamma - phi - mu) / (lit width) in phi), then theta given phi has density proportional
// to D_theta (w . m) = D_theta (A cos(theta) + B sin(theta)), clipped to where it is positive.
#include "barbule/cross_section.h"
#include "core/vector.h"

namespace columba {

// Half-range of the barbules' longitudinal normal angles (their slight bending along t), 0.025 pi,
// and its sine, cosine and tangent (from the angle in double, each rounded once to float).
inline constexpr double kBarbuleThetaDInDouble = 0.025 * kPiDouble;
inline constexpr float kBarbuleThetaD = float(kBarbuleThetaDInDouble);
inline constexpr float kSinBarbuleThetaD = float(constexprSin(kBarbuleThetaDInDouble));
inline constexpr float kCosBarbuleThetaD = float(constexprCos(kBarbuleThetaDInDouble));
inline constexpr float kTanBarbuleThetaD =
    float(constexprSin(kBarbuleThetaDInDouble) / constexprCos(kBarbuleThetaDInDouble));

// The 2D part of a 3D direction w = (x, y, z): unit in-plane direction (z, x) / |(z, x)| and
// cos(theta) = |(z, x)|.
struct InPlaneDirection {
  Vec2 dir;
  float cosTheta = 0.0f;
};
inline InPlaneDirection inPlane(const Vec3& w) {
  InPlaneDirection p;
  p.cosTheta = std::sqrt(w.z * w.z + w.x * w.x);
  p.dir = p.cosTheta > 0.0f ? Vec2(w.z / p.cosTheta, w.x / p.cosTheta) : Vec2(1.0f, 0.0f);
  return p;
}

// The 3D normal with world in-plane normal n (unit) and longitudinal angle theta.
inline Vec3 barbuleNormal(Vec2 worldNormal, float cosTheta, float sinTheta) {
  return {cosTheta * worldNormal.y, sinTheta, cosTheta * worldNormal.x};
}

// w . m for the normal m = barbuleNormal(n, 1, 0) of world in-plane normal n and longitudinal angle
// 0: the in-plane projection cos(theta_w) cos(gamma_w - gamma_n), the A of LongitudinalDensity.
// N is a Vec2, or Vec2Lanes for four normals at once.
template <typename N>
inline auto inPlaneProjection(const Vec3& w, const N& n) {
  return w.z * n.x + w.x * n.y;
}

// An angle with its cosine and sine.
struct AngleCosSin {
  float theta, cosTheta, sinTheta;
};

// Density of theta on [-thetaD, thetaD] proportional to (A cos(theta) + B sin(theta))+, the
// projected area of the normals at one phi seen from a direction with in-plane part
// A = cos(theta_w) cos(gamma_w - phi - mu) > 0 and longitudinal part B = sin(theta_w).
class LongitudinalDensity {
 public:
  LongitudinalDensity(float A, float B);

  float thetaMin() const { return thetaMin_; }
  float thetaMax() const { return thetaMax_; }
  // Inverse CDF in closed form: theta = delta + asin(...), delta = atan2(B, A).
  float sample(float u) const { return clampf(angleAtMass(u * mass_).theta, thetaMin_, thetaMax_); }
  // The angle where the density's mass from thetaMin reaches `mass`, with its cosine and sine, not
  // clamped to the range: those of theta - delta and delta combined (one asin, no atan2 or sincos).
  AngleCosSin angleAtMass(float mass) const;
  float pdf(float theta) const;
  // The density's mass below theta within the range, and on the whole range (the projected area of
  // the normals at this phi seen from w, over D_theta).
  float massBelow(float theta) const { return A_ * std::sin(theta) - B_ * std::cos(theta) - primitiveMin_; }
  float mass() const { return mass_; }
  // The same density at the normal m with w . m = `projection`, for m within |theta| < thetaD:
  // there A cos(theta) + B sin(theta) is w . m, and the clipped range is exactly where it is > 0.
  float pdfFromProjection(float projection) const { return mass_ > 0.0f ? std::max(projection, 0.0f) / mass_ : 0.0f; }
  // Mean of theta under this density (a one-node rule placed there is exact for linear integrands).
  float mean() const;
  // Longitudinal shadowing: A / integral of D_theta (w . m)+ dtheta. It is 1 unless the range is
  // clipped (w nearly grazing the normals' arc), and makes the projected area of the visible
  // normals equal the projected area A of the cross-section's normal, as a Smith term does.
  float shadowing() const { return shadowing_; }

 private:
  float A_, B_;
  float thetaMin_, thetaMax_;
  float primitiveMin_;  // F(thetaMin), F(theta) = A sin(theta) - B cos(theta)
  float mass_;          // F(thetaMax) - F(thetaMin)
  float shadowing_;
};

// Whether every normal with |theta| <= thetaD at this phi faces w (A cos(theta) + B sin(theta) >= 0
// on the whole range): the usual case, where the density needs no clipping.
inline bool facesWholeRange(float A, float B) { return std::abs(B) * kTanBarbuleThetaD <= A; }
// LongitudinalDensity(A, B).shadowing() and .mean(), short-cut in that usual case.
inline float longitudinalShadowing(float A, float B) {
  return facesWholeRange(A, B) ? 1.0f : LongitudinalDensity(A, B).shadowing();
}
// LongitudinalDensity(A, B).mean() for four normals seen from one direction (A per lane, B
// shared); unclipped it is (B / A) (sin(thetaD) - thetaD cos(thetaD)) / sin(thetaD).
inline FloatLanes meanLongitudinalAngles(FloatLanes A, float B) {
  // The scale as first written, to six digits: 8e-6 above the computed 0.0020570136, and kept so
  // that rendered images stay as they were.
  constexpr float kUnclippedMeanScale = 0.00205703f;
  constexpr double kThetaD = kBarbuleThetaDInDouble;
  constexpr double kComputedScale = 1.0 - kThetaD * constexprCos(kThetaD) / constexprSin(kThetaD);
  static_assert(kUnclippedMeanScale > kComputedScale && kUnclippedMeanScale < kComputedScale * (1.0 + 1e-5));
  FloatLanes theta = B / A * kUnclippedMeanScale;
  for (int j = 0; j < kLaneCount; ++j)
    if (!facesWholeRange(A[j], B)) theta[j] = LongitudinalDensity(A[j], B).mean();
  return theta;
}

// D(m) of a normal m on the reflective arc with |theta_m| < thetaD, from its in-plane normal in the
// ellipse's frame and cos(theta_m): D_phi D_theta / cos(theta_m) with D_phi = rho / H.
inline float barbuleNDF(const BarbuleCrossSection& geometry, Vec2 localNormal, float cosTheta) {
  return geometry.radiusOfCurvature(localNormal) / geometry.spacing() / (2.0f * kSinBarbuleThetaD * cosTheta);
}

struct VisibleNormal {
  Vec3 m;
  Vec2 localNormal;  // in-plane normal in the ellipse's frame
};
// A visible normal from w (w.z > 0; `arc` = geometry.litArc(inPlane(w).dir), not empty): the
// offset from u.x, theta from u.y.
VisibleNormal sampleVisibleNormal(const BarbuleCrossSection& geometry, const LitArc& arc, const Vec3& w, Vec2 u);
// Solid-angle density of sampleVisibleNormal producing m, for an m it can produce: lit from w
// (w . m > 0, `arc` not empty, m's in-plane normal on the lit part of `arc`) with
// |theta_m| < thetaD. Takes what the caller has computed for those checks: inPlane(w).cosTheta,
// w . m, inPlane(m) and m's in-plane normal in the ellipse's frame.
float visibleNormalPdf(const BarbuleCrossSection& geometry, const LitArc& arc, const Vec3& w, float wCosTheta,
                       float wDotM, const InPlaneDirection& mPlane, Vec2 mLocal);

}  // namespace columba
