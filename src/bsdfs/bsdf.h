#pragma once
// The BSDF interface. Directions are in the local shading frame (z = normal) and point away
// from the surface: `wi` toward where the path came from (camera side), `wo` toward the light
// (Mitsuba's convention). Values include the cosine of `wo`.
#include <cmath>
#include <optional>
#include <string>
#include <string_view>
#include "core/object.h"
#include "core/shape_point_values.h"
#include "core/spectrum.h"
#include "core/surface_attributes.h"
#include "core/vector.h"
#include "textures/texture_point.h"

namespace columba {

// Per-call inputs besides the directions: where textured parameters are looked up (its surface
// coordinates, on meshes with per-vertex or per-face values the triangle and barycentric
// coordinates, and the values of BSDF parameters its shape gives per point, none by default), and
// the derivatives of the position in u and v (in the local shading frame; zero where the shape
// gives none), which bump maps perturb.
struct BSDFContext {
  TexturePoint point;
  Vec3 dpdu, dpdv;
  // The caller carries light straight through the surface itself (it continues the ray with
  // passThrough()'s weight), so sample() draws from the scattering components only and pdf() is
  // their density given that, as Mitsuba's context without the null component asks. A BSDF may
  // ignore it: then sample() and pdf() keep the pass-through among their choices and the caller
  // drops pass-through samples, which costs samples but no correctness.
  bool passThroughByCaller = false;

  std::optional<float> attribute(SurfaceAttributeKey key) const {
    return point.attributes ? point.attributes->find(key) : std::nullopt;
  }
};

struct BSDFSample {
  Vec3 wo;
  // f * |cos(wo)| / pdf, or an estimate of it with the same mean against any function of wo (a
  // BSDF that estimates each lobe by its own samples: that lobe's value over its density).
  Spectrum weight;
  float pdf = 0.0f;    // solid-angle density; for delta components, the component's probability
  bool delta = false;  // a delta component was chosen (no MIS with emitter sampling)
  // The pass-through ("null") component: wo = -wi, the ray just continues. Not a bounce.
  bool passThrough = false;
};

struct BSDFEvalPdf {
  Spectrum value;    // eval()
  float pdf = 0.0f;  // pdf()
};

// The most directions toward light samples one vertex query evaluates (PathIntegrator's
// emitter_candidates).
inline constexpr int kMaxLightDirections = 8;
// Chooses which of a vertex's light directions to trace, from the BSDF's resampling targets toward
// them (PathIntegrator's emitter candidates): returns the index chosen, or -1 for none.
class LightChooser {
 public:
  virtual int choose(const BSDFEvalPdf* targets, int count) = 0;

 protected:
  ~LightChooser() = default;
};
// What an integrator asks of a BSDF at one path vertex, for one wi: the values toward light
// samples (and, for MIS, their densities), a sampled continuation, the pass-through weight.
// Asked together, they share what the model derives from wi alone.
struct BSDFVertexRequest {
  const Vec3* woLights = nullptr;   // evaluate toward these directions (light samples)
  int woLightCount = 0;             // at most kMaxLightDirections
  BSDFEvalPdf* toLights = nullptr;  // where their values go, woLightCount of them (the caller's
                                    // storage: queries stay small at every vertex)
  bool lightPdf = false;            // with the density of sampling each (pdf 0 otherwise)
  // With a chooser, the BSDF hands it a resampling target toward each light direction (its value,
  // or a cheaper guide that is positive at every wavelength where the value is), and only the
  // chosen direction's entry of toLights ends up holding the value (and density).
  LightChooser* chooseLight = nullptr;
  bool sample = false;  // draw a continuation from uComponent and u
  float uComponent = 0.0f;
  Vec2 u;
  // false: the caller reads only the sample's direction and weight (it weighs no other strategy
  // against it), and the BSDF may leave the sample's pdf 0 where working it out costs extra.
  bool samplePdf = true;
  bool passThrough = false;
};
struct BSDFVertexQueries {
  std::optional<BSDFSample> sampled;  // nullopt unless asked
  Spectrum passThrough;               // 0 unless asked
};

// Answers `request` with callables: eval(wo), pdf(wo), sample(uComponent, u) and passThrough(). A
// BSDF that works something out once per vertex (its material at a textured point) answers all
// the queries with callables that share it.
template <typename Eval, typename Pdf, typename Sample, typename PassThrough>
BSDFVertexQueries answerVertexQueries(const BSDFVertexRequest& request, Eval&& eval, Pdf&& pdf, Sample&& sample,
                                      PassThrough&& passThrough) {
  BSDFVertexQueries q;
  if (request.chooseLight) {
    // The values are the targets; only the chosen direction needs a density.
    for (int k = 0; k < request.woLightCount; ++k) request.toLights[k] = {eval(request.woLights[k]), 0.0f};
    const int chosen = request.chooseLight->choose(request.toLights, request.woLightCount);
    if (chosen >= 0 && request.lightPdf) request.toLights[chosen].pdf = pdf(request.woLights[chosen]);
  } else {
    for (int k = 0; k < request.woLightCount; ++k) {
      const Vec3& wo = request.woLights[k];
      request.toLights[k] = {eval(wo), request.lightPdf ? pdf(wo) : 0.0f};
    }
  }
  if (request.sample) q.sampled = sample(request.uComponent, request.u);
  if (request.passThrough) q.passThrough = passThrough();
  return q;
}

class BSDF : public Object {
 public:
  // f(wi, wo) * |cos(wo)| of the non-delta components.
  virtual Spectrum eval(const BSDFContext& ctx, const Vec3& wi, const Vec3& wo, const Wavelengths& wl) const = 0;
  // Density of `sample` producing `wo`, non-delta components only (solid angle).
  virtual float pdf(const BSDFContext& ctx, const Vec3& wi, const Vec3& wo, const Wavelengths& wl) const = 0;
  // Whether queryVertex hands a LightChooser targets far cheaper than its values (so that drawing
  // several emitter candidates costs little more than one).
  virtual bool hasCheapResamplingTargets() const { return false; }
  // The requested queries at one vertex; the same values as the separate calls.
  virtual BSDFVertexQueries queryVertex(const BSDFContext& ctx, const Vec3& wi, const Wavelengths& wl,
                                        const BSDFVertexRequest& request) const {
    return answerVertexQueries(
        request, [&](const Vec3& wo) { return eval(ctx, wi, wo, wl); },
        [&](const Vec3& wo) { return pdf(ctx, wi, wo, wl); },
        [&](float uComponent, Vec2 u) { return sample(ctx, wi, wl, uComponent, u); },
        [&] { return passThrough(ctx, wi, wl); });
  }
  // `uComponent` picks a component, `u` drives it. nullopt = absorbed / rejected.
  virtual std::optional<BSDFSample> sample(const BSDFContext& ctx, const Vec3& wi, const Wavelengths& wl,
                                           float uComponent, Vec2 u) const = 0;
  // Weight of light passing straight through along -wi (shadow rays are attenuated by it).
  virtual Spectrum passThrough(const BSDFContext&, const Vec3& /*wi*/, const Wavelengths&) const {
    return Spectrum(0.0f);
  }
  virtual bool hasPassThrough() const { return false; }
  // True when all scattering is delta: emitter sampling is pointless there.
  virtual bool isDeltaOnly() const { return false; }
  // True when `sample` can draw every direction where the BSDF has a value (pdf > 0 there), so
  // that light it finds needs no emitter sample beside it (Scene::EmitterSet). False where a
  // user's parameters switch a strategy off.
  virtual bool samplesAllItScatters() const { return true; }
  // Called by a shape that gives BSDF parameters at its points (a feather's per-vertex barbule
  // values): a BSDF warns, once, for each parameter the scene gave it that `given.everywhere`
  // leaves without effect there, and throws InputError for a choice it cannot honour (a layer
  // stack it does not have).
  virtual void noteValuesGivenByShape(const ShapePointValues& /*given*/) const {}
  // True when the BSDF's values are not square-integrable over directions (a barbule whose flat
  // faces make its normal distribution singular): estimators that only evaluate it, without
  // sampling it, have an infinite variance (docs/model.md, "Which estimators converge").
  virtual bool hasSingularValues() const { return false; }
  // True when the BSDF's values turn with the shading frame's first axis about the normal (a
  // barbule's axis): a shape whose surface gives no such direction (a mesh without uvs) then
  // chooses one, and says so.
  virtual bool followsSurfaceAxis() const { return false; }
};

inline float cosTheta(const Vec3& w) { return w.z; }
inline float absCosTheta(const Vec3& w) { return std::abs(w.z); }
inline bool sameHemisphere(const Vec3& a, const Vec3& b) { return a.z * b.z > 0.0f; }
// The mirror direction of w about the shading normal (a smooth surface's specular reflection).
inline Vec3 mirrorDirection(const Vec3& w) { return Vec3(-w.x, -w.y, w.z); }

}  // namespace columba
