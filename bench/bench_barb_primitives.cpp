// Barb segments as Embree user geometry (the feather shape's exact mitred strips) against
// Embree's own linear curves of the same centre lines and half-widths, which are what a curve
// representation would cost at best: flat curves are ribbons turned toward each ray, round ones
// cylinders, neither the strip. The same generated 60-feather neck, the same rays: straight down
// onto the neck (first hits) and from those hits in random directions (rays leaving a barb),
// traced one at a time (rtcIntersect1, as the renderer does) or in packets of 8 neighbours
// (rtcIntersect8, what a wavefront integrator would issue).
#include <benchmark/benchmark.h>
#include <embree3/rtcore.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <memory>
#include <vector>
#include "core/rng.h"
#include "core/sampling.h"
#include "feather/feather_generator.h"
#include "shapes/feather_shape.h"

using namespace columba;

namespace {

// Distance to the nearest hit of `ray` in `scene`, infinity for none.
float nearestHit(RTCScene scene, const Ray& ray) {
  RTCRayHit rh{};
  rh.ray.org_x = ray.o.x;
  rh.ray.org_y = ray.o.y;
  rh.ray.org_z = ray.o.z;
  rh.ray.dir_x = ray.d.x;
  rh.ray.dir_y = ray.d.y;
  rh.ray.dir_z = ray.d.z;
  rh.ray.tfar = INFINITY;
  rh.ray.mask = 0xFFFFFFFFu;
  rh.hit.geomID = RTC_INVALID_GEOMETRY_ID;
  RTCIntersectContext context;
  rtcInitIntersectContext(&context);
  rtcIntersect1(scene, &context, &rh);
  return rh.hit.geomID == RTC_INVALID_GEOMETRY_ID ? INFINITY : rh.ray.tfar;
}

// Hits among `count` (at most 8) rays traced together as one packet (rtcIntersect8).
size_t packetHits(RTCScene scene, const Ray* rays, int count) {
  alignas(32) int valid[8];
  alignas(32) RTCRayHit8 rh;
  for (int i = 0; i < 8; ++i) {
    valid[i] = i < count ? -1 : 0;
    const Ray& ray = rays[std::min(i, count - 1)];
    rh.ray.org_x[i] = ray.o.x;
    rh.ray.org_y[i] = ray.o.y;
    rh.ray.org_z[i] = ray.o.z;
    rh.ray.tnear[i] = 0.0f;
    rh.ray.dir_x[i] = ray.d.x;
    rh.ray.dir_y[i] = ray.d.y;
    rh.ray.dir_z[i] = ray.d.z;
    rh.ray.time[i] = 0.0f;
    rh.ray.tfar[i] = INFINITY;
    rh.ray.mask[i] = 0xFFFFFFFFu;
    rh.ray.id[i] = unsigned(i);
    rh.ray.flags[i] = 0;
    rh.hit.geomID[i] = RTC_INVALID_GEOMETRY_ID;
    rh.hit.instID[0][i] = RTC_INVALID_GEOMETRY_ID;
  }
  RTCIntersectContext context;
  rtcInitIntersectContext(&context);
  context.flags = RTC_INTERSECT_CONTEXT_FLAG_COHERENT;
  rtcIntersect8(valid, scene, &context, &rh);
  size_t hits = 0;
  for (int i = 0; i < count; ++i) hits += rh.hit.geomID[i] != RTC_INVALID_GEOMETRY_ID;
  return hits;
}

struct Geometry {
  std::unique_ptr<FeatherShape> feather;
  std::vector<Ray> downRays, leavingRays;
};

const Geometry& geometry() {
  static const Geometry g = [] {
    Geometry out;
    std::string path = (std::filesystem::temp_directory_path() / "columba-bench-primitives.ply").string();
    FeatherGenerationOptions options;
    options.neck = true;
    options.binary = true;
    generateFeatherPly(options, path);
    out.feather = std::make_unique<FeatherShape>(readFeatherPly(path), FeatherShapeParams{});
    std::remove(path.c_str());

    // A 256 x 192 grid of rays down onto the neck's extent (x in [-2.4, 3.4], y in [-1.6, 3]).
    RTCDevice device = rtcNewDevice(nullptr);
    RTCScene scene = rtcNewScene(device);
    out.feather->addToEmbree(device, scene);
    rtcCommitScene(scene);
    PCG32 rng(7);
    for (int y = 0; y < 192; ++y)
      for (int x = 0; x < 256; ++x) {
        Ray ray;
        ray.o = Vec3(-2.4f + 5.8f * (x + 0.5f) / 256.0f, -1.6f + 4.6f * (y + 0.5f) / 192.0f, 10.0f);
        ray.d = Vec3(0.0f, 0.0f, -1.0f);
        out.downRays.push_back(ray);
        float t = nearestHit(scene, ray);
        if (!std::isfinite(t)) continue;
        Ray leaving;
        leaving.o = ray.at(t * 0.9999f);
        leaving.d = sampleUniformSphere(Vec2(rng.nextFloat(), rng.nextFloat()));
        out.leavingRays.push_back(leaving);
      }
    rtcReleaseScene(scene);
    rtcReleaseDevice(device);
    return out;
  }();
  return g;
}

// Linear curves through every strip's centre line with its half-widths, as one Embree geometry.
void addCurves(RTCDevice device, RTCScene scene, RTCGeometryType type) {
  const FeatherShape& feather = *geometry().feather;
  const size_t strips = feather.primitiveCount();
  RTCGeometry geom = rtcNewGeometry(device, type);
  auto* vertices = static_cast<float*>(
      rtcSetNewGeometryBuffer(geom, RTC_BUFFER_TYPE_VERTEX, 0, RTC_FORMAT_FLOAT4, 4 * sizeof(float), 2 * strips));
  auto* indices = static_cast<unsigned*>(
      rtcSetNewGeometryBuffer(geom, RTC_BUFFER_TYPE_INDEX, 0, RTC_FORMAT_UINT, sizeof(unsigned), strips));
  for (size_t i = 0; i < strips; ++i) {
    BarbStrip s = feather.strip(i);
    Vec3 end = s.p0 + s.axis * s.length;
    float* v = vertices + 8 * i;
    v[0] = s.p0.x;
    v[1] = s.p0.y;
    v[2] = s.p0.z;
    v[3] = s.halfWidthStart;
    v[4] = end.x;
    v[5] = end.y;
    v[6] = end.z;
    v[7] = s.halfWidthEnd;
    indices[i] = unsigned(2 * i);
  }
  rtcCommitGeometry(geom);
  rtcAttachGeometry(scene, geom);
  rtcReleaseGeometry(geom);
}

enum class Representation { UserStrips, FlatCurves, RoundCurves };

void BM_BarbRays(benchmark::State& state) {
  const Geometry& g = geometry();
  const auto representation = Representation(state.range(0));
  const std::vector<Ray>& rays = state.range(1) == 0 ? g.downRays : g.leavingRays;
  RTCDevice device = rtcNewDevice(nullptr);
  RTCScene scene = rtcNewScene(device);
  rtcSetSceneBuildQuality(scene, RTC_BUILD_QUALITY_HIGH);  // as Scene builds
  if (representation == Representation::UserStrips)
    g.feather->addToEmbree(device, scene);
  else
    addCurves(device, scene,
              representation == Representation::FlatCurves ? RTC_GEOMETRY_TYPE_FLAT_LINEAR_CURVE
                                                           : RTC_GEOMETRY_TYPE_ROUND_LINEAR_CURVE);
  rtcCommitScene(scene);
  const bool packets = state.range(2) == 8;
  size_t hits = 0;
  for (auto _ : state) {
    hits = 0;
    if (packets) {
      for (size_t i = 0; i < rays.size(); i += 8)
        hits += packetHits(scene, &rays[i], int(std::min<size_t>(8, rays.size() - i)));
    } else {
      for (const Ray& ray : rays) hits += std::isfinite(nearestHit(scene, ray));
    }
    benchmark::DoNotOptimize(hits);
  }
  state.counters["hit_fraction"] = double(hits) / double(rays.size());
  state.SetItemsProcessed(int64_t(state.iterations()) * int64_t(rays.size()));
  rtcReleaseScene(scene);
  rtcReleaseDevice(device);
}
BENCHMARK(BM_BarbRays)
    ->ArgNames({"repr(0=user strips,1=flat curves,2=round curves)", "rays(0=down,1=leaving)", "packet"})
    ->ArgsProduct({{0, 1, 2}, {0, 1}, {1, 8}})
    ->Unit(benchmark::kMillisecond);

}  // namespace
