#pragma once
// `heterogeneous`: extinction and albedo given by volumes (a grid read from a file, or a constant
// over a box). Its majorant is one value, the largest extinction of the grid, over the part of a
// ray inside the extinction volume's box; collisions drawn against it are real with probability
// sigma_t / majorant and null otherwise (delta tracking).
#include "core/properties.h"
#include "media/medium.h"
#include "media/volume.h"

namespace columba {

class HeterogeneousMedium final : public Medium {
 public:
  HeterogeneousMedium(std::shared_ptr<Volume> sigmaT, std::shared_ptr<Volume> albedo, float scale,
                      std::shared_ptr<PhaseFunction> phase)
      : Medium(std::move(phase)),
        sigmaT_(std::move(sigmaT)),
        albedo_(std::move(albedo)),
        scale_(scale),
        majorant_(scale_ * sigmaT_->maxValue()) {}
  MediumCoefficients coefficients(const Vec3& p, const Wavelengths& wl) const override;
  std::optional<MajorantSegment> majorant(const Ray& ray, const Wavelengths& wl) const override;

 private:
  std::shared_ptr<Volume> sigmaT_, albedo_;
  float scale_;
  float majorant_;
};

std::shared_ptr<Object> makeHeterogeneousMedium(const Properties& props);

}  // namespace columba
