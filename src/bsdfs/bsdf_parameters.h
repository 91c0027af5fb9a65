#pragma once
// Scene parameters shared by several BSDF plug-ins, read with Mitsuba's names and conventions.
#include <optional>
#include <string>
#include "bsdfs/microfacet.h"
#include "bsdfs/microfacet_roughness.h"
#include "core/properties.h"
#include "core/spectrum.h"
#include "optics/conductor_materials.h"
#include "textures/textured_parameter.h"

namespace columba {

// An index of refraction given as a <float> or as a named material (<string>, e.g. "bk7",
// "air"); `defaultName` when absent. InputError for unknown names and non-positive values.
float readIOR(const Properties& props, const std::string& name, const std::string& defaultName);

// `distribution` ("beckmann", the default, or "ggx"), `alpha` (default 0.1) or both `alpha_u`
// and `alpha_v`, and `sample_visible`. Visible normals are always sampled: the flag only picks a
// sampling strategy, which changes noise, not the expected image. Without `allowAnisotropic`,
// alpha_u / alpha_v are an error. Each roughness may be a value or a texture.
MicrofacetRoughness readMicrofacetRoughness(const Properties& props, bool allowAnisotropic);
// The same for a BSDF whose roughness must be constant (InputError for a texture).
MicrofacetDistribution readMicrofacetDistribution(const Properties& props, bool allowAnisotropic);

// A conductor's complex index at each point: a measured metal's, or `eta` and `k` given as
// values or textures (as Mitsuba allows).
struct ConductorIndexParameter {
  SpectrumParameter eta, k;
};

// `material` (a measured metal, or "none", the default: a perfect mirror, returned as nullopt) or
// `eta` (default 0) and `k` (default 1), each a spectrum or a texture; not both. InputError for a
// negative eta or k.
std::optional<ConductorIndexParameter> readConductorIndex(const Properties& props);

// `specular` (specular_reflectance at the path's wavelengths) times the conductor's Fresnel
// reflectance at incidence cosine cosI (1 without an index), the index taken at `p`.
Spectrum conductorReflectance(const std::optional<ConductorIndexParameter>& ior, const Spectrum& specular, float cosI,
                              const TexturePoint& p, const Wavelengths& wl);

}  // namespace columba
