#include "scene/unsupported_plugins.h"

#include <map>
#include <utility>

namespace columba {

namespace {
const char* kPhases =
    "of Mitsuba's phase functions, Columba has 'isotropic', 'hg', 'rayleigh', 'blendphase' and 'tabphase'";
const char* kTextures =
    "of Mitsuba's textures, Columba has 'bitmap', 'checkerboard', 'mesh_attribute' and 'rawconstant'";
const char* kDifferentiable = "differentiable rendering is not supported; use 'path'";
const char* kPolarisation = "polarised rendering is not supported";
}  // namespace

std::optional<std::string> unsupportedMitsubaPlugin(const std::string& tag, const std::string& type) {
  static const std::map<std::pair<std::string, std::string>, const char*> kReasons = {
      {{"integrator", "prbvolpath"}, "differentiable rendering is not supported; use 'volpath'"},
      {{"integrator", "prb"}, kDifferentiable},
      {{"integrator", "prb_basic"}, kDifferentiable},
      {{"integrator", "prb_projective"}, kDifferentiable},
      {{"integrator", "direct_projective"}, kDifferentiable},
      {{"integrator", "stokes"}, kPolarisation},
      {{"integrator", "aov"}, "arbitrary output variables are not supported"},
      {{"integrator", "depth"}, "the depth integrator is not supported"},
      {{"phase", "sggx"}, kPhases},
      {{"texture", "volume"}, kTextures},
      {{"bsdf", "hair"}, "the hair BSDF is not supported"},
      {{"bsdf", "measured"}, "measured (RGL) BSDFs are not supported"},
      {{"bsdf", "pplastic"}, kPolarisation},
      {{"bsdf", "polarizer"}, kPolarisation},
      {{"bsdf", "retarder"}, kPolarisation},
      {{"bsdf", "circular"}, kPolarisation},
      {{"shape", "bsplinecurve"}, "curves are not supported"},
      {{"shape", "linearcurve"}, "curves are not supported"},
      {{"shape", "ellipsoids"}, "ellipsoid clouds are not supported"},
      {{"emitter", "sunsky"}, "the sun and sky model is not supported; use 'envmap' or 'directional'"},
      {{"sensor", "irradiancemeter"}, "only cameras are supported as sensors"},
      {{"sensor", "radiancemeter"}, "only cameras are supported as sensors"},
      {{"sensor", "distant"}, "only cameras are supported as sensors"},
      {{"sensor", "batch"}, "only one sensor per scene is supported"},
      {{"film", "specfilm"}, "use 'hdrfilm' (columba render --spectral writes spectral bands)"},
      {{"rfilter", "lanczos"}, "use 'box', 'tent' or 'gaussian'"},
      {{"rfilter", "mitchell"}, "use 'box', 'tent' or 'gaussian'"},
      {{"rfilter", "catmullrom"}, "use 'box', 'tent' or 'gaussian'"},
  };
  auto it = kReasons.find({tag, type});
  if (it == kReasons.end()) return std::nullopt;
  return std::string(it->second);
}

}  // namespace columba
