#include "scene/scene.h"

#include <algorithm>
#include <cstring>
#include <stdexcept>

#include "core/error.h"
#include "core/fast_math.h"
#include "integrators/particle_tracer_integrator.h"
#include "integrators/path_integrator.h"
#include "sensors/perspective_sensor.h"
#include "shapes/analytic_shape.h"
#include "shapes/shape_group.h"

namespace columba {

namespace {
// A ray can cross at most this many pass-through layers: bounds the work of a shadow ray in a
// dense feather coat and guarantees termination.
constexpr int kMaxPassThroughLayers = 256;
// Up to this many analytic shapes are intersected in turn rather than through Embree, which costs
// more than a few exact tests (docs/performance.md, "Sample patterns and wavelengths").
constexpr size_t kShapesTestedInTurn = 4;

void throwOnEmbreeError(RTCDevice device) {
  RTCError code = rtcGetDeviceError(device);
  if (code != RTC_ERROR_NONE)
    throw std::runtime_error("Embree failed to build the scene (error " + std::to_string(int(code)) + ")");
}
}  // namespace

Scene::Scene(const ParsedScene& parsed, const SourceLocation& source) {
  for (const auto& object : parsed.objects) {
    if (auto shape = std::dynamic_pointer_cast<Shape>(object)) {
      shapes_.push_back(shape);
      if (shape->emitter) emitters_.push_back(shape->emitter);
      if (shape->interior || shape->exterior) hasMedia_ = true;
    } else if (auto emitter = std::dynamic_pointer_cast<Emitter>(object)) {
      emitters_.push_back(emitter);
    } else if (auto sensor = std::dynamic_pointer_cast<Sensor>(object)) {
      if (sensor_) throw InputError(source, "the scene has more than one sensor");
      sensor_ = sensor;
    } else if (auto integrator = std::dynamic_pointer_cast<Integrator>(object)) {
      if (integrator_ || particleTracer_) throw InputError(source, "the scene has more than one integrator");
      integrator_ = integrator;
    } else if (auto tracer = std::dynamic_pointer_cast<ParticleTracerIntegrator>(object)) {
      if (integrator_ || particleTracer_) throw InputError(source, "the scene has more than one integrator");
      particleTracer_ = tracer;
    } else if (!std::dynamic_pointer_cast<BSDF>(object) && !std::dynamic_pointer_cast<ShapeGroup>(object)) {
      // A shapegroup is rendered only through its instances.
      throw InputError(source,
                       "the scene has a top-level object that is not a shape, emitter, sensor, integrator or bsdf");
    }
  }
  for (const auto& e : emitters_) {
    allEmitters_.push_back(e.get());
    if (!e->leftToBSDFSamples()) emittersBesideBSDFSamples_.push_back(e.get());
    if (e->isInfinite()) infiniteEmitters_.push_back(e.get());
  }
  auto anyExtended = [](const std::vector<const Emitter*>& set) {
    return std::any_of(set.begin(), set.end(), [](const Emitter* e) { return !e->isDelta(); });
  };
  hasExtendedEmitters_ = anyExtended(allEmitters_);
  hasExtendedEmittersBesideBSDFSamples_ = anyExtended(emittersBesideBSDFSamples_);
  if (!sensor_) sensor_ = makeDefaultPlugin<Sensor>(makePerspectiveSensor, "sensor", "perspective", source);
  if (sensor_->medium()) hasMedia_ = true;
  if (!integrator_ && !particleTracer_)
    integrator_ = makeDefaultPlugin<Integrator>(makePathIntegrator, "integrator", "path", source);
  if (hasMedia_ && !(integrator_ && integrator_->tracesMedia()))
    warn(source,
         "the scene's media have no effect: its integrator renders surfaces only (as Mitsuba's does); "
         "use volpath or volpathmis");
  warnOfSingularValuesWeighedAlone(source);
  // Before Embree is set up: it needs the sensor and the emitters only.
  if (particleTracer_) particleTracer_->checkScene(*this);

  device_ = rtcNewDevice(nullptr);
  if (!device_) throw std::runtime_error("cannot create an Embree device");
  scene_ = rtcNewScene(device_);
  rtcSetSceneBuildQuality(scene_, RTC_BUILD_QUALITY_HIGH);
  for (size_t i = 0; i < shapes_.size(); ++i) {
    unsigned id = shapes_[i]->addToEmbree(device_, scene_);
    if (id != i) throw std::logic_error("Embree geometry IDs are expected in insertion order");
  }
  rtcCommitScene(scene_);
  throwOnEmbreeError(device_);
  if (shapes_.size() <= kShapesTestedInTurn) {
    for (const auto& shape : shapes_) {
      const auto* analytic = dynamic_cast<const AnalyticShape*>(shape.get());
      if (!analytic) {
        testedInTurn_.clear();
        break;
      }
      testedInTurn_.push_back(analytic);
    }
  }
  RTCBounds bounds;
  rtcGetSceneBounds(scene_, &bounds);
  const Vec3 lo(bounds.lower_x, bounds.lower_y, bounds.lower_z), hi(bounds.upper_x, bounds.upper_y, bounds.upper_z);
  if (!shapes_.empty() && lo.x <= hi.x && lo.y <= hi.y && lo.z <= hi.z)
    boundingSphere_ = {(lo + hi) * 0.5f, 0.5f * length(hi - lo)};
}

const Integrator& Scene::integrator() const {
  if (!integrator_) throw std::logic_error("the scene is rendered by ptracer, which traces no camera paths");
  return *integrator_;
}

void Scene::warnOfSingularValuesWeighedAlone(const SourceLocation& source) const {
  const std::string integrator = particleTracer_ ? "ptracer" : integrator_->weighsBSDFValuesAlone();
  if (integrator.empty()) return;
  const bool singular = std::any_of(shapes_.begin(), shapes_.end(), [](const std::shared_ptr<Shape>& shape) {
    return shape->anyBSDF([](const BSDF& bsdf) { return bsdf.hasSingularValues(); });
  });
  if (singular)
    warn(source, "the integrator (" + integrator +
                     ") weighs BSDF values at directions it does not sample from the BSDF, and a barbule BSDF with a "
                     "profile_exponent above 3 has values whose square is not integrable: the image converges slowly "
                     "and from below (docs/model.md, \"Which estimators converge\"); an integrator with MIS (the "
                     "default path) or BSDF sampling converges");
}

Scene::~Scene() {
  if (scene_) rtcReleaseScene(scene_);
  if (device_) rtcReleaseDevice(device_);
}

std::optional<SurfaceInteraction> Scene::intersect(const Ray& ray) const {
  if (!testedInTurn_.empty()) return intersectInTurn(ray);
  RTCIntersectContext context;
  rtcInitIntersectContext(&context);
  RTCRayHit rh;
  // Origin and tnear, direction and time as whole 16-byte stores: Embree loads them as vectors,
  // and a vector load from several narrower stores stalls until they have all retired.
  const FloatLanes originAndNear{ray.o.x, ray.o.y, ray.o.z, ray.tmin},
      directionAndTime{ray.d.x, ray.d.y, ray.d.z, 0.0f};
  std::memcpy(&rh.ray.org_x, &originAndNear, sizeof(FloatLanes));
  std::memcpy(&rh.ray.dir_x, &directionAndTime, sizeof(FloatLanes));
  rh.ray.tfar = ray.tmax;
  rh.ray.mask = 0xFFFFFFFFu;
  rh.ray.id = 0;
  rh.ray.flags = 0;
  rh.hit.geomID = RTC_INVALID_GEOMETRY_ID;
  rh.hit.instID[0] = RTC_INVALID_GEOMETRY_ID;
  rtcIntersect1(scene_, &context, &rh);
  if (rh.hit.geomID == RTC_INVALID_GEOMETRY_ID) return std::nullopt;
  HitRecord hit{rh.ray.tfar, rh.hit.primID, rh.hit.u, rh.hit.v, Vec3(rh.hit.Ng_x, rh.hit.Ng_y, rh.hit.Ng_z)};
  hit.geomID = rh.hit.geomID;
  // A hit through an instance belongs to the instance, which finds the group's shape by geomID.
  const unsigned shape = rh.hit.instID[0] == RTC_INVALID_GEOMETRY_ID ? rh.hit.geomID : rh.hit.instID[0];
  return shapes_[shape]->interaction(ray, hit);
}

std::optional<SurfaceInteraction> Scene::intersectInTurn(const Ray& ray) const {
  // What Embree asks of each shape's user geometry, in geometry ID order: the nearest hit within
  // (tmin, tmax), each test bounded by the nearest hit so far.
  HitRecord hit;
  hit.t = ray.tmax;
  bool found = false;
  for (size_t i = 0; i < testedInTurn_.size(); ++i) {
    float t;
    if (!testedInTurn_[i]->intersectPrimitive(0, ray.o, ray.d, ray.tmin, hit.t, t)) continue;
    hit.t = t;
    hit.geomID = unsigned(i);
    found = true;
  }
  if (!found) return std::nullopt;
  hit.ng = testedInTurn_[hit.geomID]->primitiveNormal(0, ray.o + ray.d * hit.t);
  return shapes_[hit.geomID]->interaction(ray, hit);
}

Spectrum Scene::traceThrough(Ray ray, const Wavelengths& wl, uint64_t& rays,
                             std::optional<SurfaceInteraction>& blocker) const {
  Spectrum result(1.0f);
  blocker.reset();
  for (int layer = 0; layer < kMaxPassThroughLayers; ++layer) {
    ++rays;
    auto hit = intersect(ray);
    if (!hit) return result;
    const BSDF& bsdf = *hit->shape->bsdf;
    if (!bsdf.hasPassThrough() || hit->shape->emitter) {
      blocker = hit;
      return result;
    }
    Vec3 dir = normalize(ray.d);
    result *= bsdf.passThrough(hit->bsdfContext(), hit->shading.toLocal(-dir), wl);
    if (result.isZero()) return result;
    // Continue from just beyond the surface, keeping the same end point.
    Ray next = hit->spawnRay(dir);
    if (std::isfinite(ray.tmax)) {
      Vec3 end = ray.at(ray.tmax);
      next.d = end - next.o;
      next.tmax = 1.0f;
      if (dot(next.d, dir) <= 0.0f) return result;
    }
    ray = next;
  }
  return Spectrum(0.0f);
}

Spectrum Scene::transmittance(const Ray& ray, const Wavelengths& wl, uint64_t& rays) const {
  std::optional<SurfaceInteraction> blocker;
  Spectrum result = traceThrough(ray, wl, rays, blocker);
  return blocker ? Spectrum(0.0f) : result;
}

size_t Scene::primitiveCount() const {
  size_t n = 0;
  for (const auto& s : shapes_) n += s->primitiveCount();
  return n;
}

}  // namespace columba
