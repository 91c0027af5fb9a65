#pragma once
// `ptracer`: Mitsuba 3's particle tracer. Each sample starts a path on an emitter (an emitter
// chosen uniformly, a ray leaving it with its emitted power) and follows it through the BSDFs,
// connecting every surface vertex to the sensor: the light the vertex scatters toward the sensor,
// weighted by the sensor's importance, lands on the film where the sensor sees the vertex.
// Unless hide_emitters, each sample also connects a point of an emitter (area lights) or a
// direction of a light at infinity to the sensor, for the emitters the camera sees directly.
// max_depth and rr_depth count as in `path`, so the two render the same image in expectation.
//
// The light scattered at a vertex is f(toward the camera's side, toward the light), the BSDF with
// its arguments as camera paths pass them, so BSDFs that are not reciprocal (the barbule BSDF) give
// the same image; directions are still sampled from the light's side, and a sample is weighted
// with the BSDF evaluated the other way round. Veach's correction covers shading normals. Delta
// samples keep their own weight: for dielectrics that leaves out (eta_i / eta_t)^2, which for a
// light path telescopes to 1 between a light and a camera in the same medium (e.g. both in air),
// the only case Columba's scenes describe.
#include "core/error.h"
#include "core/properties.h"
#include "core/spectrum.h"
#include "samplers/sampler.h"

namespace columba {

class Scene;
struct SurfaceInteraction;

// Where the light of a light path goes: radiance-weighted values at film positions (pixels), which
// the renderer spreads over the pixels with the film's filter.
class FilmSplats {
 public:
  virtual ~FilmSplats() = default;
  virtual void add(Vec2 filmPosition, const Spectrum& value) = 0;
};

class ParticleTracerIntegrator : public Object {
 public:
  // `where`: the integrator's element, which errors about the scene name.
  ParticleTracerIntegrator(int maxDepth, int rrDepth, bool hideEmitters, SourceLocation where)
      : maxDepth_(maxDepth), rrDepth_(rrDepth), hideEmitters_(hideEmitters), where_(std::move(where)) {}
  // Throws InputError for a scene it cannot render: a sensor without importance, or lights at
  // infinity to be seen directly through a sensor that has no importance toward directions.
  void checkScene(const Scene& scene) const;
  // One sample at the wavelengths `wl`: the emitters seen directly and one light path. `rays`
  // counts the rays traced.
  void trace(const Scene& scene, Sampler& sampler, const Wavelengths& wl, FilmSplats& splats, uint64_t& rays) const;

 private:
  void splatVisibleEmitter(const Scene& scene, Sampler& sampler, const Wavelengths& wl, FilmSplats& splats,
                           uint64_t& rays) const;
  void traceLightPath(const Scene& scene, Sampler& sampler, const Wavelengths& wl, FilmSplats& splats,
                      uint64_t& rays) const;
  // Splats the light `beta` arriving at `hit` from `toLight` (world, unit) that the surface
  // scatters toward the sensor.
  void connectToSensor(const Scene& scene, const SurfaceInteraction& hit, const Vec3& toLight, const Spectrum& beta,
                       Vec2 u, const Wavelengths& wl, FilmSplats& splats, uint64_t& rays) const;

  int maxDepth_;  // -1: unlimited; 1: the emitters seen directly only
  int rrDepth_;
  bool hideEmitters_;
  SourceLocation where_;
};

std::shared_ptr<Object> makeParticleTracerIntegrator(const Properties& props);

}  // namespace columba
