#pragma once
// Terms of the Disney principled model (Burley 2012, "Physically Based Shading at Disney";
// Burley 2015, "Extending the Disney BRDF to a BSDF with Integrated Subsurface Scattering") in
// the form Mitsuba 3's `principled` and `principledthin` BSDFs use them. Directions are in the
// local shading frame.
#include "bsdfs/microfacet.h"
#include "core/spectrum.h"
#include "core/vector.h"

namespace columba {

// Schlick's (1 - cos)^5, with cos clamped to [0, 1].
float schlickWeight(float cosTheta);

// The weight w of Schlick's approximation F = R0 + (1 - R0) w for light meeting a microfacet at
// cosI (> 0) with relative index eta: taken at the angle on the optically thinner side, which is
// the refracted angle when eta < 1 (1 under total internal reflection).
float schlickFresnelWeight(float cosI, float eta);

// Schlick's approximation with that weight, per wavelength.
inline Spectrum schlickFresnel(const Spectrum& r0, float weight) { return r0 + (Spectrum(1.0f) - r0) * weight; }

// Normal-incidence reflectance of an interface with relative index eta.
float normalIncidenceReflectance(float eta);

// base / luminance: the base colour's hue at unit luminance, the tint of the specular and sheen
// lobes (white for a black base).
Spectrum tintColour(const Spectrum& base, float baseLuminance);

// The sheen's colour: white blended toward the tint by sheenTint.
inline Spectrum sheenColour(const Spectrum& tint, float sheenTint) {
  return Spectrum(1.0f - sheenTint) + tint * sheenTint;
}

// The GGX distribution of the main specular lobes: alpha = roughness^2, stretched along x and
// squeezed along y by sqrt(1 - 0.9 anisotropic), and at least 0.001.
MicrofacetDistribution principledDistribution(float roughness, float anisotropic);

// The clearcoat's normal distribution, Berry's (GTR with exponent 1), isotropic:
// D(m) = (alpha^2 - 1) / (pi ln(alpha^2) (1 + (alpha^2 - 1) cos^2 theta_m)), sampled exactly
// (not through the visible normals).
class GTR1Distribution {
 public:
  explicit GTR1Distribution(float alpha) : alpha_(alpha) {}
  // alpha from clearcoat_gloss: 0.1 (gloss 0) to 0.001 (gloss 1).
  static GTR1Distribution fromGloss(float gloss);

  float D(const Vec3& m) const;
  Vec3 sample(Vec2 u) const;
  // Density of `sample` producing m: D(m) cos(theta_m).
  float pdf(const Vec3& m) const;

 private:
  float alpha_;
};

// The clearcoat's shadowing-masking: Smith's for GGX with a fixed alpha of 0.25 (Burley 2012).
float clearcoatShadowing(const Vec3& wi, const Vec3& wo, const Vec3& m);

// Disney's diffuse factor f_d * pi / base colour for reflection between directions with cosines
// cosI and cosO (> 0) whose half vector makes cosD with them: Lambert with the Schlick-shaped
// grazing darkening and the roughness-driven retro-reflection (Burley 2015, eq. 4-5), blended by
// `flatness` toward the Hanrahan-Krueger-like subsurface approximation of Burley 2012.
float principledDiffuse(float cosI, float cosO, float cosD, float roughness, float flatness);

}  // namespace columba
