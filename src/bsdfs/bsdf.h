#pragma once
// The BSDF interface. Directions are in the local shading frame (z = normal) and point away
// from the surface: `wi` toward where the path came from (camera side), `wo` toward the light
// (Mitsuba's convention). Values include the cosine of `wo`.
#include <cmath>
#include <limits>
#include <optional>
#include "core/object.h"
#include "core/spectrum.h"
#include "core/vector.h"

namespace columba {

// Per-hit inputs besides the directions: per-point parameters supplied by the geometry
// (the feather's per-vertex barbule spacing, tilt and cortex thickness). NaN means "not given".
struct BSDFContext {
  float barbuleH = std::numeric_limits<float>::quiet_NaN();
  float barbuleMu = std::numeric_limits<float>::quiet_NaN();
  float barbuleHeight = std::numeric_limits<float>::quiet_NaN();
};

struct BSDFSample {
  Vec3 wo;
  Spectrum weight;     // f * |cos(wo)| / pdf
  float pdf = 0.0f;    // solid-angle density; for delta components, the component's probability
  bool delta = false;  // a delta component was chosen (no MIS with emitter sampling)
  // The pass-through ("null") component: wo = -wi, the ray just continues. Not a bounce.
  bool passThrough = false;
};

struct BSDFEvalPdf {
  Spectrum value;  // eval()
  float pdf = 0.0f;  // pdf()
};

// What a path vertex asks of its BSDF: the value and density toward a light sample, and a sampled
// continuation.
struct BSDFVertexQueries {
  BSDFEvalPdf toLight;
  std::optional<BSDFSample> sampled;
};

class BSDF : public Object {
 public:
  // f(wi, wo) * |cos(wo)| of the non-delta components.
  virtual Spectrum eval(const BSDFContext& ctx, const Vec3& wi, const Vec3& wo, const Wavelengths& wl) const = 0;
  // Density of `sample` producing `wo`, non-delta components only (solid angle).
  virtual float pdf(const BSDFContext& ctx, const Vec3& wi, const Vec3& wo, const Wavelengths& wl) const = 0;
  // Both at once (emitter sampling with MIS needs both): models share the work of the two.
  virtual BSDFEvalPdf evalPdf(const BSDFContext& ctx, const Vec3& wi, const Vec3& wo, const Wavelengths& wl) const {
    return {eval(ctx, wi, wo, wl), pdf(ctx, wi, wo, wl)};
  }
  // evalPdf toward `woLight` (when given) and sample, for the same wi: a path tracer's emitter
  // and BSDF sampling at one vertex. Models that derive much from wi alone share it.
  virtual BSDFVertexQueries evalPdfAndSample(const BSDFContext& ctx, const Vec3& wi, const Vec3* woLight,
                                             const Wavelengths& wl, float uComponent, Vec2 u) const {
    return {woLight ? evalPdf(ctx, wi, *woLight, wl) : BSDFEvalPdf{}, sample(ctx, wi, wl, uComponent, u)};
  }
  // `uComponent` picks a component, `u` drives it. nullopt = absorbed / rejected.
  virtual std::optional<BSDFSample> sample(const BSDFContext& ctx, const Vec3& wi, const Wavelengths& wl,
                                           float uComponent, Vec2 u) const = 0;
  // Weight of light passing straight through along -wi (shadow rays are attenuated by it).
  virtual Spectrum passThrough(const BSDFContext&, const Vec3& /*wi*/, const Wavelengths&) const { return Spectrum(0.0f); }
  virtual bool hasPassThrough() const { return false; }
  // True when all scattering is delta: emitter sampling is pointless there.
  virtual bool isDeltaOnly() const { return false; }
};

inline float cosTheta(const Vec3& w) { return w.z; }
inline float absCosTheta(const Vec3& w) { return std::abs(w.z); }
inline bool sameHemisphere(const Vec3& a, const Vec3& b) { return a.z * b.z > 0.0f; }

}  // namespace columba
