#pragma once
// Mitsuba's `blendbsdf`: a linear blend (1 - weight) f_0 + weight f_1 of two nested BSDFs, sampled
// by choosing one of them with those probabilities. A non-delta sample's density is the blend of
// both densities, so MIS sees the whole mixture; a delta one keeps its component's weight.
#include <memory>
#include "bsdfs/bsdf.h"
#include "core/properties.h"
#include "textures/textured_parameter.h"

namespace columba {

class BlendBSDF : public BSDF {
 public:
  BlendBSDF(std::shared_ptr<const BSDF> first, std::shared_ptr<const BSDF> second, FloatParameter weight)
      : first_(std::move(first)), second_(std::move(second)), weight_(std::move(weight)) {}
  Spectrum eval(const BSDFContext& ctx, const Vec3& wi, const Vec3& wo, const Wavelengths& wl) const override;
  float pdf(const BSDFContext& ctx, const Vec3& wi, const Vec3& wo, const Wavelengths& wl) const override;
  std::optional<BSDFSample> sample(const BSDFContext& ctx, const Vec3& wi, const Wavelengths& wl, float uComponent,
                                   Vec2 u) const override;
  Spectrum passThrough(const BSDFContext& ctx, const Vec3& wi, const Wavelengths& wl) const override;
  bool hasPassThrough() const override { return first_->hasPassThrough() || second_->hasPassThrough(); }
  bool isDeltaOnly() const override { return first_->isDeltaOnly() && second_->isDeltaOnly(); }
  bool hasSingularValues() const override { return first_->hasSingularValues() || second_->hasSingularValues(); }
  bool followsSurfaceAxis() const override { return first_->followsSurfaceAxis() || second_->followsSurfaceAxis(); }
  void noteValuesGivenByShape(const ShapePointValues& given) const override {
    first_->noteValuesGivenByShape(given);
    second_->noteValuesGivenByShape(given);
  }
  bool samplesAllItScatters() const override {
    return first_->samplesAllItScatters() && second_->samplesAllItScatters();
  }

 private:
  // The second BSDF's weight at the shading point; a texture's value is clamped to [0, 1].
  float weightAt(const BSDFContext& ctx) const;

  std::shared_ptr<const BSDF> first_, second_;
  FloatParameter weight_;  // of the second
};

// <bsdf type="blendbsdf">: its parameters are in docs/reference/bsdfs.md.
std::shared_ptr<Object> makeBlendBSDF(const Properties& props);

}  // namespace columba
