#pragma once
// Mitsuba's `mask`: a nested BSDF on a fraction `opacity` of the surface (leaves, fences); the rest
// lets light through untouched. Values and densities of the nested BSDF are scaled by the opacity,
// and light passes straight through with weight 1 - opacity (a pass-through, for shadow rays too).
#include <memory>
#include "bsdfs/bsdf.h"
#include "core/properties.h"
#include "textures/textured_parameter.h"

namespace columba {

class MaskBSDF : public BSDF {
 public:
  MaskBSDF(std::shared_ptr<const BSDF> nested, FloatParameter opacity)
      : nested_(std::move(nested)), opacity_(std::move(opacity)) {}
  Spectrum eval(const BSDFContext& ctx, const Vec3& wi, const Vec3& wo, const Wavelengths& wl) const override;
  float pdf(const BSDFContext& ctx, const Vec3& wi, const Vec3& wo, const Wavelengths& wl) const override;
  std::optional<BSDFSample> sample(const BSDFContext& ctx, const Vec3& wi, const Wavelengths& wl, float uComponent,
                                   Vec2 u) const override;
  Spectrum passThrough(const BSDFContext& ctx, const Vec3& wi, const Wavelengths& wl) const override;
  bool hasPassThrough() const override { return true; }
  bool isDeltaOnly() const override { return nested_->isDeltaOnly(); }
  bool hasSingularValues() const override { return nested_->hasSingularValues(); }
  bool followsSurfaceAxis() const override { return nested_->followsSurfaceAxis(); }
  void noteValuesGivenByShape(const ShapePointValues& given) const override { nested_->noteValuesGivenByShape(given); }
  bool samplesAllItScatters() const override { return nested_->samplesAllItScatters(); }

 private:
  // The opacity at the shading point; a texture's value is clamped to [0, 1].
  float opacityAt(const BSDFContext& ctx) const;

  std::shared_ptr<const BSDF> nested_;
  FloatParameter opacity_;
};

// <bsdf type="mask">: its parameters are in docs/reference/bsdfs.md.
std::shared_ptr<Object> makeMaskBSDF(const Properties& props);

}  // namespace columba
