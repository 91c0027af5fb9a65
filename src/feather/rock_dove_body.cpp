#include "feather/rock_dove_body.h"

#include <algorithm>
#include <cmath>

#include "core/math.h"

namespace columba {

namespace {

// p in the ellipsoid's own frame (rotated back by its pitch), before its scaling.
Vec3 toFrame(const Ellipsoid& e, const Vec3& p) {
  const Vec3 d = p - e.centre;
  const float c = std::cos(e.pitch), s = std::sin(e.pitch);
  return Vec3(c * d.x + s * d.y, -s * d.x + c * d.y, d.z);
}

Vec3 fromFrame(const Ellipsoid& e, const Vec3& q) {
  const float c = std::cos(e.pitch), s = std::sin(e.pitch);
  return e.centre + Vec3(c * q.x - s * q.y, s * q.x + c * q.y, q.z);
}

Ellipsoid along(Vec3 centre, float length, float radius, float pitch) {
  return {centre, {length, radius, radius}, pitch};
}

}  // namespace

float Ellipsoid::implicit(const Vec3& p) const {
  const Vec3 q = toFrame(*this, p);
  const Vec3 v(q.x / radii.x, q.y / radii.y, q.z / radii.z);
  return dot(v, v) - 1.0f;
}

Vec3 Ellipsoid::normal(const Vec3& p) const {
  const Vec3 q = toFrame(*this, p);
  const Vec3 g(q.x / (radii.x * radii.x), q.y / (radii.y * radii.y), q.z / (radii.z * radii.z));
  const float c = std::cos(pitch), s = std::sin(pitch);
  return normalize(Vec3(c * g.x - s * g.y, s * g.x + c * g.y, g.z));
}

Vec3 Ellipsoid::point(float theta, float phi) const {
  const Vec3 unit(std::sin(theta) * std::cos(phi), std::cos(theta), std::sin(theta) * std::sin(phi));
  return fromFrame(*this, Vec3(unit.x * radii.x, unit.y * radii.y, unit.z * radii.z));
}

// Sizes in centimetres: 31 cm from bill tip to tail tip, a 10 cm tail, a 2 cm bill and a head
// about 2.5 cm high under its feathers (docs/rock-dove.md gives the measurements, their sources
// and what is assumed).
RockDoveBody::RockDoveBody() {
  const Vec3 base(kNeckBaseX, kNeckBaseY, 0.0f), top(kNeckTopX, kNeckTopY, 0.0f);
  const float neckPitch = std::atan2(top.y - base.y, top.x - base.x);
  auto neckAt = [&](float t) { return base + (top - base) * t; };
  parts_ = {
      {"torso", {{-3.5f, 1.0f, 0.0f}, {8.5f, 5.6f, 5.6f}, 0.15f}, Plumage::Grey},
      {"breast", {{2.5f, 2.6f, 0.0f}, {4.8f, 5.4f, 5.0f}, 0.3f}, Plumage::Grey},
      // The neck as one ellipsoid from inside the breast to inside the head, so that no crease
      // runs round it.
      {"neck", along(neckAt(0.45f), 5.2f, 3.0f, neckPitch), Plumage::Iridescent},
      {"head", {{8.6f, 12.3f, 0.0f}, {2.1f, 1.75f, 1.65f}, 0.1f}, Plumage::Grey},
      {"left wing", {{-5.0f, 3.0f, 3.3f}, {9.5f, 3.6f, 2.3f}, -0.05f}, Plumage::Grey},
      {"right wing", {{-5.0f, 3.0f, -3.3f}, {9.5f, 3.6f, 2.3f}, -0.05f}, Plumage::Grey},
      {"tail", {{-13.4f, -1.3f, 0.0f}, {5.0f, 0.7f, 3.0f}, -0.15f}, Plumage::Grey},
      {"beak", {{11.3f, 11.9f, 0.0f}, {1.0f, 0.28f, 0.26f}, -0.25f}, Plumage::None},
      // The cere: the bare, swollen skin over the nostrils at the top of the beak's base.
      {"cere", {{10.45f, 12.45f, 0.0f}, {0.5f, 0.3f, 0.32f}, -0.1f}, Plumage::None},
      {"left eye", {{9.5f, 12.75f, 1.3f}, {0.36f, 0.36f, 0.36f}, 0.0f}, Plumage::None},
      {"right eye", {{9.5f, 12.75f, -1.3f}, {0.36f, 0.36f, 0.36f}, 0.0f}, Plumage::None},
  };
}

float RockDoveBody::inside(const Vec3& p) const {
  float lowest = INFINITY;
  for (const BodyPart& part : parts_)
    if (part.plumage != Plumage::None) lowest = std::min(lowest, part.shape.implicit(p));
  return lowest;
}

bool RockDoveBody::onSurface(const Vec3& p, size_t index) const {
  for (size_t i = 0; i < parts_.size(); ++i)
    if (i != index && parts_[i].plumage != Plumage::None && parts_[i].shape.implicit(p) < 0.0f) return false;
  return true;
}

bool RockDoveBody::face(const Vec3& p, bool ring) const {
  for (const BodyPart& part : parts_) {
    if (part.plumage != Plumage::None) continue;
    const bool eye = part.name.find("eye") != std::string::npos;
    const float margin = ring ? (eye ? 0.25f : 1.0f) : (eye ? 0.03f : 0.0f);
    if (eye ? length(p - part.shape.centre) < part.shape.radii.x + margin : part.shape.implicit(p) < margin)
      return true;
  }
  return false;
}

float RockDoveBody::neckFraction(const Vec3& p) const {
  const Vec2 base(kNeckBaseX, kNeckBaseY), axis = Vec2(kNeckTopX, kNeckTopY) - base;
  const Vec2 d = Vec2(p.x, p.y) - base;
  return clampf((d.x * axis.x + d.y * axis.y) / (axis.x * axis.x + axis.y * axis.y), 0.0f, 1.0f);
}

Vec3 RockDoveBody::featherDirection(const Vec3& p, size_t index) const {
  const BodyPart& part = parts_[index];
  Vec3 flow;
  if (part.plumage == Plumage::Iridescent)
    flow = Vec3(kNeckBaseX - kNeckTopX, kNeckBaseY - kNeckTopY, 0.0f);  // down the neck
  else if (part.name == "breast")
    flow = Vec3(-0.5f, -1.0f, 0.0f);
  else if (part.name == "head")
    flow = Vec3(-1.0f, -0.25f, 0.0f);
  else
    flow = Vec3(-1.0f, -0.1f, 0.0f);
  const Vec3 n = part.shape.normal(p);
  Vec3 tangent = flow - n * dot(flow, n);
  if (lengthSquared(tangent) < 1e-8f) tangent = cross(n, Vec3(0.0f, 0.0f, 1.0f));  // flow along the normal
  return normalize(tangent);
}

}  // namespace columba
