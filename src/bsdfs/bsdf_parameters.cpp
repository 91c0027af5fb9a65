#include "bsdfs/bsdf_parameters.h"

#include <algorithm>
#include <cctype>
#include "optics/conductor_fresnel.h"
#include "optics/ior_table.h"

namespace columba {

float readIOR(const Properties& props, const std::string& name, const std::string& defaultName) {
  float value;
  if (props.has(name) && !props.isString(name)) {
    value = props.getFloat(name);  // reports kinds that are neither a string nor a number
  } else {
    std::string material = props.getString(name, defaultName);
    auto named = lookupIOR(material);
    if (!named)
      throw props.error(name, "unknown material '" + material + "' (give a number or a known name such as 'bk7')");
    value = *named;
  }
  if (!(value > 0.0f)) throw props.error(name, "the index of refraction must be positive");
  return value;
}

MicrofacetDistribution readMicrofacetDistribution(const Properties& props, bool allowAnisotropic) {
  std::string distribution = props.getString("distribution", "beckmann");
  std::transform(distribution.begin(), distribution.end(), distribution.begin(),
                 [](unsigned char c) { return char(std::tolower(c)); });
  MicrofacetType type;
  if (distribution == "beckmann")
    type = MicrofacetType::Beckmann;
  else if (distribution == "ggx")
    type = MicrofacetType::GGX;
  else
    throw props.error("distribution",
                      "unknown microfacet distribution '" + distribution + "' (use 'beckmann' or 'ggx')");

  props.getBool("sample_visible", true);

  float alphaU, alphaV;
  if (props.has("alpha_u") || props.has("alpha_v")) {
    const std::string given = props.has("alpha_u") ? "alpha_u" : "alpha_v";
    if (!allowAnisotropic) throw props.error(given, "this BSDF supports isotropic roughness only (use 'alpha')");
    if (props.has("alpha")) throw props.error(given, "give either 'alpha' or 'alpha_u' and 'alpha_v', not both");
    if (!props.has("alpha_u") || !props.has("alpha_v")) throw props.error(given, "'alpha_u' and 'alpha_v' go together");
    alphaU = props.getFloat("alpha_u");
    alphaV = props.getFloat("alpha_v");
  } else {
    alphaU = alphaV = props.getFloat("alpha", 0.1f);
  }
  if (!(alphaU >= 0.0f && alphaV >= 0.0f))
    throw props.error(props.has("alpha") ? "alpha" : "alpha_u", "roughness must not be negative");
  return MicrofacetDistribution(type, alphaU, alphaV);
}

std::optional<ConductorIndex> readConductorIndex(const Properties& props) {
  std::string material = props.getString("material", "none");
  if (props.has("eta") || props.has("k")) {
    if (material != "none") throw props.error("material", "give either a material or eta and k, not both");
    return ConductorIndex{props.getSpectrum("eta", 0.0f, SpectrumUse::Unbounded),
                          props.getSpectrum("k", 1.0f, SpectrumUse::Unbounded)};
  }
  if (material == "none") return std::nullopt;
  std::optional<ConductorIndex> measured = conductorIndex(material);
  if (!measured)
    throw props.error("material", "no measured data for conductor '" + material + "' (known: none, " +
                                      conductorNames() + "); give its eta and k spectra");
  return measured;
}

Spectrum conductorReflectance(const std::optional<ConductorIndex>& ior, const SpectralDistribution& specular,
                              float cosI, const Wavelengths& wl) {
  Spectrum r = specular.sample(wl);
  if (ior)
    for (int i = 0; i < kSpectrumSamples; ++i) r[i] *= fresnelConductor(cosI, ior->eta.eval(wl[i]), ior->k.eval(wl[i]));
  return r;
}

}  // namespace columba
