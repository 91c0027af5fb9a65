#include "bsdfs/principled_parameters.h"

#include <cmath>

namespace columba {

namespace {
// A value or texture meant to lie in [0, upper]; a constant outside it is an error.
FloatParameter readBounded(const Properties& props, const std::string& name, float def, float upper,
                           const std::string& range) {
  FloatParameter value = readFloatParameter(props, name, def);
  if (!value.isTextured() && !(value.mean() >= 0.0f && value.mean() <= upper))
    throw props.error(name, "must lie between " + range);
  return value;
}

FloatParameter readFraction(const Properties& props, const std::string& name, float def) {
  return readBounded(props, name, def, 1.0f, "0 and 1");
}

float readSamplingRate(const Properties& props, const std::string& name) {
  float value = props.getFloat(name, 1.0f);
  if (!(value >= 0.0f)) throw props.error(name, "a sampling rate must not be negative");
  return value;
}
}  // namespace

PrincipledParameters readPrincipledParameters(const Properties& props) {
  PrincipledParameters p;
  p.baseColor = readSpectrumParameter(props, "base_color", 0.5f, SpectrumUse::Reflectance);
  p.roughness = readFraction(props, "roughness", 0.5f);
  p.anisotropic = readFraction(props, "anisotropic", 0.0f);
  p.metallic = readFraction(props, "metallic", 0.0f);
  p.specTrans = readFraction(props, "spec_trans", 0.0f);
  p.specTint = readFraction(props, "spec_tint", 0.0f);
  p.sheen = readFraction(props, "sheen", 0.0f);
  p.sheenTint = readFraction(props, "sheen_tint", 0.0f);
  p.flatness = readFraction(props, "flatness", 0.0f);
  p.clearcoat = readFraction(props, "clearcoat", 0.0f);
  p.clearcoatGloss = readFraction(props, "clearcoat_gloss", 0.0f);
  p.diffuseSamplingRate = readSamplingRate(props, "diffuse_reflectance_sampling_rate");
  p.specularSamplingRate = readSamplingRate(props, "main_specular_sampling_rate");
  p.clearcoatSamplingRate = readSamplingRate(props, "clearcoat_sampling_rate");

  // An index of exactly 1 (specular 0) would make the transmission lobe a delta: Mitsuba nudges it.
  const bool transmits = p.specTrans.isTextured() || p.specTrans.mean() > 0.0f;
  if (props.has("eta")) {
    if (props.has("specular")) throw props.error("specular", "give either 'eta' or 'specular', not both");
    p.eta = props.getFloat("eta");
    if (!(p.eta > 0.0f)) throw props.error("eta", "the relative index of refraction must be positive");
    if (transmits && p.eta == 1.0f) p.eta = 1.001f;
  } else {
    // specular = R0 / 0.08, R0 the normal-incidence reflectance ((eta - 1) / (eta + 1))^2.
    float specular = props.getFloat("specular", 0.5f);
    if (!(specular >= 0.0f && specular < 12.5f)) throw props.error("specular", "must lie in [0, 12.5)");
    if (transmits && specular == 0.0f) specular = 1e-3f;
    p.eta = 2.0f / (1.0f - std::sqrt(0.08f * specular)) - 1.0f;
  }
  return p;
}

PrincipledThinParameters readPrincipledThinParameters(const Properties& props) {
  PrincipledThinParameters p;
  p.baseColor = readSpectrumParameter(props, "base_color", 0.5f, SpectrumUse::Reflectance);
  p.roughness = readFraction(props, "roughness", 0.5f);
  p.anisotropic = readFraction(props, "anisotropic", 0.0f);
  p.specTrans = readFraction(props, "spec_trans", 0.0f);
  p.diffTrans = readBounded(props, "diff_trans", 0.0f, 2.0f, "0 and 2");
  p.eta = readFloatParameter(props, "eta", 1.5f);
  if (!p.eta.isTextured() && !(p.eta.mean() > 0.0f))
    throw props.error("eta", "the relative index of refraction must be positive");
  p.specTint = readFraction(props, "spec_tint", 0.0f);
  p.sheen = readFraction(props, "sheen", 0.0f);
  p.sheenTint = readFraction(props, "sheen_tint", 0.0f);
  p.flatness = readFraction(props, "flatness", 0.0f);
  p.specularReflectionSamplingRate = readSamplingRate(props, "specular_reflectance_sampling_rate");
  p.specularTransmissionSamplingRate = readSamplingRate(props, "specular_transmittance_sampling_rate");
  p.diffuseReflectionSamplingRate = readSamplingRate(props, "diffuse_reflectance_sampling_rate");
  p.diffuseTransmissionSamplingRate = readSamplingRate(props, "diffuse_transmittance_sampling_rate");
  return p;
}

}  // namespace columba
