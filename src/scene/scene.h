#pragma once
// A loaded scene: shapes in an Embree BVH, emitters, the sensor and the integrator. A scene of a
// few analytic shapes (a sample in a scatterometer set-up) is intersected shape by shape instead:
// there Embree's traversal and callback cost more than the shapes' own tests.
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

class AnalyticShape;
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
  // The emitters next-event estimation draws from: all of them, or, at a vertex that also draws a
  // BSDF sample and weighs the two by MIS, those that BSDF samples do not find as well
  // (Emitter::leftToBSDFSamples: a constant environment). With a constant environment and one
  // area light, the light then gets every emitter sample instead of half of them.
  enum class EmitterSet { All, BesideBSDFSamples };
  // Emitter choice for next-event estimation, uniform over the set. `u` is remapped to a fresh
  // uniform value in [0, 1) for reuse (as Mitsuba does), unchanged when there is one emitter.
  // Inline: `u` is usually half of a Vec2 that would otherwise be reloaded from memory.
  const Emitter* sampleEmitter(float& u, float* pmf, EmitterSet set = EmitterSet::All) const {
    const std::vector<const Emitter*>& choices = emittersOf(set);
    if (choices.empty()) return nullptr;
    float scaled = u * float(choices.size());
    int i = std::min(int(scaled), int(choices.size()) - 1);
    u = std::min(scaled - float(i), kOneMinusEpsilon);
    *pmf = 1.0f / float(choices.size());
    return choices[size_t(i)];
  }
  // Whether the set holds an emitter that is not a delta light: only then can emitter samples from
  // one point differ in direction (worth resampling several of them).
  bool hasExtendedEmitters(EmitterSet set) const {
    return set == EmitterSet::All ? hasExtendedEmitters_ : hasExtendedEmittersBesideBSDFSamples_;
  }
  // Whether the two sets differ: only then is a vertex's set worth deciding.
  bool leavesEmittersToBSDFSamples() const { return emittersBesideBSDFSamples_.size() != allEmitters_.size(); }
  // The probability that sampleEmitter picks `emitter` from the set (0 if the set leaves it out).
  float emitterPmf(const Emitter& emitter, EmitterSet set = EmitterSet::All) const {
    if (set == EmitterSet::BesideBSDFSamples && emitter.leftToBSDFSamples()) return 0.0f;
    const std::vector<const Emitter*>& choices = emittersOf(set);
    return choices.empty() ? 0.0f : 1.0f / float(choices.size());
  }

  // The sphere around the shapes (radius 0 without shapes), which lights at infinity shine through.
  const SceneSphere& boundingSphere() const { return boundingSphere_; }

  const Sensor& sensor() const { return *sensor_; }
  // Whether a shape bounds a medium or the sensor sits in one: only then do paths track media.
  bool hasMedia() const { return hasMedia_; }
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
  // Every shape, when the scene is intersected shape by shape; otherwise empty.
  std::vector<const AnalyticShape*> testedInTurn_;
  std::optional<SurfaceInteraction> intersectInTurn(const Ray& ray) const;
  // Warns when the integrator weighs BSDF values alone (emitter sampling without MIS, ptracer)
  // and some shape's BSDF has values that are not square-integrable: its estimate then has an
  // infinite variance.
  void warnOfSingularValuesWeighedAlone(const SourceLocation& source) const;
  const std::vector<const Emitter*>& emittersOf(EmitterSet set) const {
    return set == EmitterSet::All ? allEmitters_ : emittersBesideBSDFSamples_;
  }

  std::vector<std::shared_ptr<Emitter>> emitters_;
  std::vector<const Emitter*> allEmitters_, emittersBesideBSDFSamples_;
  std::vector<const Emitter*> infiniteEmitters_;
  bool hasExtendedEmitters_ = false, hasExtendedEmittersBesideBSDFSamples_ = false;
  std::shared_ptr<Sensor> sensor_;
  std::shared_ptr<Integrator> integrator_;
  std::shared_ptr<ParticleTracerIntegrator> particleTracer_;
  SceneSphere boundingSphere_;
  bool hasMedia_ = false;
};

}  // namespace columba
