/*! plugin bsdf principledthin
The principled model for a sheet with no thickness (leaves, paper, cloth), after Burley 2015, section 5.3: both sides look the same and light crossing the sheet is not bent. Its lobes are a GGX specular reflection, the same lobe mirrored through the sheet as specular transmission (tinted by `base_color`, its roughness scaled by 0.65 η − 0.35), Disney's diffuse with flatness and sheen as in `principled`, and a Lambertian diffuse transmission tinted by `base_color`.
Mitsuba 3: Mitsuba 3's parameters and defaults. All but the sampling rates may be textures.
| parameter | type | default | meaning | Mitsuba 3 |
| base_color | spectrum or texture | 0.5 | the base colour | same |
| roughness | float or texture | 0.5 | the specular lobes' roughness, 0 to 1 | same |
| anisotropic | float or texture | 0 | the specular lobes' anisotropy, 0 to 1 | same |
| spec_trans | float or texture | 0 | the weight of the specular lobes against the diffuse ones, 0 to 1 | same |
| diff_trans | float or texture | 0 | the share of diffuse transmission, 0 to 2 (diffuse transmission weighs diff_trans / 2) | same |
| eta | float or texture | 1.5 | the sheet's relative index of refraction; positive | same |
| spec_tint | float or texture | 0 | tints the specular reflection toward the base colour, 0 to 1 | same |
| sheen | float or texture | 0 | the sheen's weight, 0 to 1 | same |
| sheen_tint | float or texture | 0 | tints the sheen toward the base colour, 0 to 1 | same |
| flatness | float or texture | 0 | the blend of the diffuse lobe toward the subsurface approximation, 0 to 1 | same |
| specular_reflectance_sampling_rate | float | 1 | the relative rate at which the specular reflection is sampled; not negative | same |
| specular_transmittance_sampling_rate | float | 1 | the same for the specular transmission | same |
| diffuse_reflectance_sampling_rate | float | 1 | the same for the diffuse reflection | same |
| diffuse_transmittance_sampling_rate | float | 1 | the same for the diffuse transmission | same |
*/
#include "bsdfs/principledthin.h"

#include "bsdfs/microfacet_interface.h"
#include "bsdfs/principled_terms.h"
#include "core/sampling.h"
#include "optics/fresnel.h"

namespace columba {

namespace {
// The pair seen from wi's side (the sheet is the same from both), with wo's mirror image above
// the sheet when it crosses it: the direction the reflection lobe would have sent it.
struct SheetPair {
  Vec3 wi, wo, woAbove;
  bool reflection;
};

SheetPair sheetPair(const Vec3& wi, const Vec3& wo) {
  bool flip = cosTheta(wi) < 0.0f;
  SheetPair p;
  p.wi = flip ? mirroredThroughSurface(wi) : wi;
  p.wo = flip ? mirroredThroughSurface(wo) : wo;
  p.reflection = cosTheta(p.wo) > 0.0f;
  p.woAbove = p.reflection ? p.wo : mirroredThroughSurface(p.wo);
  return p;
}
}  // namespace

PrincipledThinBSDF::PrincipledThinBSDF(PrincipledThinParameters parameters) : p_(std::move(parameters)) {}

PrincipledThinBSDF::Material PrincipledThinBSDF::materialAt(const BSDFContext& ctx, const Wavelengths& wl) const {
  const TexturePoint& at = ctx.point;
  const Spectrum base = p_.baseColor.eval(at, wl);
  const float roughness = p_.roughness.eval(at), anisotropic = p_.anisotropic.eval(at), eta = p_.eta.eval(at);
  return Material{base,
                  tintColour(base, p_.baseColor.evalLuminance(at)),
                  roughness,
                  p_.specTrans.eval(at),
                  0.5f * p_.diffTrans.eval(at),
                  eta,
                  p_.specTint.eval(at),
                  p_.sheen.eval(at),
                  p_.sheenTint.eval(at),
                  p_.flatness.eval(at),
                  principledDistribution(roughness, anisotropic),
                  principledDistribution((0.65f * eta - 0.35f) * roughness, anisotropic)};
}

PrincipledThinBSDF::Strategies PrincipledThinBSDF::strategies(const Material& material) const {
  Strategies s;
  const float diffTrans = material.diffTrans;
  s.specularReflection = 0.5f * material.specTrans * p_.specularReflectionSamplingRate;
  s.specularTransmission = 0.5f * material.specTrans * p_.specularTransmissionSamplingRate;
  s.diffuseReflection = (1.0f - material.specTrans) * (1.0f - diffTrans) * p_.diffuseReflectionSamplingRate;
  s.diffuseTransmission = (1.0f - material.specTrans) * diffTrans * p_.diffuseTransmissionSamplingRate;
  float total = s.specularReflection + s.specularTransmission + s.diffuseReflection + s.diffuseTransmission;
  if (!(total > 0.0f)) return Strategies{};
  s.specularReflection /= total;
  s.specularTransmission /= total;
  s.diffuseReflection /= total;
  s.diffuseTransmission /= total;
  return s;
}

Spectrum PrincipledThinBSDF::valueFor(const Material& material, const Vec3& wi, const Vec3& wo) const {
  if (cosTheta(wi) == 0.0f || cosTheta(wo) == 0.0f) return Spectrum(0.0f);
  const SheetPair pair = sheetPair(wi, wo);
  const Vec3 m = normalize(pair.wi + pair.woAbove);
  const float cosI = cosTheta(pair.wi), cosO = std::abs(cosTheta(pair.wo));
  const float diffTrans = material.diffTrans, diffuseWeight = 1.0f - material.specTrans;

  Spectrum value(0.0f);
  // wi meets the front of m, and wo leaves on m's side (reflection) or through it (transmission).
  bool compatible = dot(pair.wi, m) > 0.0f && (dot(pair.wo, m) > 0.0f) == pair.reflection;
  if (material.specTrans > 0.0f && compatible) {
    float cosIm = dot(pair.wi, m);
    float fresnel = fresnelDielectric(cosIm, material.eta);
    if (pair.reflection) {
      Spectrum tinted = schlickFresnel(material.tint * normalIncidenceReflectance(material.eta),
                                       schlickFresnelWeight(cosIm, material.eta));
      Spectrum sheetFresnel = Spectrum((1.0f - material.specTint) * fresnel) + tinted * material.specTint;
      const MicrofacetDistribution& d = material.reflection;
      value += sheetFresnel * (material.specTrans * d.D(m) * d.G(pair.wi, pair.wo, m) / (4.0f * cosI));
    } else {
      const MicrofacetDistribution& d = material.transmission;
      value += material.baseColor *
               (material.specTrans * (1.0f - fresnel) * d.D(m) * d.G(pair.wi, pair.wo, m) / (4.0f * cosI));
    }
  }
  if (pair.reflection && diffTrans < 1.0f) {
    float cosD = dot(m, pair.wo);
    float diffuse = principledDiffuse(cosI, cosO, cosD, material.roughness, material.flatness);
    float weight = diffuseWeight * (1.0f - diffTrans) * cosO;
    value += material.baseColor * (weight * diffuse * kInvPi);
    if (material.sheen > 0.0f)
      value += sheenColour(material.tint, material.sheenTint) * (weight * material.sheen * schlickWeight(cosD));
  } else if (!pair.reflection && diffTrans > 0.0f) {
    value += material.baseColor * (diffuseWeight * diffTrans * kInvPi * cosO);
  }
  return value;
}

float PrincipledThinBSDF::densityFor(const Material& material, const Vec3& wi, const Vec3& wo) const {
  if (cosTheta(wi) == 0.0f || cosTheta(wo) == 0.0f) return 0.0f;
  const Strategies strategy = strategies(material);
  const SheetPair pair = sheetPair(wi, wo);
  float density = pair.reflection ? strategy.diffuseReflection * cosineHemispherePdf(cosTheta(pair.wo))
                                  : strategy.diffuseTransmission * cosineHemispherePdf(-cosTheta(pair.wo));
  if (material.specTrans > 0.0f) {
    const Vec3 m = normalize(pair.wi + pair.woAbove);
    bool compatible = dot(pair.wi, m) > 0.0f && (dot(pair.wo, m) > 0.0f) == pair.reflection;
    if (compatible) {
      // The reflection about m, mirrored when it crosses the sheet: dm / dwo of a reflection.
      float jacobian = 1.0f / (4.0f * dot(pair.woAbove, m));
      density += pair.reflection
                     ? strategy.specularReflection * material.reflection.visiblePdf(pair.wi, m) * jacobian
                     : strategy.specularTransmission * material.transmission.visiblePdf(pair.wi, m) * jacobian;
    }
  }
  return density;
}

std::optional<BSDFSample> PrincipledThinBSDF::sampleFor(const Material& material, const Vec3& wi, float uComponent,
                                                        Vec2 u) const {
  if (cosTheta(wi) == 0.0f) return std::nullopt;
  const bool flip = cosTheta(wi) < 0.0f;
  const Vec3 above = flip ? mirroredThroughSurface(wi) : wi;
  const Strategies strategy = strategies(material);

  Vec3 wo;  // seen from wi's side
  float specular = strategy.specularReflection + strategy.specularTransmission;
  if (uComponent < specular) {
    bool reflection = uComponent < strategy.specularReflection;
    Vec3 m = (reflection ? material.reflection : material.transmission).sampleVisible(above, u);
    wo = reflect(above, m);
    if (!(cosTheta(wo) > 0.0f && dot(above, m) > 0.0f)) return std::nullopt;
    if (!reflection) {
      wo = mirroredThroughSurface(wo);
      // Mirrored, it must still leave through the back of m.
      if (!(dot(wo, m) < 0.0f)) return std::nullopt;
    }
  } else if (uComponent < specular + strategy.diffuseReflection) {
    wo = sampleCosineHemisphere(u);
  } else {
    wo = mirroredThroughSurface(sampleCosineHemisphere(u));
  }
  if (flip) wo = mirroredThroughSurface(wo);

  // Several strategies reach most directions: weight by the mixture density (one-sample MIS).
  BSDFSample s;
  s.wo = wo;
  s.pdf = densityFor(material, wi, wo);
  if (!(s.pdf > 0.0f)) return std::nullopt;
  s.weight = valueFor(material, wi, wo) / s.pdf;
  return s;
}

std::shared_ptr<Object> makePrincipledThinBSDF(const Properties& props) {
  return std::make_shared<PrincipledThinBSDF>(readPrincipledThinParameters(props));
}

}  // namespace columba
