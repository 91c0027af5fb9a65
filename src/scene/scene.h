#pragma once
// A loaded scene: shapes in an Embree BVH, emitters, the sensor and the integrator.
#include <embree3/rtcore.h>

#include <memory>
#include <optional>
#include <vector>
#include "core/math.h"
#include "emitters/emitter.h"
#include "scene/scene_loader.h"
#include "sensors/sensor.h"
#include "shapes/shape.h"

namespace columba {

class Integrator;
class ParticleTracerIntegrator;

class Scene {
 public:
  // Takes the parsed plug-ins; missing sensor/integrator get Mitsuba's defaults. Throws
  // InputError for a scene it cannot render (e.g. several sensors).
  explicit Scene(const ParsedScene& parsed, const SourceLocation& source);
  ~Scene();
  Scene(const Scene&) = delete;
  Scene& operator=(const Scene&) = delete;

  std::optional<SurfaceInteraction> intersect(const Ray& ray) const;
  // Follows `ray` through pass-through surfaces (such as the gaps between barbules) up to
  // ray.tmax: returns the fraction of light that gets through them and, in `blocker`, the first
  // surface that does not let light pass (none if the ray escapes). Counts the rays it traces.
  Spectrum traceThrough(Ray ray, const Wavelengths& wl, uint64_t& rays,
                        std::optional<SurfaceInteraction>& blocker) const;
  // Fraction of light that travels along `ray`; 0 when an opaque surface is in the way.
  Spectrum transmittance(const Ray& ray, const Wavelengths& wl, uint64_t& rays) const;

  const std::vector<std::shared_ptr<Emitter>>& emitters() const { return emitters_; }
  const std::vector<const Emitter*>& infiniteEmitters() const { return infiniteEmitters_; }
  // Emitter choice for next-event estimation (uniform over emitters). `u` is remapped to a fresh
  // uniform value in [0, 1) for reuse (as Mitsuba does), unchanged when there is one emitter.
  // Inline: `u` is usually half of a Vec2 that would otherwise be reloaded from memory.
  const Emitter* sampleEmitter(float& u, float* pmf) const {
    if (emitters_.empty()) return nullptr;
    float scaled = u * float(emitters_.size());
    int i = std::min(int(scaled), int(emitters_.size()) - 1);
    u = std::min(scaled - float(i), kOneMinusEpsilon);
    *pmf = emitterPmf();
    return emitters_[size_t(i)].get();
  }
  float emitterPmf() const { return emitters_.empty() ? 0.0f : 1.0f / float(emitters_.size()); }

  // The sphere around the shapes (radius 0 without shapes), which lights at infinity shine through.
  const SceneSphere& boundingSphere() const { return boundingSphere_; }

  const Sensor& sensor() const { return *sensor_; }
  // The camera-path integrator; a scene rendered by light tracing (particleTracer()) has none, and
  // asking for it is a std::logic_error.
  const Integrator& integrator() const;
  // The scene's integrator when it is `ptracer`, otherwise null.
  const ParticleTracerIntegrator* particleTracer() const { return particleTracer_.get(); }
  size_t primitiveCount() const;
  size_t shapeCount() const { return shapes_.size(); }

 private:
  RTCDevice device_ = nullptr;
  RTCScene scene_ = nullptr;
  std::vector<std::shared_ptr<Shape>> shapes_;  // indexed by Embree geometry ID
  std::vector<std::shared_ptr<Emitter>> emitters_;
  std::vector<const Emitter*> infiniteEmitters_;
  std::shared_ptr<Sensor> sensor_;
  std::shared_ptr<Integrator> integrator_;
  std::shared_ptr<ParticleTracerIntegrator> particleTracer_;
  SceneSphere boundingSphere_;
};

}  // namespace columba
