#pragma once
// The scene parameters of Mitsuba 3's `principled` and `principledthin` BSDFs, with Mitsuba's
// names and defaults. As in Mitsuba, all but eta, specular and the sampling rates may be textures.
#include "core/properties.h"
#include "core/spectrum.h"
#include "textures/textured_parameter.h"

namespace columba {

// `principled`'s parameters, with Mitsuba's defaults.
struct PrincipledParameters {
  SpectrumParameter baseColor = SpectralDistribution::constant(0.5f);
  FloatParameter roughness = 0.5f, anisotropic = 0.0f, metallic = 0.0f, specTrans = 0.0f;
  float eta = 1.5f;  // interior / exterior index; from `specular` = 0.5 by default
  FloatParameter specTint = 0.0f, sheen = 0.0f, sheenTint = 0.0f, flatness = 0.0f;
  FloatParameter clearcoat = 0.0f, clearcoatGloss = 0.0f;
  float diffuseSamplingRate = 1.0f, specularSamplingRate = 1.0f, clearcoatSamplingRate = 1.0f;
};

// `principledthin`'s parameters, with Mitsuba's defaults.
struct PrincipledThinParameters {
  SpectrumParameter baseColor = SpectralDistribution::constant(0.5f);
  FloatParameter roughness = 0.5f, anisotropic = 0.0f, specTrans = 0.0f;
  FloatParameter diffTrans = 0.0f;  // 0 to 2: half of it is the transmitted share of the diffuse part
  FloatParameter eta = 1.5f;        // of the sheet, relative to the medium around it
  FloatParameter specTint = 0.0f, sheen = 0.0f, sheenTint = 0.0f, flatness = 0.0f;
  float specularReflectionSamplingRate = 1.0f, specularTransmissionSamplingRate = 1.0f;
  float diffuseReflectionSamplingRate = 1.0f, diffuseTransmissionSamplingRate = 1.0f;
};

// Reads base_color (0.5), roughness (0.5), anisotropic, metallic, spec_trans, eta or specular
// (0.5, i.e. eta 1.5; not both), spec_tint, sheen, sheen_tint, flatness, clearcoat,
// clearcoat_gloss (all 0), main_specular_sampling_rate, diffuse_reflectance_sampling_rate and
// clearcoat_sampling_rate (1). Constant fractions outside [0, 1] are errors.
PrincipledParameters readPrincipledParameters(const Properties& props);

// Reads base_color (0.5), roughness (0.5), anisotropic, spec_trans, diff_trans (0 to 2), eta
// (1.5), spec_tint, sheen, sheen_tint, flatness (all 0), specular_reflectance_sampling_rate,
// specular_transmittance_sampling_rate, diffuse_reflectance_sampling_rate and
// diffuse_transmittance_sampling_rate (1).
PrincipledThinParameters readPrincipledThinParameters(const Properties& props);

}  // namespace columba
