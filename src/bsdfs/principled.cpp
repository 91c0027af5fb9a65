/*! plugin bsdf principled
The principled BSDF after Burley's Disney model (the 2012 BRDF and the 2015 BSDF without its subsurface and volume parts): an anisotropic GGX main specular lobe, a specular transmission lobe (rough refraction tinted by √base_color), Disney's diffuse with retro-reflection blended toward its subsurface approximation by `flatness`, a sheen and a GTR1 clearcoat. The lobes add up, so with a white base they can reflect more than the light they receive, as in Mitsuba 3.
Mitsuba 3: Mitsuba 3's parameters and defaults; no subsurface scattering, as in Mitsuba 3. All but `eta`, `specular` and the sampling rates may be textures.
| parameter | type | default | meaning | Mitsuba 3 |
| base_color | spectrum or texture | 0.5 | the base colour | same |
| roughness | float or texture | 0.5 | the specular lobes' roughness, 0 to 1 | same |
| anisotropic | float or texture | 0 | the anisotropy of the specular lobe, 0 to 1 | same |
| metallic | float or texture | 0 | the blend toward a metal, 0 to 1 | same |
| spec_trans | float or texture | 0 | the blend toward specular transmission, 0 to 1 | same |
| eta | float | from `specular` | the relative index of refraction; positive; not together with `specular` (1 becomes 1.001 when the surface transmits) | same |
| specular | float | 0.5 | the normal-incidence reflectance R₀ / 0.08, in [0, 12.5), used when `eta` is not given: η = 2 / (1 − √(0.08 specular)) − 1 | same |
| spec_tint | float or texture | 0 | tints the dielectric specular reflection toward the base colour, 0 to 1 | same |
| sheen | float or texture | 0 | the sheen's weight, 0 to 1 | same |
| sheen_tint | float or texture | 0 | tints the sheen toward the base colour, 0 to 1 | same |
| flatness | float or texture | 0 | the blend of the diffuse lobe toward the subsurface approximation, 0 to 1 | same |
| clearcoat | float or texture | 0 | the clearcoat's weight (the lobe weighs clearcoat / 4), 0 to 1 | same |
| clearcoat_gloss | float or texture | 0 | the clearcoat's glossiness, 0 to 1 | same |
| diffuse_reflectance_sampling_rate | float | 1 | the relative rate at which the diffuse lobe is sampled; not negative | same |
| main_specular_sampling_rate | float | 1 | the same for the main specular lobe | same |
| clearcoat_sampling_rate | float | 1 | the same for the clearcoat | same |
*/
#include "bsdfs/principled.h"

#include <cmath>
#include "bsdfs/microfacet_interface.h"
#include "core/sampling.h"
#include "optics/fresnel.h"

namespace columba {

PrincipledBSDF::PrincipledBSDF(PrincipledParameters parameters) : p_(std::move(parameters)) {}

PrincipledBSDF::Material PrincipledBSDF::materialAt(const BSDFContext& ctx, const Wavelengths& wl) const {
  const TexturePoint& at = ctx.point;
  const Spectrum base = p_.baseColor.eval(at, wl);
  const float metallic = p_.metallic.eval(at), specTrans = p_.specTrans.eval(at), roughness = p_.roughness.eval(at);
  return Material{base,
                  tintColour(base, p_.baseColor.evalLuminance(at)),
                  roughness,
                  metallic,
                  p_.specTint.eval(at),
                  p_.sheen.eval(at),
                  p_.sheenTint.eval(at),
                  p_.flatness.eval(at),
                  p_.clearcoat.eval(at),
                  (1.0f - metallic) * (1.0f - specTrans),
                  (1.0f - metallic) * specTrans,
                  principledDistribution(roughness, p_.anisotropic.eval(at)),
                  GTR1Distribution::fromGloss(p_.clearcoatGloss.eval(at))};
}

PrincipledBSDF::Strategies PrincipledBSDF::strategies(const Material& material, bool front) const {
  Strategies s;
  if (!front) {
    s.specular = 1.0f;
    return s;
  }
  s.diffuse = material.diffuseWeight * p_.diffuseSamplingRate;
  // The clearcoat carries about a quarter of the main specular lobe's energy.
  s.clearcoat = 0.25f * material.clearcoat * p_.clearcoatSamplingRate;
  s.specular = p_.specularSamplingRate;
  float total = s.diffuse + s.clearcoat + s.specular;
  if (!(total > 0.0f)) return Strategies{};
  s.diffuse /= total;
  s.clearcoat /= total;
  s.specular /= total;
  return s;
}

float PrincipledBSDF::specularReflectionShare(const Material& material, bool front, float fresnel) {
  // Light the dielectric part would refract is reflected by the metallic and opaque parts.
  return front ? 1.0f - material.transmissionWeight * (1.0f - fresnel) : fresnel;
}

Spectrum PrincipledBSDF::frontFresnel(const Material& material, float cosI, float dielectricFresnel) const {
  float weight = schlickFresnelWeight(cosI, p_.eta);
  Spectrum metal = schlickFresnel(material.baseColor, weight);
  Spectrum tinted = schlickFresnel(material.tint * normalIncidenceReflectance(p_.eta), weight);
  float dielectric = 1.0f - material.metallic;
  return Spectrum(dielectric * (1.0f - material.specTint) * dielectricFresnel) + metal * material.metallic +
         tinted * (dielectric * material.specTint);
}

Spectrum PrincipledBSDF::valueFor(const Material& material, const Vec3& wi, const Vec3& wo) const {
  if (cosTheta(wi) == 0.0f || cosTheta(wo) == 0.0f) return Spectrum(0.0f);
  const bool front = cosTheta(wi) > 0.0f;
  if (!front && !(material.transmissionWeight > 0.0f)) return Spectrum(0.0f);

  Spectrum value(0.0f);
  InterfacePair pair = interfacePair(wi, wo, p_.eta);
  if (pair.valid) {
    float cosI = dot(pair.wi, pair.m);
    float fresnel = fresnelDielectric(cosI, pair.eta);
    float microfacet = interfaceValue(material.specular, pair);
    if (pair.reflection) {
      value += (front ? frontFresnel(material, cosI, fresnel) : Spectrum(material.transmissionWeight * fresnel)) *
               microfacet;
      if (front && material.clearcoat > 0.0f) {
        float coatFresnel = 0.04f + 0.96f * schlickFresnelWeight(cosI, p_.eta);  // Schlick, R0 = 0.04
        value += Spectrum(0.25f * material.clearcoat * coatFresnel * material.coat.D(pair.m) *
                          clearcoatShadowing(pair.wi, pair.wo, pair.m) * cosTheta(wo));
      }
    } else if (material.transmissionWeight > 0.0f) {
      Spectrum tint;
      for (int i = 0; i < kSpectrumSamples; ++i) tint[i] = std::sqrt(material.baseColor[i]);
      value += tint * (material.transmissionWeight * (1.0f - fresnel) * microfacet);
    }
  }

  if (front && cosTheta(wo) > 0.0f && material.diffuseWeight > 0.0f) {
    // For a front-side reflection the pair is always valid: m is the half vector.
    float cosD = dot(pair.m, wo);
    float diffuse = principledDiffuse(cosTheta(wi), cosTheta(wo), cosD, material.roughness, material.flatness);
    value += material.baseColor * (material.diffuseWeight * diffuse * kInvPi * cosTheta(wo));
    if (material.sheen > 0.0f) {
      value += sheenColour(material.tint, material.sheenTint) *
               (material.sheen * (1.0f - material.metallic) * schlickWeight(cosD) * cosTheta(wo));
    }
  }
  return value;
}

float PrincipledBSDF::densityFor(const Material& material, const Vec3& wi, const Vec3& wo) const {
  if (cosTheta(wi) == 0.0f || cosTheta(wo) == 0.0f) return 0.0f;
  const bool front = cosTheta(wi) > 0.0f;
  if (!front && !(material.transmissionWeight > 0.0f)) return 0.0f;
  const Strategies strategy = strategies(material, front);

  float density = 0.0f;
  InterfacePair pair = interfacePair(wi, wo, p_.eta);
  if (pair.valid) {
    float fresnel = fresnelDielectric(dot(pair.wi, pair.m), pair.eta);
    float reflectionShare = specularReflectionShare(material, front, fresnel);
    float share = pair.reflection ? reflectionShare : 1.0f - reflectionShare;
    density += strategy.specular * share * interfaceDensity(material.specular, pair);
    if (pair.reflection && strategy.clearcoat > 0.0f)
      density += strategy.clearcoat * material.coat.pdf(pair.m) / (4.0f * dot(pair.wo, pair.m));
  }
  if (front && cosTheta(wo) > 0.0f) density += strategy.diffuse * cosineHemispherePdf(cosTheta(wo));
  return density;
}

std::optional<BSDFSample> PrincipledBSDF::sampleFor(const Material& material, const Vec3& wi, float uComponent,
                                                    Vec2 u) const {
  if (cosTheta(wi) == 0.0f) return std::nullopt;
  const bool front = cosTheta(wi) > 0.0f;
  if (!front && !(material.transmissionWeight > 0.0f)) return std::nullopt;
  const Strategies strategy = strategies(material, front);

  Vec3 wo;
  if (uComponent < strategy.diffuse) {
    wo = sampleCosineHemisphere(u);
  } else if (uComponent < strategy.diffuse + strategy.clearcoat) {
    Vec3 m = material.coat.sample(u);
    wo = reflect(wi, m);
    if (!(dot(wi, m) > 0.0f && cosTheta(wo) > 0.0f)) return std::nullopt;
  } else {
    if (!(strategy.specular > 0.0f)) return std::nullopt;
    // The rest of uComponent, rescaled to [0, 1), chooses between reflection and refraction.
    float uSpecular = (uComponent - strategy.diffuse - strategy.clearcoat) / strategy.specular;
    Vec3 side = front ? wi : mirroredThroughSurface(wi);
    float eta = front ? p_.eta : 1.0f / p_.eta;
    Vec3 m = material.specular.sampleVisible(side, u);
    float cosI = dot(side, m);
    if (!(cosI > 0.0f)) return std::nullopt;
    FresnelAmplitudes a = fresnelAmplitudes(cosI, eta);
    float fresnel = 0.5f * (a.rs * a.rs + a.rp * a.rp);
    bool reflection = uSpecular < specularReflectionShare(material, front, fresnel);
    if (!reflection && a.totalInternalReflection) return std::nullopt;
    wo = reflection ? reflect(side, m) : refractThrough(side, m, cosI, eta, a.cosT);
    // A reflection below the surface or a refraction back above it is light the neighbouring
    // microfacets stop: no sample.
    if (reflection != (cosTheta(wo) > 0.0f)) return std::nullopt;
    if (!front) wo = mirroredThroughSurface(wo);
  }

  // Several strategies reach most directions: weight by the mixture density (one-sample MIS).
  BSDFSample s;
  s.wo = wo;
  s.pdf = densityFor(material, wi, wo);
  if (!(s.pdf > 0.0f)) return std::nullopt;
  s.weight = valueFor(material, wi, wo) / s.pdf;
  return s;
}

std::shared_ptr<Object> makePrincipledBSDF(const Properties& props) {
  return std::make_shared<PrincipledBSDF>(readPrincipledParameters(props));
}

}  // namespace columba
