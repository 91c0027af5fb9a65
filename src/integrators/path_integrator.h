#pragma once
// `path`: unidirectional path tracing with next-event estimation and multiple importance
// sampling of emitters and BSDFs (power heuristic), Russian roulette after `rr_depth`.
// Pass-through components (barbule gaps) continue the path without counting a bounce.
// `strategy` (a Columba parameter, as pbrt-v4's simplepath offers) keeps one of the two
// estimators alone, to check the combination against each: "emitter" finds emitters only by
// sampling them (and through delta BSDFs), "bsdf" only by hitting them (delta emitters, which
// no ray hits, then add nothing). `emitter_candidates` (a Columba parameter, 1 to 8) draws that
// many emitter samples at a path's first scattering vertex and traces one, chosen by the BSDF's
// resampling targets toward them (resampled importance sampling, integrators/direct_light.h, and
// BSDFVertexRequest::chooseLight); 0, the default, draws 3 where the BSDF has cheap resampling
// targets (the barbule's) and emitters with extent are drawn from, and 1 elsewhere.
#include "core/properties.h"
#include "integrators/integrator.h"
#include "scene/scene.h"

namespace columba {

class PathIntegrator : public Integrator {
 public:
  enum class Strategy { MIS, EmitterOnly, BSDFOnly };
  static constexpr int kAutomatic = 0;  // emitter_candidates chosen per vertex (candidatesAt)
  PathIntegrator(int maxDepth, int rrDepth, bool hideEmitters, Strategy strategy = Strategy::MIS,
                 int emitterCandidates = kAutomatic)
      : maxDepth_(maxDepth),
        rrDepth_(rrDepth),
        hideEmitters_(hideEmitters),
        strategy_(strategy),
        emitterCandidates_(emitterCandidates) {}
  Spectrum radiance(const Scene& scene, const Ray& ray, Sampler& sampler, const Wavelengths& wl,
                    uint64_t& rays) const override;
  std::string weighsBSDFValuesAlone() const override {
    return strategy_ == Strategy::EmitterOnly ? "path with strategy emitter" : "";
  }
  int maxDepth() const { return maxDepth_; }
  int rrDepth() const { return rrDepth_; }
  bool hidesEmitters() const { return hideEmitters_; }

 private:
  float hitWeight(bool afterDeltaBounce, float bsdfPdf, float lightPdf) const;
  float emitterSampleWeight(bool deltaLight, float lightPdf, float bsdfPdf) const;
  // Emitter samples to draw at a first vertex with this BSDF, drawing from `set`.
  int candidatesAt(const Scene& scene, const BSDF& bsdf, Scene::EmitterSet set) const;

  int maxDepth_;  // longest path in vertices after the camera; -1: unlimited (Mitsuba's meaning)
  int rrDepth_;
  bool hideEmitters_;
  Strategy strategy_;
  int emitterCandidates_;  // emitter samples drawn at the first vertex, one traced (resampleLights)
};

std::shared_ptr<Object> makePathIntegrator(const Properties& props);
// A path integrator of Mitsuba's path parameters (max_depth, rr_depth, hide_emitters and the pass
// parameters) read from `props`, with that strategy and emitter candidates.
std::shared_ptr<Object> makePathIntegratorWith(const Properties& props, PathIntegrator::Strategy strategy,
                                               int emitterCandidates);

}  // namespace columba
