#include "barbule/parameters.h"

#include <fmt/format.h>

#include <cmath>
#include <utility>
#include "barbule/cross_section.h"
#include "core/math.h"

namespace columba {

const std::vector<BarbulePreset>& barbulePresets() {
  // The cross-section (b, phi_0, phi_1, mu, H) is the one of the paper's published scenes for
  // both colours; green and purple barbules differ in the thickness of their keratin cortex
  // (Yin et al. 2006, "Iridescence in the neck feathers of domestic pigeons", Phys. Rev. E 74,
  // 051916: green barbules have the thicker cortex, green at normal incidence turning purple at
  // oblique angles, purple barbules the reverse).
  static const std::vector<BarbulePreset> presets = {
      {"dove-green",
       "Huang et al. 2022 (Rendering Iridescent Rock Dove Neck Feathers, SIGGRAPH; DOI 10.1145/3528233.3530749), "
       "the barbule parameters of its published BSDF visualisation scenes (simulation1/2: height 0.58 um)",
       0.25f, -0.37f, 2.64f, -0.35f, 1.25f, 0.58f},
      {"dove-purple",
       "cross-section as dove-green (Huang et al. 2022); cortex thickness 0.51 um, chosen so that the film "
       "reflects purple at normal incidence and turns green at oblique angles, the behaviour Yin et al. 2006 "
       "(Phys. Rev. E 74, 051916) measured on purple barbules; the paper gives no purple thickness",
       0.25f, -0.37f, 2.64f, -0.35f, 1.25f, 0.51f},
  };
  return presets;
}

std::optional<BarbuleParameters> barbulePreset(const std::string& name) {
  for (const BarbulePreset& preset : barbulePresets())
    if (name == preset.name) {
      BarbuleParameters p;
      p.b = preset.b;
      p.phi0 = preset.phi0;
      p.phi1 = preset.phi1;
      p.mu = preset.mu;
      p.H = preset.H;
      p.height = preset.height;
      return p;
    }
  return std::nullopt;
}

std::string barbulePresetNames() {
  std::string names;
  for (const BarbulePreset& preset : barbulePresets()) names += (names.empty() ? "" : ", ") + std::string(preset.name);
  return names;
}

std::optional<BarbuleParameterProblem> findProblem(const BarbuleParameters& p) {
  const std::pair<const char*, float> numbers[] = {{"b", p.b},
                                                   {"phi_0", p.phi0},
                                                   {"phi_1", p.phi1},
                                                   {"mu", p.mu},
                                                   {"H", p.H},
                                                   {"height", p.height},
                                                   {"profile_exponent", p.profileExponent}};
  for (const auto& [name, value] : numbers)
    if (!std::isfinite(value)) return BarbuleParameterProblem{name, "must be a finite number"};
  if (!(p.b > 0.0f)) return BarbuleParameterProblem{"b", "the cross-section's semi-axis must be positive"};
  if (!(p.H > 0.0f)) return BarbuleParameterProblem{"H", "the barbule spacing must be positive"};
  if (!(p.height >= 0.0f)) return BarbuleParameterProblem{"height", "the film thickness must not be negative"};
  if (!(p.profileExponent >= 2.0f && p.profileExponent <= kMaxProfileExponent))
    return BarbuleParameterProblem{"profile_exponent",
                                   "the cross-section's superellipse exponent must lie in [2, 16] (2: the ellipse)"};
  float arc = p.phi1 - p.phi0;
  if (!(arc > 0.0f && (arc <= kPi || arc >= kTwoPi)))
    return BarbuleParameterProblem{"phi_1", "the reflective arc phi_1 - phi_0 must lie in (0, pi] or be at least 2 pi"};
  if (!(p.extIOR > 0.0f)) return BarbuleParameterProblem{"ext_ior", "the index of refraction must be positive"};
  if (!(p.filmIOR.minimumVisible() > p.extIOR))
    return BarbuleParameterProblem{"film_ior",
                                   "the film must be optically denser than the surrounding medium at "
                                   "every wavelength from 300 to 830 nm"};
  if (!(p.filmIOR.maximumVisible() <= kMaxFilmIndex))
    return BarbuleParameterProblem{
        "film_ior", fmt::format("the film's index reaches {:g} between 300 and 830 nm; an index above {:g} is no "
                                "material's (Cauchy's n = a + b / lambda^2 takes lambda in nm)",
                                p.filmIOR.maximumVisible(), kMaxFilmIndex)};
  if (p.melanin)
    for (float l = kSpectralMin; l <= kLambdaMax; l += 1.0f)
      if (!(p.melanin->eval(l) >= 0.0f && p.melanin->eval(l) <= 1.0f))
        return BarbuleParameterProblem{"melanin",
                                       "the melanin reflectance must lie in [0, 1] at every wavelength "
                                       "from 300 to 830 nm"};
  return std::nullopt;
}

std::optional<BarbuleParameterProblem> findImplausibility(const BarbuleParameters& p) {
  // Keratin cortices of iridescent barbules are a few hundred nanometres thick, and the layers
  // beneath them (melanosomes, air channels, keratin between) no thicker.
  constexpr float kThickest = 5.0f;
  if (p.height > kThickest)
    return BarbuleParameterProblem{"height", "a film " + fmt::format("{:g}", p.height) +
                                                 " um thick is implausible for a barbule cortex (did you give nm? "
                                                 "the unit is micrometres)"};
  for (size_t i = 0; i < p.layersBelow.layers.size(); ++i)
    if (p.layersBelow.layers[i].thicknessUm > kThickest)
      return BarbuleParameterProblem{"layers", fmt::format("layer {} is {:g} um thick, implausible for a barbule's "
                                                           "layers (did you give nm? the unit is micrometres)",
                                                           i + 1, p.layersBelow.layers[i].thicknessUm)};
  return std::nullopt;
}

}  // namespace columba
