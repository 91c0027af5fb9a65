#include "shapes/feather_shape.h"

#include <tbb/parallel_for.h>

#include <cmath>
#include <limits>
#include "barbule/parameters.h"
#include "shapes/embree_user_geometry.h"
#include "shapes/feather_barbule_values.h"

namespace columba {

namespace {

// Width of the barb at vertex `i` relative to its base: quadratic, so the vane stays closed
// over most of a barb's length and opens into a fringe toward the tips.
float taper(int i) {
  float u = float(i) / float(kBarbSegments);
  return 1.0f - (1.0f - FeatherShape::kTipWidthFraction) * u * u;
}

// Any unit vector perpendicular to the unit vector `a`, as close as possible to `v`.
Vec3 perpendicularTo(const Vec3& a, const Vec3& v) {
  Vec3 p = v - a * dot(v, a);
  if (lengthSquared(p) > 1e-12f) return normalize(p);
  return Frame::fromNormal(a).s;
}

float linearScale(const Transform& t) {
  const auto& m = t.matrix().m;
  double det = m[0][0] * (m[1][1] * m[2][2] - m[1][2] * m[2][1]) - m[0][1] * (m[1][0] * m[2][2] - m[1][2] * m[2][0]) +
               m[0][2] * (m[1][0] * m[2][1] - m[1][1] * m[2][0]);
  return float(std::cbrt(std::abs(det)));
}

template <typename T>
void gather(std::vector<T>& values, const std::vector<uint32_t>& indices) {
  if (values.empty()) return;
  std::vector<T> out(indices.size());
  tbb::parallel_for(size_t(0), indices.size(), [&](size_t i) { out[i] = values[indices[i]]; });
  values = std::move(out);
}

void boundsCallback(const RTCBoundsFunctionArguments* args) {
  const auto* shape = static_cast<const FeatherShape*>(args->geometryUserPtr);
  Vec3 lo, hi;
  shape->stripBounds(args->primID, lo, hi);
  RTCBounds* b = args->bounds_o;
  b->lower_x = lo.x;
  b->lower_y = lo.y;
  b->lower_z = lo.z;
  b->upper_x = hi.x;
  b->upper_y = hi.y;
  b->upper_z = hi.z;
}

// The rays of a packet of width kWidth, or of args->N when kWidth is 0. rtcIntersect1 passes
// single rays: with the width known at compile time, the packet indexing folds away.
template <unsigned kWidth>
void intersectPacket(const RTCIntersectFunctionNArguments* args) {
  const auto* shape = static_cast<const FeatherShape*>(args->geometryUserPtr);
  const unsigned N = kWidth ? kWidth : args->N;
  RTCRayN* ray = RTCRayHitN_RayN(args->rayhit, N);
  RTCHitN* hit = RTCRayHitN_HitN(args->rayhit, N);
  for (unsigned i = 0; i < N; ++i) {
    if (!args->valid[i]) continue;
    Vec3 o(RTCRayN_org_x(ray, N, i), RTCRayN_org_y(ray, N, i), RTCRayN_org_z(ray, N, i));
    Vec3 d(RTCRayN_dir_x(ray, N, i), RTCRayN_dir_y(ray, N, i), RTCRayN_dir_z(ray, N, i));
    StripHit h;
    if (!shape->intersectStrip(args->primID, o, d, RTCRayN_tnear(ray, N, i), RTCRayN_tfar(ray, N, i), h)) continue;
    RTCRayN_tfar(ray, N, i) = h.t;
    // interaction() derives the normal from sin(phi); Ng is left defined, not computed.
    RTCHitN_Ng_x(hit, N, i) = 0.0f;
    RTCHitN_Ng_y(hit, N, i) = 0.0f;
    RTCHitN_Ng_z(hit, N, i) = 0.0f;
    RTCHitN_u(hit, N, i) = h.axial;
    RTCHitN_v(hit, N, i) = h.sinAngle;
    RTCHitN_primID(hit, N, i) = args->primID;
    RTCHitN_geomID(hit, N, i) = args->geomID;
    for (unsigned l = 0; l < RTC_MAX_INSTANCE_LEVEL_COUNT; ++l) RTCHitN_instID(hit, N, i, l) = args->context->instID[l];
  }
}

void intersectCallback(const RTCIntersectFunctionNArguments* args) {
  if (args->N == 1)
    intersectPacket<1>(args);
  else
    intersectPacket<0>(args);
}

void occludedCallback(const RTCOccludedFunctionNArguments* args) {
  const auto* shape = static_cast<const FeatherShape*>(args->geometryUserPtr);
  const unsigned N = args->N;
  for (unsigned i = 0; i < N; ++i) {
    if (!args->valid[i]) continue;
    Vec3 o(RTCRayN_org_x(args->ray, N, i), RTCRayN_org_y(args->ray, N, i), RTCRayN_org_z(args->ray, N, i));
    Vec3 d(RTCRayN_dir_x(args->ray, N, i), RTCRayN_dir_y(args->ray, N, i), RTCRayN_dir_z(args->ray, N, i));
    StripHit h;
    if (shape->intersectStrip(args->primID, o, d, RTCRayN_tnear(args->ray, N, i), RTCRayN_tfar(args->ray, N, i), h))
      RTCRayN_tfar(args->ray, N, i) = -std::numeric_limits<float>::infinity();
  }
}

}  // namespace

FeatherShape::FeatherShape(FeatherPlyData ply, const FeatherShapeParams& params) {
  barbCount_ = ply.barbCount();
  const Transform& toWorld = params.toWorld;
  tbb::parallel_for(size_t(0), ply.positions.size(), [&](size_t i) {
    ply.positions[i] = toWorld.point(ply.positions[i]);
    ply.normals[i] = normalize(toWorld.normal(ply.normals[i]));
  });
  if (!ply.barbsAreSequential()) {
    // Make every barb's vertices contiguous (files may share or reorder vertices).
    gather(ply.positions, ply.barbIndices);
    gather(ply.normals, ply.barbIndices);
    gather(ply.barbuleH, ply.barbIndices);
    gather(ply.barbuleMu, ply.barbIndices);
    gather(ply.barbuleHeight, ply.barbIndices);
    gather(ply.layerStack, ply.barbIndices);
  }
  layerStacks_ = std::move(ply.layerStack);
  given_.largestLayerStack = ply.largestLayerStack;
  given_.largestLayerStackAt = {ply.path, ply.largestLayerStackLine};
  given_.largestLayerStackElement = "vertex " + std::to_string(ply.largestLayerStackVertex);
  if (ply.hasBarbuleValues()) {
    // In the model's terms and interleaved, so that a hit reads its parameters from one place.
    barbuleValues_.resize(ply.positions.size());
    tbb::parallel_for(size_t(0), barbuleValues_.size(), [&](size_t i) {
      barbuleValues_[i] = {modelSpacingFromFile(ply.barbuleH[i]), modelTiltFromFile(ply.barbuleMu[i]),
                           ply.barbuleHeight[i]};
    });
  }

  given_.everywhere.add(kBarbuleSpacingAttribute);
  bool zeroTiltSegment = false, zeroThicknessSegment = false;
  for (size_t i = 0; i + 1 < barbuleValues_.size(); ++i) {
    if (i % kBarbVertices == kBarbSegments) continue;  // the last vertex of a barb starts no segment
    const BarbuleValues &a = barbuleValues_[i], &b = barbuleValues_[i + 1];
    zeroTiltSegment |= a.mu == 0.0f && b.mu == 0.0f;
    zeroThicknessSegment |= a.height == 0.0f && b.height == 0.0f;
  }
  if (!zeroTiltSegment) given_.everywhere.add(kBarbuleTiltAttribute);
  if (!zeroThicknessSegment) given_.everywhere.add(kCortexThicknessAttribute);

  const float scale = linearScale(toWorld);
  const float halfWidth = 0.5f * params.barbWidth * scale;
  radius_ = halfWidth / std::sin(params.cover);
  ramusHalfAngle_ = safeAsin(0.5f * params.ramusWidth * scale / radius_);
  cover_ = params.cover;
  cosSpan_ = std::cos(params.span);
  sinSpan_ = std::sin(params.span);

  for (int i = 0; i < kBarbSegments; ++i) profiles_[i] = {radius_, halfWidth * taper(i), halfWidth * taper(i + 1)};

  strips_.resize(barbCount_ * kBarbSegments);
  tbb::parallel_for(size_t(0), barbCount_, [&](size_t barb) {
    const Vec3* p = &ply.positions[barb * kBarbVertices];
    const Vec3* vn = &ply.normals[barb * kBarbVertices];
    auto fail = [&](const std::string& msg) {
      throw InputError(ply.faceLocation(barb), "face " + std::to_string(barb) + ": " + msg);
    };
    Vec3 dir[kBarbSegments];
    for (int i = 0; i < kBarbSegments; ++i) {
      if (!(lengthSquared(p[i + 1] - p[i]) > 0.0f))
        fail("vertices " + std::to_string(i) + " and " + std::to_string(i + 1) + " coincide (a zero-length segment)");
      dir[i] = segmentDirection(p[i], p[i + 1]);
      // Beyond 120 degrees the mitre cuts reach far past the joint and the strips fold.
      if (i > 0 && dot(dir[i - 1], dir[i]) < -0.5f)
        fail("the barb turns by " + std::to_string(int(radToDeg(safeAcos(dot(dir[i - 1], dir[i]))))) +
             " degrees at vertex " + std::to_string(i) + " (at most 120 can be mitred)");
    }
    // End planes: mitreNormal at the joints, square cuts at both ends of the barb.
    Vec3 mitre[kBarbVertices];
    mitre[0] = dir[0];
    for (int i = 1; i < kBarbSegments; ++i) mitre[i] = mitreNormal(dir[i - 1], dir[i]);
    mitre[kBarbSegments] = dir[kBarbSegments - 1];
    // Transport a basis (e, cross(dir, e)) of the first segment's normal plane along the barb,
    // then pick the one transported normal that best matches the vane normals.
    Vec3 e[kBarbSegments];
    e[0] = perpendicularTo(dir[0], vn[0] + vn[1]);
    for (int i = 1; i < kBarbSegments; ++i) e[i] = transportAcrossJoint(e[i - 1], mitre[i]);
    float alongE = 0.0f, alongCross = 0.0f;
    for (int i = 0; i < kBarbSegments; ++i) {
      Vec3 target = vn[i] + vn[i + 1];
      alongE += dot(target, e[i]);
      alongCross += dot(target, cross(dir[i], e[i]));
    }
    float angle = std::atan2(alongCross, alongE);
    Vec3 n = normalize(e[0] * std::cos(angle) + cross(dir[0], e[0]) * std::sin(angle));
    PackedStrip* strips = &strips_[barb * kBarbSegments];
    for (int i = 0; i < kBarbSegments; ++i) {
      if (i > 0) n = transportAcrossJoint(n, mitre[i]);
      strips[i] = PackedStrip(
          BarbStrip::fromSegment(p[i], dir[i], length(p[i + 1] - p[i]), mitre[i], mitre[i + 1], n, profiles_[i]));
    }
  });
}

BarbStrip FeatherShape::strip(size_t primID) const {
  const int seg = int(primID % kBarbSegments);
  const PackedStrip& s = strips_[primID];
  // The neighbours' axes are the segment directions the mitre planes were built from.
  const Vec3 startMitre = seg > 0 ? mitreNormal(strips_[primID - 1].axis, s.axis) : s.axis;
  const Vec3 endMitre = seg + 1 < kBarbSegments ? mitreNormal(s.axis, strips_[primID + 1].axis) : s.axis;
  return BarbStrip::fromSegment(s.p0, s.axis, s.length, startMitre, endMitre, s.n, profiles_[seg]);
}

unsigned FeatherShape::addToEmbree(RTCDevice device, RTCScene scene) const {
  // No build quality of its own: in a scene without instancing Embree builds user geometry as
  // the scene's quality says, and for it MEDIUM and HIGH build the same SAH tree (LOW's Morton
  // tree builds faster but costs half again as much traversal on the neck).
  return attachUserGeometry(device, scene, unsigned(primitiveCount()), this, boundsCallback, intersectCallback,
                            occludedCallback);
}

SurfaceInteraction FeatherShape::interaction(const Ray& ray, const HitRecord& hit) const {
  // BarbStrip's point, normal and circumferential direction, on the packed strip and with one
  // cosine and sine.
  const PackedStrip& s = strips_[hit.primID];
  const Vec3 b = s.b();
  const size_t barb = hit.primID / kBarbSegments;
  const int seg = int(hit.primID % kBarbSegments);
  // The strip is the part of the cylinder facing n (|angle| < pi/2), so the cosine is positive.
  const float sinAngle = hit.v, cosAngle = std::sqrt(std::max(1.0f - sinAngle * sinAngle, 0.0f));
  const float angle = std::asin(sinAngle);
  SurfaceInteraction si;
  // cos - 1 as -sin^2 / (1 + cos): no cancellation near the top line.
  const float cosMinusOne = -sinAngle * sinAngle / (1.0f + cosAngle);
  si.p = s.p0 + s.axis * (hit.u * s.length) + s.n * (radius_ * cosMinusOne) + b * (radius_ * sinAngle);
  si.ng = s.n * cosAngle + b * sinAngle;
  si.t = hit.t;
  si.shape = this;
  const float along = clampf(hit.u, 0.0f, 1.0f);
  si.uv = Vec2((float(seg) + along) / float(kBarbSegments), angle / cover_);
  Vec3 t = s.axis;
  if (std::abs(angle) >= ramusHalfAngle_) {
    // Barbules leave the ramus toward the tip on either side. The frame (s, t, n) is right-handed
    // with s toward the ramus on both sides, as in the original, so that one tilt makes the two
    // rows mirror images; on the positive side t therefore runs back along the barbule (the BSDF
    // is symmetric in t).
    const Vec3 circumferential = b * cosAngle - s.n * sinAngle;  // toward increasing angle
    t = angle > 0.0f ? -(s.axis * cosSpan_ + circumferential * sinSpan_)
                     : s.axis * cosSpan_ - circumferential * sinSpan_;
  }
  si.shading = Frame(cross(t, si.ng), t, si.ng);
  BarbuleValues values = kDefaultBarbuleValues;
  if (!barbuleValues_.empty()) {
    const BarbuleValues* v = &barbuleValues_[barb * kBarbVertices + size_t(seg)];
    values = {lerp(along, v[0].h, v[1].h), lerp(along, v[0].mu, v[1].mu), lerp(along, v[0].height, v[1].height)};
  }
  const float edgeAngle = std::asin(std::min(profiles_[seg].halfWidthAt(hit.u) / radius_, 1.0f));
  values.mu += ramusTilt(angle, edgeAngle);
  // Named as the barbule BSDF's parameters, which reads a zero tilt or thickness as its own
  // parameter's, as the original does.
  si.attributes.set(kBarbuleSpacingAttribute, values.h);
  si.attributes.set(kBarbuleTiltAttribute, values.mu);
  si.attributes.set(kCortexThicknessAttribute, values.height);
  // A choice, not a quantity: the nearer vertex's.
  if (!layerStacks_.empty())
    si.attributes.set(kLayerStackAttribute,
                      float(layerStacks_[barb * kBarbVertices + size_t(seg) + (along < 0.5f ? 0 : 1)]));
  return si;
}

size_t FeatherShape::memoryBytes() const {
  return strips_.capacity() * sizeof(PackedStrip) + barbuleValues_.capacity() * sizeof(BarbuleValues) +
         layerStacks_.capacity();
}

ShapePointValues FeatherShape::givenValues(const std::string& name) const {
  ShapePointValues given = given_;
  given.shape = name;
  return given;
}

}  // namespace columba
