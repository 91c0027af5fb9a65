#pragma once
// Mitsuba's `normalmap`: a nested BSDF seen through shading normals read from an image. The
// image's colour c at a point gives the normal n = 2c - 1 in the tangent frame there (x along
// dp/du, z along the shading normal), as normal maps are usually stored; the nested BSDF is
// evaluated in the frame around n whose x axis is the one closest to dp/du.
//
// As in Mitsuba, a direction that lies above the surface in one frame and below it in the other
// is given no value, so that the perturbed normals do not leak light through the surface.
#include <memory>
#include "bsdfs/bsdf.h"
#include "core/frame.h"
#include "core/properties.h"
#include "textures/bitmap_texture.h"

namespace columba {

class NormalMapBSDF : public BSDF {
 public:
  NormalMapBSDF(std::shared_ptr<const BSDF> nested, std::shared_ptr<const BitmapTexture> normals)
      : nested_(std::move(nested)), normals_(std::move(normals)) {}
  Spectrum eval(const BSDFContext& ctx, const Vec3& wi, const Vec3& wo, const Wavelengths& wl) const override;
  float pdf(const BSDFContext& ctx, const Vec3& wi, const Vec3& wo, const Wavelengths& wl) const override;
  std::optional<BSDFSample> sample(const BSDFContext& ctx, const Vec3& wi, const Wavelengths& wl, float uComponent,
                                   Vec2 u) const override;
  Spectrum passThrough(const BSDFContext& ctx, const Vec3& wi, const Wavelengths& wl) const override;
  bool hasPassThrough() const override { return nested_->hasPassThrough(); }
  bool isDeltaOnly() const override { return nested_->isDeltaOnly(); }

  // The perturbed frame at `uv`, in the local shading frame.
  Frame perturbedFrame(Vec2 uv) const;

 private:
  std::shared_ptr<const BSDF> nested_;
  std::shared_ptr<const BitmapTexture> normals_;
};

// Parameters: a texture `normalmap` (a bitmap read with raw=true) and one nested BSDF.
std::shared_ptr<Object> makeNormalMapBSDF(const Properties& props);

}  // namespace columba
