#pragma once
// A nested BSDF evaluated in a shading frame perturbed at each point (normal and bump mapping).
// Directions are taken into the perturbed frame and back. As Mitsuba does, a direction that lies
// above the surface in one frame and below it in the other is given no value, so that perturbed
// normals do not leak light through the surface.
#include <memory>
#include "bsdfs/bsdf.h"
#include "core/frame.h"

namespace columba {

class PerturbedFrameBSDF : public BSDF {
 public:
  explicit PerturbedFrameBSDF(std::shared_ptr<const BSDF> nested) : nested_(std::move(nested)) {}
  Spectrum eval(const BSDFContext& ctx, const Vec3& wi, const Vec3& wo, const Wavelengths& wl) const final;
  float pdf(const BSDFContext& ctx, const Vec3& wi, const Vec3& wo, const Wavelengths& wl) const final;
  std::optional<BSDFSample> sample(const BSDFContext& ctx, const Vec3& wi, const Wavelengths& wl, float uComponent,
                                   Vec2 u) const final;
  Spectrum passThrough(const BSDFContext& ctx, const Vec3& wi, const Wavelengths& wl) const final;
  bool hasPassThrough() const final { return nested_->hasPassThrough(); }
  bool isDeltaOnly() const final { return nested_->isDeltaOnly(); }
  bool hasSingularValues() const final { return nested_->hasSingularValues(); }
  bool followsSurfaceAxis() const final { return nested_->followsSurfaceAxis(); }
  void noteValuesGivenByShape(const ShapePointValues& given) const final { nested_->noteValuesGivenByShape(given); }
  bool samplesAllItScatters() const final { return nested_->samplesAllItScatters(); }

  // The perturbed frame at the shading point, in the local shading frame.
  virtual Frame perturbedFrame(const BSDFContext& ctx) const = 0;

 private:
  std::shared_ptr<const BSDF> nested_;
};

}  // namespace columba
