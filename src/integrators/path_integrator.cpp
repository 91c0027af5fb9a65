/*! plugin integrator path
The unidirectional path tracer with next-event estimation, emitter and BSDF samples combined by multiple importance sampling. With `mis`, a `constant` environment is left to the BSDF samples wherever the BSDF can draw every direction it scatters into (as pbrt-v4 does for uniform infinite lights), so the other emitters get all of the emitter samples. At a path's first scattering vertex `emitter_candidates` emitter samples are drawn, all from one stratified light point shifted along a lattice, and the one traced is chosen in proportion to the BSDF's resampling target toward it times the emitter's radiance over its density (resampled importance sampling, unbiased); the barbule BSDF's target is R's value plus a bound of TRT, other BSDFs' their value.
Mitsuba 3: the same depth parameters and defaults; `strategy` and `emitter_candidates` are added; `timeout` does not stop the render.
uses: passes
| parameter | type | default | meaning | Mitsuba 3 |
| max_depth | integer | -1 | the longest path, in segments; -1 is unlimited, 1 shows the emitters seen directly only; below -1 is an error | same |
| rr_depth | integer | 5 | the depth from which Russian roulette ends paths (with probability 1 − min(throughput, 0.95)); at least 1 | same |
| hide_emitters | boolean | false | emitters seen directly by the camera are black | same |
| strategy | string | `mis` | `mis`; `emitter` or `bsdf` keeps that estimator alone, for checks | not in Mitsuba 3 |
| emitter_candidates | integer | 0 | 0 (automatic): 3 where the BSDF has a cheap resampling target (the barbule) and an emitter with extent is drawn from, 1 elsewhere; 1 to 8: that many candidates; 1 is plain next-event estimation. On the neck bench patch under a rectangle light, 3 give 0.55× the variance per sample for 1.15× the instructions; under delta lights every candidate is the same | not in Mitsuba 3 |
*/
#include "integrators/path_integrator.h"

#include <array>
#include <map>
#include <string>

#include "core/sampling.h"
#include "integrators/direct_light.h"

namespace columba {

namespace {
// Bounds the pass-through steps of one path (a ray crossing a whole feather coat).
constexpr int kMaxPassThroughSteps = 1024;

// Emitter candidates where emitter_candidates is left automatic: at a first vertex whose BSDF has
// cheap resampling targets (the barbule's) and emitters with extent to draw from, where they lower
// the variance for little more work; elsewhere (BSDFs evaluated in full toward every candidate,
// delta lights) one. Measured in docs/performance.md, "Measured and kept".
constexpr int kAutomaticEmitterCandidates = 3;

// Candidate k of `count` as uLight shifted by the k-th point of a rank-1 lattice (k / count, k /
// golden ratio), wrapped into the unit square: each candidate is uniform, as resampling needs, and
// together they are spread over the emitters, while uLight is stratified across a pixel's samples.
Vec2 candidatePoint(Vec2 uLight, int k, int count) {
  if (k == 0) return uLight;
  const float x = uLight.x + float(k) / float(count), y = uLight.y + float(k) * 0.618033988f;
  return {std::min(x - std::floor(x), kOneMinusEpsilon), std::min(y - std::floor(y), kOneMinusEpsilon)};
}

// Resamples a vertex's emitter candidates by the BSDF's targets toward them (resampleLights).
class CandidateChooser final : public LightChooser {
 public:
  CandidateChooser(const LightSample* lights, int candidates, float u)
      : lights_(lights), candidates_(candidates), u_(u) {}
  int choose(const BSDFEvalPdf* targets, int drawn) override {
    std::array<float, kMaxLightDirections> ratios{};  // the candidates sampleLight did not draw stay 0
    for (int k = 0; k < drawn; ++k) ratios[size_t(k)] = resamplingRatio(lights_[k], targets[k].value);
    chosen_ = resampleLights(ratios.data(), candidates_, u_);
    return chosen_ ? chosen_->index : -1;
  }
  const std::optional<ResampledLight>& chosen() const { return chosen_; }

 private:
  const LightSample* lights_;
  int candidates_;
  float u_;
  std::optional<ResampledLight> chosen_;
};
}  // namespace

int PathIntegrator::candidatesAt(const Scene& scene, const BSDF& bsdf, Scene::EmitterSet set) const {
  if (emitterCandidates_ != kAutomatic) return emitterCandidates_;
  return bsdf.hasCheapResamplingTargets() && scene.hasExtendedEmitters(set) ? kAutomaticEmitterCandidates : 1;
}

// The weight of an emitter found by a BSDF-sampled ray, and of one found by emitter sampling.
float PathIntegrator::hitWeight(bool afterDeltaBounce, float bsdfPdf, float lightPdf) const {
  if (afterDeltaBounce) return 1.0f;  // no emitter sample could have found it
  switch (strategy_) {
    case Strategy::MIS:
      return powerHeuristic(bsdfPdf, lightPdf);
    case Strategy::EmitterOnly:
      return 0.0f;
    case Strategy::BSDFOnly:
      return 1.0f;
  }
  return 0.0f;
}

float PathIntegrator::emitterSampleWeight(bool deltaLight, float lightPdf, float bsdfPdf) const {
  if (deltaLight || strategy_ == Strategy::EmitterOnly) return 1.0f;
  return powerHeuristic(lightPdf, bsdfPdf);
}

Spectrum PathIntegrator::radiance(const Scene& scene, const Ray& cameraRay, Sampler& sampler, const Wavelengths& wl,
                                  uint64_t& rays) const {
  Spectrum L(0.0f), beta(1.0f);
  Ray ray = cameraRay;
  int depth = 0, passThroughSteps = 0;
  bool deltaBounce = true;  // the camera, like a delta vertex, takes no MIS weight
  float prevBsdfPdf = 0.0f;
  Vec3 prevP;
  // What the last vertex's emitter sampling drew from (an emitter found by its BSDF sample is
  // weighed against it).
  Scene::EmitterSet prevEmitterSet = Scene::EmitterSet::All;
  while (true) {
    ++rays;
    std::optional<SurfaceInteraction> hit = scene.intersect(ray);
    Vec3 dir = normalize(ray.d);
    if (!(depth == 0 && hideEmitters_)) {
      EmitterHit seen = emitterSeenAlong(scene, prevP, dir, hit, wl, prevEmitterSet);
      if (!seen.radiance.isZero()) L += beta * seen.radiance * hitWeight(deltaBounce, prevBsdfPdf, seen.lightPdf);
    }
    if (!hit) break;
    if (maxDepth_ >= 0 && depth + 1 >= maxDepth_) break;

    const BSDF& bsdf = *hit->shape->bsdf;
    Vec3 wi = hit->shading.toLocal(-dir);
    // Emitter sampling and BSDF sampling, with one call to the BSDF for both.
    Vec2 uLight = sampler.get2D();
    bool sampleEmitters = !bsdf.isDeltaOnly() && strategy_ != Strategy::BSDFOnly;
    // With MIS, emitters that this vertex's BSDF sample finds as well are left to it.
    const Scene::EmitterSet emitterSet =
        strategy_ == Strategy::MIS && scene.leavesEmittersToBSDFSamples() && bsdf.samplesAllItScatters()
            ? Scene::EmitterSet::BesideBSDFSamples
            : Scene::EmitterSet::All;
    float uComponent = sampler.get1D();
    Vec2 uDirection = sampler.get2D();
    // Emitter candidates (emitter_candidates, at the first scattering vertex, which most of an
    // image's direct light leaves from), all from uLight (candidatePoint).
    const int candidates = !sampleEmitters ? 0 : depth == 0 ? candidatesAt(scene, bsdf, emitterSet) : 1;
    std::array<LightSample, kMaxLightDirections> lights;
    std::array<Vec3, kMaxLightDirections> towardLights;
    int drawn = 0;
    for (int k = 0; k < candidates; ++k) {
      if (std::optional<LightSample> light =
              sampleLight(scene, *hit, wl, candidatePoint(uLight, k, candidates), emitterSet)) {
        lights[size_t(drawn)] = *light;
        towardLights[size_t(drawn++)] = light->woLocal;
      }
    }
    CandidateChooser chooser(lights.data(), candidates, candidates > 1 ? sampler.get1D() : 0.0f);
    BSDFVertexRequest request;
    if (candidates > 1 && drawn > 0) request.chooseLight = &chooser;
    request.woLights = towardLights.data();
    request.woLightCount = drawn;
    std::array<BSDFEvalPdf, kMaxLightDirections> toLights;
    request.toLights = toLights.data();
    request.lightPdf = true;
    request.sample = true;
    request.uComponent = uComponent;
    request.u = uDirection;
    BSDFVertexQueries queries = bsdf.queryVertex(hit->bsdfContext(), wi, wl, request);
    // Without a chooser at most one light sample was drawn, and it is traced.
    const std::optional<ResampledLight> chosen = request.chooseLight ? chooser.chosen()
                                                 : drawn == 1        ? std::optional(ResampledLight{0, 1.0f})
                                                                     : std::nullopt;
    if (chosen) {
      const size_t i = size_t(chosen->index);
      if (auto ds = connectToLight(scene, *hit, lights[i], toLights[i], wl, rays))
        L += beta * ds->value * (chosen->weight * emitterSampleWeight(ds->deltaLight, ds->lightPdf, ds->bsdfPdf));
    }

    const std::optional<BSDFSample>& bs = queries.sampled;
    if (!bs) break;
    beta *= bs->weight;
    if (beta.isZero() || !beta.isFinite()) break;
    Vec3 woWorld = hit->shading.toWorld(bs->wo);
    ray = hit->spawnRay(woWorld);
    if (bs->passThrough) {
      // The ray goes on as if the surface were not there: same MIS state, no bounce.
      if (++passThroughSteps > kMaxPassThroughSteps) break;
      continue;
    }
    deltaBounce = bs->delta;
    prevBsdfPdf = bs->pdf;
    prevEmitterSet = emitterSet;
    prevP = hit->p;
    ++depth;
    if (depth >= rrDepth_) {
      float q = std::min(beta.maxValue(), 0.95f);
      if (sampler.get1D() >= q) break;
      beta /= q;
    }
  }
  return L;
}

std::shared_ptr<Object> makePathIntegratorWith(const Properties& props, PathIntegrator::Strategy strategy,
                                               int emitterCandidates) {
  int maxDepth = props.getInt("max_depth", -1), rrDepth = props.getInt("rr_depth", 5);
  if (maxDepth < -1) throw props.error("max_depth", "max_depth must be -1 (unlimited) or non-negative");
  if (rrDepth < 1) throw props.error("rr_depth", "rr_depth must be at least 1");
  readMitsubaPassParameters(props);
  return std::make_shared<PathIntegrator>(maxDepth, rrDepth, props.getBool("hide_emitters", false), strategy,
                                          emitterCandidates);
}

std::shared_ptr<Object> makePathIntegrator(const Properties& props) {
  int emitterCandidates = props.getInt("emitter_candidates", PathIntegrator::kAutomatic);
  if (emitterCandidates < 0 || emitterCandidates > kMaxLightDirections)
    throw props.error("emitter_candidates", "emitter_candidates must be 0 (automatic) or a whole number from 1 to " +
                                                std::to_string(kMaxLightDirections) + ", not " +
                                                std::to_string(emitterCandidates));
  std::string strategy = props.getString("strategy", "mis");
  static const std::map<std::string, PathIntegrator::Strategy> kStrategies = {
      {"mis", PathIntegrator::Strategy::MIS},
      {"emitter", PathIntegrator::Strategy::EmitterOnly},
      {"bsdf", PathIntegrator::Strategy::BSDFOnly}};
  auto found = kStrategies.find(strategy);
  if (found == kStrategies.end())
    throw props.error("strategy", "strategy must be 'mis', 'emitter' or 'bsdf', not '" + strategy + "'");
  return makePathIntegratorWith(props, found->second, emitterCandidates);
}

}  // namespace columba
