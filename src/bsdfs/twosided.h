#pragma once
// Two-sided adapter (Mitsuba's `twosided`): the front BSDF for wi above the surface, the back
// BSDF, mirrored through the surface, for wi below it. Meant for reflective BSDFs; nested BSDFs
// that transmit would scatter into the wrong side.
#include <memory>
#include "bsdfs/bsdf.h"
#include "core/properties.h"

namespace columba {

class TwoSidedBSDF : public BSDF {
 public:
  TwoSidedBSDF(std::shared_ptr<const BSDF> front, std::shared_ptr<const BSDF> back)
      : front_(std::move(front)), back_(std::move(back)) {}
  Spectrum eval(const BSDFContext& ctx, const Vec3& wi, const Vec3& wo, const Wavelengths& wl) const override;
  float pdf(const BSDFContext& ctx, const Vec3& wi, const Vec3& wo, const Wavelengths& wl) const override;
  std::optional<BSDFSample> sample(const BSDFContext& ctx, const Vec3& wi, const Wavelengths& wl, float uComponent,
                                   Vec2 u) const override;
  Spectrum passThrough(const BSDFContext& ctx, const Vec3& wi, const Wavelengths& wl) const override;
  bool hasPassThrough() const override { return front_->hasPassThrough() || back_->hasPassThrough(); }
  bool isDeltaOnly() const override { return front_->isDeltaOnly() && back_->isDeltaOnly(); }
  bool hasSingularValues() const override { return front_->hasSingularValues() || back_->hasSingularValues(); }
  bool followsSurfaceAxis() const override { return front_->followsSurfaceAxis() || back_->followsSurfaceAxis(); }
  void noteValuesGivenByShape(const ShapePointValues& given) const override {
    front_->noteValuesGivenByShape(given);
    back_->noteValuesGivenByShape(given);
  }
  bool samplesAllItScatters() const override { return front_->samplesAllItScatters() && back_->samplesAllItScatters(); }

 private:
  std::shared_ptr<const BSDF> front_, back_;
};

// <bsdf type="twosided">: its parameters are in docs/reference/bsdfs.md.
std::shared_ptr<Object> makeTwoSidedBSDF(const Properties& props);

}  // namespace columba
