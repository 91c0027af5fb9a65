#pragma once
// `heterogeneous`: extinction and albedo given by volumes (a grid read from a file, or a constant
// over a box). Its majorants are those of a majorant grid over the extinction volume's cube, the
// largest extinction within each cell; collisions drawn against them are real with probability
// sigma_t / majorant and null otherwise (delta tracking).
#include "core/properties.h"
#include "media/medium.h"
#include "media/volume.h"

namespace columba {

class HeterogeneousMedium final : public Medium {
 public:
  HeterogeneousMedium(std::shared_ptr<Volume> sigmaT, std::shared_ptr<Volume> albedo, float scale,
                      std::shared_ptr<PhaseFunction> phase, const Properties* element = nullptr)
      : Medium(std::move(phase), element),
        sigmaT_(std::move(sigmaT)),
        albedo_(std::move(albedo)),
        scale_(scale),
        majorants_(*sigmaT_) {}
  MediumCoefficients coefficients(const Vec3& p, const Wavelengths& wl) const override;
  MajorantIterator majorant(const Ray& ray, const Wavelengths& wl) const override;

 private:
  std::shared_ptr<Volume> sigmaT_, albedo_;
  float scale_;
  MajorantGrid majorants_;  // of sigmaT_, before scale_
};

std::shared_ptr<Object> makeHeterogeneousMedium(const Properties& props);

}  // namespace columba
