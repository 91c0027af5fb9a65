#pragma once
// `tabphase`: a phase function tabulated over the cosine of the scattering angle at regularly
// spaced points from -1 (backward) to 1 (forward), linear between them and normalised.
#include <vector>
#include "core/properties.h"
#include "media/phase_function.h"

namespace columba {

class TabulatedPhase final : public PhaseFunction {
 public:
  // At least two values, none negative, not all zero, finite.
  explicit TabulatedPhase(const std::vector<double>& values);
  float eval(const Vec3& wi, const Vec3& wo) const override;
  std::optional<PhaseSample> sample(const Vec3& wi, Vec2 u) const override;

  // The density per steradian at cosTheta, the cosine between the directions of travel.
  float density(float cosTheta) const;

 private:
  std::vector<float> values_;    // at cos theta = -1 + 2 i / (n - 1)
  std::vector<double> areaCdf_;  // area under the table up to each point, the last 1
  double totalArea_;             // under the values as given
  float spacing_;                // between the points in cos theta
  float scale_;                  // 1 / (total area * 2 pi): table values to densities per steradian
};

std::shared_ptr<Object> makeTabulatedPhase(const Properties& props);

}  // namespace columba
