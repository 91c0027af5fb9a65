#pragma once
// Scene parameters shared by several BSDF plug-ins, read with Mitsuba's names and conventions.
#include <string>
#include "bsdfs/microfacet.h"
#include "core/properties.h"

namespace columba {

// An index of refraction given as a <float> or as a named material (<string>, e.g. "bk7",
// "air"); `defaultName` when absent. InputError for unknown names and non-positive values.
float readIOR(const Properties& props, const std::string& name, const std::string& defaultName);

// `distribution` ("beckmann", the default, or "ggx"), `alpha` (default 0.1) or both `alpha_u`
// and `alpha_v`, and `sample_visible`. Visible normals are always sampled: the flag only picks a
// sampling strategy, which changes noise, not the expected image. Without `allowAnisotropic`,
// alpha_u / alpha_v are an error.
MicrofacetDistribution readMicrofacetDistribution(const Properties& props, bool allowAnisotropic);

}  // namespace columba
