/*! plugin phase tabphase
A phase function given as a table of values over the cosine of the scattering angle, at regularly spaced points from −1 (backward) to 1 (forward: on along the light's direction of travel), linear between them and normalised over the sphere. Directions are drawn by inverting the piecewise-linear distribution of cos θ exactly.
Mitsuba 3: as Mitsuba 3's `tabphase`.
| parameter | type | default | meaning | Mitsuba 3 |
| values | string | required | the values, separated by commas or spaces (an empty place between commas is an error): at least two, finite, none negative, not all zero; only their ratios matter, whatever their scale | same |
*/
#include "media/tabulated_phase.h"

#include <fmt/format.h>
#include <algorithm>
#include <cmath>
#include <stdexcept>

#include "core/error.h"

namespace columba {

TabulatedPhase::TabulatedPhase(const std::vector<double>& values) {
  if (values.size() < 2) throw std::invalid_argument("a tabulated phase function needs at least two values");
  // The table is normalised, so only the ratios of its values matter: divided by the largest (in
  // double) they lie in [0, 1], and neither 1e38 nor 1e-38 given overflows or vanishes in float.
  const double largest = *std::max_element(values.begin(), values.end());
  if (!(largest > 0.0)) throw std::invalid_argument("the tabulated values are all zero");
  for (double v : values) values_.push_back(float(v / largest));
  spacing_ = 2.0f / float(values_.size() - 1);
  areaCdf_.assign(values_.size(), 0.0);
  for (size_t i = 1; i < values_.size(); ++i)
    areaCdf_[i] = areaCdf_[i - 1] + 0.5 * double(spacing_) * (double(values_[i - 1]) + values_[i]);
  totalArea_ = areaCdf_.back();  // at least half a spacing: the largest value is 1
  for (double& a : areaCdf_) a /= totalArea_;
  scale_ = float(1.0 / (totalArea_ * 2.0 * double(kPi)));
}

float TabulatedPhase::density(float cosTheta) const {
  const float x = (std::clamp(cosTheta, -1.0f, 1.0f) + 1.0f) / spacing_;
  const size_t i = std::min(size_t(x), values_.size() - 2);
  const float t = std::min(x - float(i), 1.0f);  // x may round past the last point at cos theta = 1
  return ((1.0f - t) * values_[i] + t * values_[i + 1]) * scale_;
}

float TabulatedPhase::eval(const Vec3& wi, const Vec3& wo) const { return density(-dot(wi, wo)); }

std::optional<PhaseSample> TabulatedPhase::sample(const Vec3& wi, Vec2 u) const {
  // The segment holding u's share of the area, then within it the fraction t where the area of the
  // trapezoid from its start, spacing (v0 t + (v1 - v0) t^2 / 2), reaches the rest: the stable root
  // t = 2 r / (v0 + sqrt(v0^2 + 2 (v1 - v0) r)), r the rest over the spacing.
  const size_t i = std::min(size_t(std::upper_bound(areaCdf_.begin(), areaCdf_.end(), double(u.x)) - areaCdf_.begin()),
                            values_.size() - 1) -
                   1;
  const double r = (double(u.x) - areaCdf_[i]) * totalArea_ / double(spacing_);
  const double v0 = values_[i], v1 = values_[i + 1];
  const double root = std::sqrt(std::max(0.0, v0 * v0 + 2.0 * (v1 - v0) * r));
  const double t = v0 + root > 0.0 ? std::clamp(2.0 * r / (v0 + root), 0.0, 1.0) : 0.0;
  const float cosTheta = std::clamp(-1.0f + (float(i) + float(t)) * spacing_, -1.0f, 1.0f);
  const Vec3 wo = scatteredDirection(wi, cosTheta, u.y);
  const float pdf = density(cosTheta);
  if (!(pdf > 0.0f)) return std::nullopt;
  return PhaseSample{wo, pdf};
}

std::shared_ptr<Object> makeTabulatedPhase(const Properties& props) {
  if (!props.has("values")) throw InputError(props.location, "'tabphase' needs its 'values'");
  const std::vector<double> values = props.getNumberList("values");
  for (size_t i = 0; i < values.size(); ++i)
    if (!(values[i] >= 0.0))
      throw props.error("values", fmt::format("'{:g}' is not a number at least 0 (value {})", values[i], i + 1));
  try {
    return std::make_shared<TabulatedPhase>(std::move(values));
  } catch (const std::invalid_argument& e) {
    throw props.error("values", e.what());
  }
}

}  // namespace columba
