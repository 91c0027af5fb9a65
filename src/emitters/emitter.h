#pragma once
// The emitter interface: light sources sampled from a reference point (next-event estimation),
// evaluated where paths hit them, and sampled as rays leaving them (light tracing).
#include <optional>
#include "core/object.h"
#include "core/spectrum.h"
#include "shapes/shape.h"

namespace columba {

struct EmitterSample {
  Vec3 direction;         // unit, from the reference point toward the light
  float distance = 0.0f;  // to the sampled point; infinity for lights at infinity
  Spectrum radiance;      // radiance arriving along -direction (not divided by the pdf)
  float pdf = 0.0f;       // solid-angle density; 1 for delta lights
};

// A ray of light leaving an emitter, for paths that start on the lights.
struct EmitterRaySample {
  Ray ray;          // ray.d unit
  Spectrum weight;  // emitted radiance times the cosine at the origin, over the densities of origin and direction
};

// The sphere bounding the scene's shapes: lights at infinity send their rays through its disk
// facing them.
struct SceneSphere {
  Vec3 centre;
  float radius = 0.0f;
};

class Emitter : public Object {
 public:
  virtual std::optional<EmitterSample> sample(const Vec3& ref, Vec2 u, const Wavelengths& wl) const = 0;
  // Density of `sample` choosing the direction toward `hit` (a point on this emitter's shape).
  virtual float pdfHit(const Vec3& ref, const SurfaceInteraction& hit) const { return 0.0f; }
  // Radiance leaving `hit` (on this emitter's shape) toward `toViewer`.
  virtual Spectrum radianceAt(const SurfaceInteraction& hit, const Vec3& toViewer, const Wavelengths& wl) const {
    return Spectrum(0.0f);
  }
  // Lights at infinity: radiance arriving along a ray that escapes in direction `d`, and the
  // density of `sample` choosing `d`.
  virtual Spectrum radianceFromDirection(const Vec3& d, const Wavelengths& wl) const { return Spectrum(0.0f); }
  virtual float pdfDirection(const Vec3& d) const { return 0.0f; }

  // A ray leaving the emitter: `uPosition` picks where it starts, `uDirection` where it goes.
  // nullopt: no light leaves there.
  virtual std::optional<EmitterRaySample> sampleRay(Vec2 uPosition, Vec2 uDirection, const Wavelengths& wl,
                                                    const SceneSphere& scene) const = 0;
  // A point of an emitter that a camera may see (area lights: a point of the shape, uniform by
  // area); nullopt for the others.
  virtual std::optional<PositionSample> samplePosition(Vec2 /*u*/) const { return std::nullopt; }

  virtual bool isDelta() const { return false; }
  virtual bool isInfinite() const { return false; }
  // Whether a BSDF sample finds this emitter's light at least as well as the emitter's own
  // samples do, so that vertices drawing both leave it to the BSDF sample (Scene::EmitterSet).
  virtual bool leftToBSDFSamples() const { return false; }
  // Area emitters learn their shape when the shape is built.
  virtual void attachTo(const Shape* shape) {}
};

}  // namespace columba
