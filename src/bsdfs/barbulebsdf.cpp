/*! plugin bsdf barbulebsdf barbulebsdfev
The barbule BSDF of rock dove neck feathers (Huang et al. 2022): a vane of parallel barbules with elliptical cross-sections, coated by a thin keratin film over melanin. Its lobes are R, the specular reflection off the film with thin-film interference (a microfacet lobe whose normals come from the cross-section's curvature), TRT, light through the film reflected by the melanin layer and back out, and T, light straight through the gaps between barbules (a pass-through). The frame has z along the vane normal and y along the barbule axis. `barbulebsdf` takes the camera side as the model's incident direction, as a BSDF-sampled path tracer needs; `barbulebsdfev` takes the light's, as the paper's emitter-sampled visualisations do, and returns what an imaging scatterometer records, f · |cos θ_camera|. The [model](../model.md) page derives the lobes.

On a feather whose file gives per-vertex values of `H`, `mu` or `height`, those win over a constant given here (with a warning naming the line); a texture given here wins over them. A feather whose file gives each vertex a `stack` (docs/feather-ply.md) chooses among this BSDF's layer stacks by number: `layers` is stack 0, `layers_1` stack 1, and so on; a stack the BSDF lacks is an error naming the vertex.
Mitsuba 3: not in Mitsuba 3.
| parameter | type | default | meaning | Mitsuba 3 |
| preset | string | — | a named set of shape parameters and film thickness (`dove-green`, `dove-purple`); parameters given beside it override its values | not in Mitsuba 3 |
| b | float or texture | 0.25 | the cross-section's semi-axis along the vane normal (the one across is 1); positive | not in Mitsuba 3 |
| phi_0 | float | −0.37 | the start of the reflective arc: a normal angle, in radians, in the cross-section's frame | not in Mitsuba 3 |
| phi_1 | float | 2.64 | the end of the reflective arc; φ₁ − φ₀ lies in (0, π] or is at least 2π | not in Mitsuba 3 |
| mu | float or texture | −0.35 | the tilt of the cross-section about the barbule axis, in radians | not in Mitsuba 3 |
| H | float or texture | 1.25 | the barbule spacing, in units of the across semi-axis; positive | not in Mitsuba 3 |
| profile_exponent | float | 2 | the cross-section's shape: the superellipse on which (u/b)^p + v^p = 1 in absolute values, with p from 2 (the paper's ellipse) to 16; larger values flatten its sides toward a rectangle with rounded corners, whose flat faces reflect like small mirrors (docs/model.md, "Cross-sections beyond the ellipse") | not in Mitsuba 3 |
| height | float or texture | 0.6 | the keratin film's thickness in micrometres; not negative (a value that looks like nanometres warns) | not in Mitsuba 3 |
| film_ior | float, string or spectrum | `keratin` | the film's index: a number, a named index, `keratin`, or a spectrum of the index against wavelength; it must exceed `ext_ior` | not in Mitsuba 3 |
| film_cauchy_a | float | — | the film's index as a Cauchy law a + b/λ², instead of `film_ior` | not in Mitsuba 3 |
| film_cauchy_b | float | 0 | the Cauchy law's b (λ in nanometres) | not in Mitsuba 3 |
| ext_ior | float or string | `air` (1.000277) | the surrounding medium's constant index | not in Mitsuba 3 |
| melanin | spectrum or float | measured table | the melanin layer's intensity reflectance against wavelength, 0 to 1; by default the embedded measured table | not in Mitsuba 3 |
| trt_offsets | integer | 4 | the TRT lobe's Gauss–Legendre nodes across the lit arc, 1 to 64: more for squarer profiles, whose normal turns fast at the corners (at p = 16 the default 4 is 1.6 % high, 16 within 0.3 % of exact; docs/model.md) | not in Mitsuba 3 |
| trt_angles | integer | 1 | the TRT lobe's nodes over the longitudinal angle, 1 to 16 (1: one node at the mean angle) | not in Mitsuba 3 |
| layers | string | — | layers under the cortex, from the cortex down, as `INDEX:THICKNESS, ...` (INDEX a number, a named index, `keratin`, `melanin` (Stavenga et al. 2015's n and k) or a complex `N+Ki`; thickness in µm), with rows of rods as `rods(INDEX, DIAMETER, SPACING[, MATRIX])` (effective layers, docs/model.md, "Rows of melanosomes as effective layers") and repeats as `[...] x N`, or the name of a published stack: `parotia-occipital` (Stavenga et al. 2015): R is then the whole stack's reflectance and TRT crosses the whole stack (transfer matrices; docs/model.md, "Layered films"), the medium below it `ext_ior` | not in Mitsuba 3 |
| layers_N | string | — | further layer stacks, `layers_1` to `layers_15`, as `layers` takes them, for the vertices of a feather whose file chooses them by number (`stack` N); numbered from 1 without gaps | not in Mitsuba 3 |
*/
#include "bsdfs/barbulebsdf.h"

#include <algorithm>
#include <cmath>

#include "barbule/parameter_reader.h"

// The lobes' normalisation is derived in docs/model.md §7 (Energy), the sampler and its density
// (the paper's Algorithm 1, made to agree exactly with pdf()) in §8.

namespace columba {

namespace {

// A shape's value of a parameter at the point; a tilt or thickness of exactly 0 stands for the
// BSDF's own, as in the original implementation (docs/feather-ply.md).
std::optional<float> shapeValueUnlessZero(const BSDFContext& ctx, SurfaceAttributeKey key) {
  std::optional<float> v = ctx.attribute(key);
  return v && *v != 0.0f ? v : std::nullopt;
}

// A texture's value, `fallback` where it is not a finite number.
float finiteOr(float value, float fallback) { return std::isfinite(value) ? value : fallback; }

}  // namespace

BarbuleBSDF::BarbuleBSDF(const BarbuleParameters& params, Role role, BarbuleQuadrature quadrature)
    : model_(params, quadrature), role_(role) {}

BarbulePointModel BarbuleBSDF::pointModel(const BSDFContext& ctx, const Wavelengths& wl) const {
  return model_.at(overriddenGeometry(ctx), cortexThickness(ctx), wl, layerStack(ctx));
}

int BarbuleBSDF::layerStack(const BSDFContext& ctx) const {
  // Shapes choose only stacks the BSDF has (noteValuesGivenByShape refuses others).
  const std::optional<float> chosen = ctx.attribute(kLayerStackAttribute);
  if (!chosen || !(*chosen >= 0.0f)) return 0;
  return int(std::min(*chosen, float(model_.parameters().layerStackCount() - 1)));
}

void BarbuleBSDF::noteValuesGivenByShape(const ShapePointValues& given) const {
  if (sceneSources_) sceneSources_->warnIfShadowed(given.everywhere, given.shape);
  const int stacks = model_.parameters().layerStackCount();
  if (given.largestLayerStack >= stacks)
    throw InputError(given.largestLayerStackAt,
                     given.shape + " chooses layer stack " + std::to_string(given.largestLayerStack) + " (" +
                         given.largestLayerStackElement + "), but its barbulebsdf (" + declaredAt_.str() + ") has " +
                         (stacks == 1 ? std::string("only stack 0, `layers`")
                                      : "stacks 0 to " + std::to_string(stacks - 1) + ", `layers` to `" +
                                            layerStackParameter(stacks - 1) + "`"));
  if (given.largestLayerStack < 0 && stacks > 1 && !warnedNoStacks_->exchange(true))
    warn(numberedStacksAt_,
         "barbulebsdf, parameter '" + layerStackParameter(1) + "': " + given.shape +
             " chooses no layer stack per vertex (no vertex property 'stack'), so only `layers` applies there (said "
             "once, for the first such feather)");
}

float BarbuleBSDF::cortexThickness(const BSDFContext& ctx) const {
  const BarbuleParameters& params = model_.parameters();
  const float height = textures_.height.isTextured()
                           ? finiteOr(textures_.height.eval(ctx.point), 0.0f)
                           : shapeValueUnlessZero(ctx, kCortexThicknessAttribute).value_or(params.height);
  return std::max(height, 0.0f);
}

std::optional<BarbuleCrossSection> BarbuleBSDF::overriddenGeometry(const BSDFContext& ctx) const {
  const BarbuleParameters& params = model_.parameters();
  // A texture wins over the shape's value; a spacing below contact acts as contact.
  std::optional<float> mu = textures_.mu.isTextured() ? finiteOr(textures_.mu.eval(ctx.point), params.mu)
                                                      : shapeValueUnlessZero(ctx, kBarbuleTiltAttribute);
  std::optional<float> H = textures_.H.isTextured() ? finiteOr(textures_.H.eval(ctx.point), params.H)
                                                    : ctx.attribute(kBarbuleSpacingAttribute);
  if (textures_.b.isTextured()) {
    // A semi-axis that is not positive (or not a number) is taken as a thin one.
    constexpr float kThinnest = 1e-3f;
    const float b = textures_.b.eval(ctx.point);
    return BarbuleCrossSection(b > kThinnest ? b : kThinnest, params.phi0, params.phi1, mu.value_or(params.mu),
                               H.value_or(params.H), params.profileExponent);
  }
  if (!mu && !H) return std::nullopt;
  return model_.geometry().withTiltAndSpacing(mu.value_or(params.mu), H.value_or(params.H));
}

Spectrum BarbuleBSDF::roleValue(const BarbulePointModel& point, const BarbuleIncident& fromWi, const Vec3& wo,
                                const LitArc& woArc) const {
  if (role_ == Role::CameraIncident) return point.value(fromWi, point.outgoing(fromWi, wo, woArc));
  // The scatterometer's quantity: light from wo, the camera's cosine (wi), so that a visualiser
  // image is the power scattered per solid angle toward each camera direction.
  BarbuleIncident fromWo = point.incident(wo, woArc);
  return point.value(fromWo, point.outgoing(fromWo, fromWi.w, fromWi.arc));
}

BSDFEvalPdf BarbuleBSDF::roleValueAndPdf(const BarbulePointModel& point, const BarbuleScattering& fromWi,
                                         const Vec3& wo, const LitArc& woArc, float mirrorVisible) const {
  BarbuleOutgoing out = point.outgoing(fromWi.in, wo, woArc);
  // With omega_i on the camera side, value and density share the pair's geometry.
  Spectrum value = role_ == Role::CameraIncident ? point.value(fromWi.in, out) : roleValue(point, fromWi.in, wo, woArc);
  return {value, point.densities(fromWi, out, mirrorVisible).total()};
}

Spectrum BarbuleBSDF::eval(const BSDFContext& ctx, const Vec3& wi, const Vec3& wo, const Wavelengths& wl) const {
  BarbulePointModel point = pointModel(ctx, wl);
  LitArc wiArc = point.litArc(wi), woArc = point.litArc(wo);
  return roleValue(point, point.incident(wi, wiArc), wo, woArc);
}

float BarbuleBSDF::pdf(const BSDFContext& ctx, const Vec3& wi, const Vec3& wo, const Wavelengths& wl) const {
  return lobePdfs(ctx, wi, wo, wl).total();
}

BarbuleBSDF::LobeDensities BarbuleBSDF::lobePdfs(const BSDFContext& ctx, const Vec3& wi, const Vec3& wo,
                                                 const Wavelengths& wl) const {
  BarbulePointModel point = pointModel(ctx, wl);
  BarbuleScattering s = point.scattering(wi, ctx.passThroughByCaller);
  if (!s.in.scatters) return {};
  return point.densities(s, point.outgoing(s.in, wo, point.litArc(wo)));
}

std::optional<BSDFSample> BarbuleBSDF::sample(const BSDFContext& ctx, const Vec3& wi, const Wavelengths& wl,
                                              float uComponent, Vec2 u) const {
  BarbulePointModel point = pointModel(ctx, wl);
  return sampleAt(point, point.scattering(wi, ctx.passThroughByCaller), uComponent, u);
}

BSDFVertexQueries BarbuleBSDF::queryVertex(const BSDFContext& ctx, const Vec3& wi, const Wavelengths& wl,
                                           const BSDFVertexRequest& request) const {
  BarbulePointModel point = pointModel(ctx, wl);
  bool needsChoice = request.sample || (request.woLightCount > 0 && request.lightPdf);
  const BarbuleScattering s =
      needsChoice ? point.scattering(wi, ctx.passThroughByCaller) : BarbuleScattering{point.incident(wi), {}};
  BSDFVertexQueries q;
  auto evaluateTowardLight = [&](int k, const LitArc& woArc) {
    const Vec3& wo = request.woLights[k];
    request.toLights[k] =
        request.lightPdf ? roleValueAndPdf(point, s, wo, woArc) : BSDFEvalPdf{roleValue(point, s.in, wo, woArc), 0.0f};
  };
  // With a chooser and cheap targets: the targets toward every candidate, the full value (TRT's
  // quadrature) and density toward the chosen one only. Otherwise the values are the targets.
  const bool cheapTargets = request.chooseLight && hasCheapResamplingTargets();
  auto litArcToward = [&](int k) { return point.litArc(request.woLights[k]); };
  for (int k = 0; k < request.woLightCount; ++k) {
    if (cheapTargets)
      request.toLights[k] = {point.resamplingTarget(s.in, request.woLights[k], litArcToward(k)), 0.0f};
    else
      evaluateTowardLight(k, litArcToward(k));
  }
  if (request.chooseLight) {
    const int chosen = request.chooseLight->choose(request.toLights, request.woLightCount);
    if (cheapTargets && chosen >= 0) evaluateTowardLight(chosen, litArcToward(chosen));  // its arc again: cheap
  }
  if (request.sample) q.sampled = sampleAt(point, s, request.uComponent, request.u, request.samplePdf);
  if (request.passThrough) q.passThrough = Spectrum(point.transmission(s.in));
  return q;
}

std::optional<BSDFSample> BarbuleBSDF::sampleAt(const BarbulePointModel& point, const BarbuleScattering& fromWi,
                                                float uComponent, Vec2 u, bool withPdf) const {
  // barbulebsdf weighs a sample by the drawing lobe's value over its density (the model's);
  // barbulebsdfev by its value over the sampler's density, the model's omega_i being wo.
  const bool lightIncident = role_ == Role::LightIncident;
  std::optional<BarbuleSample> drawn = point.sample(fromWi, uComponent, u, !lightIncident, withPdf);
  if (!drawn) return std::nullopt;
  BSDFSample bs;
  bs.wo = drawn->wo;
  if (drawn->lobe == BarbuleSample::Lobe::T) {
    bs.pdf = drawn->pdf;
    bs.weight = drawn->weight;
    bs.delta = bs.passThrough = true;
    return bs;
  }
  if (lightIncident) {
    BSDFEvalPdf f = roleValueAndPdf(point, fromWi, bs.wo, drawn->woArc, drawn->mirrorVisible);
    bs.pdf = f.pdf;
    if (!(bs.pdf > 0.0f)) return std::nullopt;
    bs.weight = f.value / bs.pdf;
    return bs;
  }
  bs.pdf = drawn->pdf;
  bs.weight = drawn->weight;
  return bs;
}

Spectrum BarbuleBSDF::passThrough(const BSDFContext& ctx, const Vec3& wi, const Wavelengths&) const {
  std::optional<BarbuleCrossSection> own = overriddenGeometry(ctx);
  return Spectrum(gapTransmission(own ? *own : model_.geometry(), wi));
}

BarbuleBSDF::Lobes BarbuleBSDF::evalLobes(const BSDFContext& ctx, const Vec3& omegaI, const Vec3& omegaO,
                                          const Wavelengths& wl) const {
  BarbulePointModel point = pointModel(ctx, wl);
  BarbuleIncident in = point.incident(omegaI);
  return point.lobes(in, point.outgoing(in, omegaO, point.litArc(omegaO)));
}

float BarbuleBSDF::coverage(const BSDFContext& ctx, const Vec3& omegaI) const {
  std::optional<BarbuleCrossSection> own = overriddenGeometry(ctx);
  return 1.0f - gapTransmission(own ? *own : model_.geometry(), omegaI);
}

namespace {

std::shared_ptr<Object> makeBarbule(const Properties& props, BarbuleBSDF::Role role) {
  std::optional<BarbuleParameterProblem> odd;
  BarbuleParameters params = readBarbuleParameters(props, odd);
  params.numberedLayerStacks = readNumberedLayerStacks(props);
  auto bsdf = std::make_shared<BarbuleBSDF>(params, role, readBarbuleQuadrature(props));
  if (odd) warn(props.locationOf(odd->parameter), "barbulebsdf, parameter '" + odd->parameter + "': " + odd->message);
  const BarbuleParameters& p = bsdf->parameters();
  BarbuleTextures textures{readFloatParameter(props, "b", p.b), readFloatParameter(props, "mu", p.mu),
                           readFloatParameter(props, "H", p.H), readFloatParameter(props, "height", p.height)};
  bsdf->setSceneSources(std::make_shared<PerPointParameterSources>(
                            props, "preset",
                            std::initializer_list<PerPointParameterSources::Parameter>{
                                {"H", kBarbuleSpacingAttribute, textures.H.isTextured()},
                                {"mu", kBarbuleTiltAttribute, textures.mu.isTextured()},
                                {"height", kCortexThicknessAttribute, textures.height.isTextured()}}),
                        props.location, props.locationOf(layerStackParameter(1)));
  bsdf->setTextures(std::move(textures));
  return bsdf;
}

}  // namespace

std::shared_ptr<Object> makeBarbuleBSDF(const Properties& props) {
  return makeBarbule(props, BarbuleBSDF::Role::CameraIncident);
}

std::shared_ptr<Object> makeBarbuleBSDFEv(const Properties& props) {
  return makeBarbule(props, BarbuleBSDF::Role::LightIncident);
}

}  // namespace columba
