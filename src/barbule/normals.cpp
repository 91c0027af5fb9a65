#include "barbule/normals.h"

namespace columba {

LongitudinalDensity::LongitudinalDensity(float A, float B)
    : A_(A), B_(B), thetaMin_(-kBarbuleThetaD), thetaMax_(kBarbuleThetaD) {
  float atMax = A * kCosBarbuleThetaD + B * kSinBarbuleThetaD;
  float atMin = A * kCosBarbuleThetaD - B * kSinBarbuleThetaD;
  if (atMax >= 0.0f && atMin >= 0.0f) {
    // The whole range faces w (the usual case): the projected area is exactly A.
    primitiveMin_ = -A * kSinBarbuleThetaD - B * kCosBarbuleThetaD;
    mass_ = 2.0f * A * kSinBarbuleThetaD;
    shadowing_ = 1.0f;
    return;
  }
  if (atMax <= 0.0f && atMin <= 0.0f) {
    primitiveMin_ = mass_ = shadowing_ = 0.0f;
    thetaMin_ = thetaMax_ = 0.0f;
    return;
  }
  // One end faces away: clip at the zero of A cos(theta) + B sin(theta), where tan(theta) = -A / B.
  float zero = std::atan(-A / B);
  if (atMin < 0.0f)
    thetaMin_ = zero;
  else
    thetaMax_ = zero;
  auto primitive = [&](float theta) { return A * std::sin(theta) - B * std::cos(theta); };
  primitiveMin_ = primitive(thetaMin_);
  mass_ = std::max(primitive(thetaMax_) - primitiveMin_, 0.0f);
  shadowing_ = mass_ > 0.0f ? clampf(2.0f * A * kSinBarbuleThetaD / mass_, 0.0f, 1.0f) : 0.0f;
}

AngleCosSin LongitudinalDensity::angleAtMass(float mass) const {
  // F(theta) = A sin(theta) - B cos(theta) = R sin(theta - delta) with R = |(A, B)|, cos(delta) = A / R
  // and sin(delta) = B / R; the density is proportional to F'. On asin's branch theta - delta has
  // the sine s below and the cosine sqrt(1 - s^2).
  const float R = std::sqrt(A_ * A_ + B_ * B_);
  const float s = clampf((primitiveMin_ + mass) / R, -1.0f, 1.0f), c = std::sqrt(1.0f - s * s);
  AngleCosSin angle;
  angle.cosTheta = (A_ * c - B_ * s) / R;
  angle.sinTheta = (B_ * c + A_ * s) / R;
  // Beyond +-pi/2 theta lies outside every range the density can have (within +-thetaD), and
  // clamping puts it at the range's end whichever value stands for it.
  angle.theta = angle.cosTheta > 0.0f ? safeAsin(angle.sinTheta) : std::copysign(kHalfPi, angle.sinTheta);
  return angle;
}

float LongitudinalDensity::mean() const {
  if (!(mass_ > 0.0f)) return 0.5f * (thetaMin_ + thetaMax_);
  if (shadowing_ == 1.0f && thetaMin_ == -kBarbuleThetaD && thetaMax_ == kBarbuleThetaD)
    return B_ / A_ * (kSinBarbuleThetaD - kBarbuleThetaD * kCosBarbuleThetaD) / kSinBarbuleThetaD;
  // Antiderivative of theta (A cos(theta) + B sin(theta)).
  auto moment = [&](float t) {
    float c = std::cos(t), s = std::sin(t);
    return A_ * (t * s + c) + B_ * (s - t * c);
  };
  return (moment(thetaMax_) - moment(thetaMin_)) / mass_;
}

float LongitudinalDensity::pdf(float theta) const {
  if (!(mass_ > 0.0f) || theta < thetaMin_ || theta > thetaMax_) return 0.0f;
  return std::max(A_ * std::cos(theta) + B_ * std::sin(theta), 0.0f) / mass_;
}

VisibleNormal sampleVisibleNormal(const BarbuleCrossSection& geometry, const LitArc& arc, const Vec3& w, Vec2 u) {
  VisibleNormal out;
  out.localNormal = geometry.normalAt(geometry.pointAt(arc, arc.hMin + u.x * arc.width()));
  Vec2 n = geometry.toWorld(out.localNormal);
  LongitudinalDensity longitudinal(inPlaneProjection(w, n), w.y);
  float theta = longitudinal.sample(u.y);
  out.m = barbuleNormal(n, std::cos(theta), std::sin(theta));
  return out;
}

float visibleNormalPdf(const BarbuleCrossSection& geometry, const LitArc& arc, const Vec3& w, float wCosTheta,
                       float wDotM, const InPlaneDirection& mPlane, Vec2 mLocal) {
  // phi: dh = rho cos(gamma - phi - mu) dphi with h uniform on the lit width.
  float A = inPlaneProjection(w, mPlane.dir);
  float pdfPhi = geometry.radiusOfCurvature(mLocal) * (A / wCosTheta) / arc.width();
  // theta given phi: (w . m) / mass, and dm = cos(theta) dtheta dphi.
  float pdfTheta = LongitudinalDensity(A, w.y).pdfFromProjection(wDotM);
  return pdfPhi * pdfTheta / mPlane.cosTheta;
}

}  // namespace columba
