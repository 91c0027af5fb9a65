#pragma once
// Shared helpers of the feather tests: synthetic barbs, an Embree scene around one shape, and
// an independent double-precision intersector to check the strips (serrated edges included)
// against.
#include <embree3/rtcore.h>

#include <array>
#include <cmath>
#include <functional>
#include <optional>
#include <string>
#include <string_view>
#include <vector>
#include "builtin/builtin_plugins.h"
#include "core/error.h"
#include "core/rng.h"
#include "io/feather_ply_writer.h"
#include "scene/scene_loader.h"
#include "shapes/feather_shape.h"

namespace columba::test {

// The InputError message of loading `xml` as scene.xml with its files in `dir`, "" when it loads.
inline std::string sceneLoadError(const std::string& xml, const std::string& dir) {
  try {
    loadSceneString(xml, "scene.xml", dir, {}, builtinPlugins());
  } catch (const InputError& e) {
    return e.what();
  }
  return "";
}

// A hit's attribute `name` (a per-point BSDF parameter), NaN where the hit does not give it.
inline float attribute(const SurfaceInteraction& si, std::string_view name) {
  return si.attributes.find(SurfaceAttributeKey(name)).value_or(std::nanf(""));
}

// Barbs laid side by side along y, each curving in its vane plane (bend), lifting out of it
// (lift) and wiggling by `zigzag` radians at alternate joints, with vane normal +z tilted
// slightly along the barb.
inline FeatherPlyData syntheticBarbs(int barbs, float bend, float lift, float zigzag, bool withParams = true) {
  FeatherPlyData ply;
  ply.path = "synthetic.ply";
  for (int b = 0; b < barbs; ++b) {
    Vec3 p(0.0f, 0.1f * float(b), 0.0f);
    for (int k = 0; k < kBarbVertices; ++k) {
      float s = float(k) / float(kBarbSegments);
      ply.positions.push_back(p);
      ply.normals.push_back(normalize(Vec3(0.0f, -0.2f * s, 1.0f)));
      if (withParams) {
        ply.barbuleH.push_back(1.0f + s);
        ply.barbuleMu.push_back(-0.35f);
        ply.barbuleHeight.push_back(0.6f - 0.1f * s);
      }
      float heading = bend * s + ((k % 2) ? zigzag : -zigzag);
      float pitch = lift * s + ((k % 3 == 0) ? zigzag : 0.0f);
      p += Vec3(std::cos(heading) * std::cos(pitch), std::sin(heading) * std::cos(pitch), std::sin(pitch)) * 0.005f;
    }
  }
  for (uint32_t i = 0; i < ply.positions.size(); ++i) ply.barbIndices.push_back(i);
  return ply;
}

// Writes `file`: eight straight barbs side by side along y (barb b at y = -0.25 + 0.07 b, 0.6 long
// along x, facing +z), file H 0.5 and mu 0.35 and cortex `height` at every vertex, and where
// `stackOf` is given, every vertex of barb b with layer stack stackOf(b).
inline std::string writeStraightBarbs(const std::string& file, float height,
                                      const std::function<int(int)>& stackOf = {}) {
  FeatherPlyWriter writer(file, false, 8, 0.07f, {true, bool(stackOf)});
  BarbVertex barb[kBarbVertices];
  for (int b = 0; b < 8; ++b) {
    for (int k = 0; k < kBarbVertices; ++k) {
      barb[k].position = Vec3(-0.3f + 0.6f * float(k) / float(kBarbSegments), -0.25f + 0.07f * float(b), 0.0f);
      barb[k].normal = Vec3(0, 0, 1);
      barb[k].fileH = 0.5f;
      barb[k].fileMu = 0.35f;
      barb[k].height = height;
      barb[k].stack = stackOf ? uint8_t(stackOf(b)) : 0;
    }
    writer.writeBarb(barb);
  }
  writer.commit();
  return file;
}

// An Embree device and scene holding one shape.
class EmbreeScene {
 public:
  explicit EmbreeScene(const Shape& shape) : shape_(shape) {
    device_ = rtcNewDevice("threads=1");
    scene_ = rtcNewScene(device_);
    geomID_ = shape.addToEmbree(device_, scene_);
    rtcCommitScene(scene_);
  }
  ~EmbreeScene() {
    rtcReleaseScene(scene_);
    rtcReleaseDevice(device_);
  }
  EmbreeScene(const EmbreeScene&) = delete;
  EmbreeScene& operator=(const EmbreeScene&) = delete;

  // Nearest hit as the renderer sees it.
  std::optional<std::pair<HitRecord, SurfaceInteraction>> intersect(const Ray& ray) const {
    RTCIntersectContext context;
    rtcInitIntersectContext(&context);
    RTCRayHit rh{};
    rh.ray.org_x = ray.o.x;
    rh.ray.org_y = ray.o.y;
    rh.ray.org_z = ray.o.z;
    rh.ray.dir_x = ray.d.x;
    rh.ray.dir_y = ray.d.y;
    rh.ray.dir_z = ray.d.z;
    rh.ray.tnear = ray.tmin;
    rh.ray.tfar = ray.tmax;
    rh.ray.mask = ~0u;
    rh.hit.geomID = RTC_INVALID_GEOMETRY_ID;
    rtcIntersect1(scene_, &context, &rh);
    if (rh.hit.geomID == RTC_INVALID_GEOMETRY_ID) return std::nullopt;
    if (rh.hit.geomID != geomID_) throw std::logic_error("unexpected geometry ID");
    HitRecord h{rh.ray.tfar, rh.hit.primID, rh.hit.u, rh.hit.v, Vec3(rh.hit.Ng_x, rh.hit.Ng_y, rh.hit.Ng_z)};
    return std::make_pair(h, shape_.interaction(ray, h));
  }

  bool occluded(const Ray& ray) const {
    RTCIntersectContext context;
    rtcInitIntersectContext(&context);
    RTCRay r{};
    r.org_x = ray.o.x;
    r.org_y = ray.o.y;
    r.org_z = ray.o.z;
    r.dir_x = ray.d.x;
    r.dir_y = ray.d.y;
    r.dir_z = ray.d.z;
    r.tnear = ray.tmin;
    r.tfar = ray.tmax;
    r.mask = ~0u;
    rtcOccluded1(scene_, &context, &r);
    return r.tfar < 0.0f;
  }

  // Nearest hits of four rays traced as one packet (tfar and primID per lane; primID
  // RTC_INVALID_GEOMETRY_ID for a miss).
  std::array<std::pair<float, unsigned>, 4> intersect4(const std::array<Ray, 4>& rays) const {
    RTCIntersectContext context;
    rtcInitIntersectContext(&context);
    alignas(16) int valid[4] = {-1, -1, -1, -1};
    alignas(16) RTCRayHit4 rh{};
    for (int i = 0; i < 4; ++i) {
      const Ray& ray = rays[size_t(i)];
      rh.ray.org_x[i] = ray.o.x;
      rh.ray.org_y[i] = ray.o.y;
      rh.ray.org_z[i] = ray.o.z;
      rh.ray.dir_x[i] = ray.d.x;
      rh.ray.dir_y[i] = ray.d.y;
      rh.ray.dir_z[i] = ray.d.z;
      rh.ray.tnear[i] = ray.tmin;
      rh.ray.tfar[i] = ray.tmax;
      rh.ray.mask[i] = ~0u;
      rh.hit.geomID[i] = RTC_INVALID_GEOMETRY_ID;
    }
    rtcIntersect4(valid, scene_, &context, &rh);
    std::array<std::pair<float, unsigned>, 4> hits;
    for (int i = 0; i < 4; ++i)
      hits[size_t(i)] = {rh.ray.tfar[i],
                         rh.hit.geomID[i] == RTC_INVALID_GEOMETRY_ID ? RTC_INVALID_GEOMETRY_ID : rh.hit.primID[i]};
    return hits;
  }

  RTCDevice device() const { return device_; }

 private:
  const Shape& shape_;
  RTCDevice device_;
  RTCScene scene_;
  unsigned geomID_;
};

struct ReferenceHit {
  double t;
  size_t primID;
};

// Every crossing of the ray with every strip, from the strip definition alone: textbook
// quadratic in world space, in double precision, with exact (slack-free) end planes.
inline std::vector<ReferenceHit> referenceHits(const FeatherShape& shape, const Vec3& o, const Vec3& d) {
  struct D3 {
    double x, y, z;
  };
  auto v = [](const Vec3& a) { return D3{a.x, a.y, a.z}; };
  auto sub = [](D3 a, D3 b) { return D3{a.x - b.x, a.y - b.y, a.z - b.z}; };
  auto dotd = [](D3 a, D3 b) { return a.x * b.x + a.y * b.y + a.z * b.z; };
  auto axpy = [](D3 a, double s, D3 b) { return D3{a.x + s * b.x, a.y + s * b.y, a.z + s * b.z}; };
  std::vector<ReferenceHit> hits;
  const D3 od = v(o), dd = v(d);
  for (size_t prim = 0; prim < shape.primitiveCount(); ++prim) {
    BarbStrip s = shape.strip(prim);
    const double R = s.radius;
    const D3 a = v(s.axis), n = v(s.n), b = v(s.b), p0 = v(s.p0);
    const D3 c = axpy(p0, -R, n);  // a point on the axis
    D3 w = sub(od, c);
    D3 wp = axpy(w, -dotd(w, a), a), dp = axpy(dd, -dotd(dd, a), a);
    double A = dotd(dp, dp), B = 2 * dotd(wp, dp), C = dotd(wp, wp) - R * R;
    double disc = B * B - 4 * A * C;
    if (A < 1e-30 || disc < 0) continue;
    for (double t : {(-B - std::sqrt(disc)) / (2 * A), (-B + std::sqrt(disc)) / (2 * A)}) {
      if (t <= 1e-9) continue;
      D3 rel = sub(axpy(od, t, dd), p0);
      double along = dotd(rel, a);
      double phi = std::atan2(dotd(rel, b), dotd(rel, n) + R);
      double frac = std::min(1.0, std::max(0.0, along / s.length));
      double halfWidth = s.halfWidthStart + frac * (s.halfWidthEnd - s.halfWidthStart);
      const double edge = std::asin(halfWidth / R);
      if (std::abs(phi) > edge) continue;
      // Serrated edges, as the original cuts them (z from the segment's tip-ward vertex).
      const double z = s.length - along;
      if (std::abs(phi) > 0.94 * edge && z >= 0.0 &&
          std::fmod(3.0 * z, s.length) > s.length * (std::abs(phi) - edge) / (0.94 * edge - edge))
        continue;
      if (dotd(rel, v(s.startMitre)) < 0) continue;
      if (dotd(sub(rel, D3{a.x * s.length, a.y * s.length, a.z * s.length}), v(s.endMitre)) > 0) continue;
      hits.push_back({t, prim});
    }
  }
  return hits;
}

inline std::optional<ReferenceHit> nearestReferenceHit(const FeatherShape& shape, const Vec3& o, const Vec3& d) {
  std::optional<ReferenceHit> best;
  for (const ReferenceHit& h : referenceHits(shape, o, d))
    if (!best || h.t < best->t) best = h;
  return best;
}

inline Vec3 randomUnitVector(PCG32& rng) {
  float z = 1.0f - 2.0f * rng.nextFloat();
  float phi = kTwoPi * rng.nextFloat();
  float r = safeSqrt(1.0f - z * z);
  return {r * std::cos(phi), r * std::sin(phi), z};
}

}  // namespace columba::test
