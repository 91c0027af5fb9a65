/*! parameters microfacet
| parameter | type | default | meaning | Mitsuba 3 |
| distribution | string | `beckmann` | the microfacet distribution, `beckmann` or `ggx` (in any case) | same |
| alpha | float or texture | 0.1 | the isotropic roughness (RMS slope); not negative. `roughplastic`'s is a float only | same |
| alpha_u | float or texture | 0.1 | the roughness along the tangent, with `alpha_v` and instead of `alpha`; refused by `roughplastic` | same |
| alpha_v | float or texture | 0.1 | the roughness along the bitangent, with `alpha_u` | same |
| sample_visible | boolean | true | accepted; no effect | chooses visible-normal sampling |
*/
/*! parameters conductor
| parameter | type | default | meaning | Mitsuba 3 |
| material | string | `none` | measured optical constants: `Au`, `Ag`, `Cu` (Johnson & Christy 1972), `Cr` (Johnson & Christy 1974) or `Al` (Rakić 1995), over 300–1000 nm; or any other of Mitsuba's names (`W`, `a-C`, `Cu_palik`, `TiO2`, ... : Mitsuba's own tables from Palik's handbooks and the LLNL/CXRO tables, data/ior/README.md); `none` is a perfect mirror. Not together with `eta` and `k` | the same names (`Ag`, `Al`, `Au`, `Cr`, `Cu` from other tables); also `none` by default |
| eta | spectrum or texture | 0 | the real part of the metal's index of refraction; not negative | same |
| k | spectrum or texture | 1 | the imaginary part (extinction coefficient); not negative | same |
*/
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

MicrofacetRoughness readMicrofacetRoughness(const Properties& props, bool allowAnisotropic) {
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

  // A value or a texture.
  auto given = [&](const std::string& name) { return props.has(name) || props.namedChild<Texture>(name) != nullptr; };
  const bool anisotropic = given("alpha_u") || given("alpha_v");
  if (anisotropic) {
    const std::string first = given("alpha_u") ? "alpha_u" : "alpha_v";
    if (!allowAnisotropic) throw props.error(first, "this BSDF supports isotropic roughness only (use 'alpha')");
    if (given("alpha")) throw props.error(first, "give either 'alpha' or 'alpha_u' and 'alpha_v', not both");
    if (!given("alpha_u") || !given("alpha_v")) throw props.error(first, "'alpha_u' and 'alpha_v' go together");
  }
  FloatParameter alphaU = readFloatParameter(props, anisotropic ? "alpha_u" : "alpha", 0.1f);
  FloatParameter alphaV = anisotropic ? readFloatParameter(props, "alpha_v", 0.1f) : alphaU;
  for (const FloatParameter& alpha : {alphaU, alphaV})
    if (!alpha.isTextured() && !(alpha.mean() >= 0.0f))
      throw props.error(anisotropic ? "alpha_u" : "alpha", "roughness must not be negative");
  return MicrofacetRoughness(type, alphaU, alphaV);
}

MicrofacetDistribution readMicrofacetDistribution(const Properties& props, bool allowAnisotropic) {
  MicrofacetRoughness roughness = readMicrofacetRoughness(props, allowAnisotropic);
  if (roughness.isTextured()) throw props.error("alpha", "this BSDF's roughness cannot be a texture, as in Mitsuba");
  return roughness.at(Vec2());
}

std::optional<ConductorIndexParameter> readConductorIndex(const Properties& props) {
  std::string material = props.getString("material", "none");
  const bool textured = props.namedChild<Texture>("eta") || props.namedChild<Texture>("k");
  if (props.has("eta") || props.has("k") || textured) {
    if (material != "none") throw props.error("material", "give either a material or eta and k, not both");
    // A negative eta or k is no passive medium: eta -1, k 0 reflected 6e14 times the light.
    return ConductorIndexParameter{readSpectrumParameter(props, "eta", 0.0f, SpectrumUse::NonNegative),
                                   readSpectrumParameter(props, "k", 1.0f, SpectrumUse::NonNegative)};
  }
  if (material == "none") return std::nullopt;
  std::optional<ConductorIndex> measured = conductorIndex(material);
  if (!measured)
    throw props.error("material", "no measured data for conductor '" + material + "' (known: none, " +
                                      conductorNames() + "); give its eta and k spectra");
  return ConductorIndexParameter{measured->eta, measured->k};
}

Spectrum conductorReflectance(const std::optional<ConductorIndexParameter>& ior, const Spectrum& specular, float cosI,
                              const TexturePoint& p, const Wavelengths& wl) {
  Spectrum r = specular;
  if (ior) {
    const Spectrum eta = ior->eta.eval(p, wl), k = ior->k.eval(p, wl);
    for (int i = 0; i < kSpectrumSamples; ++i) r[i] *= fresnelConductor(cosI, eta[i], k[i]);
  }
  return r;
}

}  // namespace columba
