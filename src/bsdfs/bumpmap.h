#pragma once
// Mitsuba's `bumpmap`: a nested BSDF on a surface displaced along its normal by scale * h(u, v),
// h a texture, without moving the geometry. The displaced surface's derivatives are
// dp/du + n dh/du and dp/dv + n dh/dv (with the normal components of dp/du and dp/dv replaced, as
// Mitsuba does), and its normal, their cross product, is the perturbed shading normal.
//
// Departure from Mitsuba: the perturbed normal is turned to the side of the shading normal, where
// Mitsuba turns it to the side of the geometric normal (they differ only on smooth-shaded meshes).
// On a shape that gives no position derivatives (a feather) the frame is left unperturbed.
#include <memory>
#include "bsdfs/perturbed_frame_bsdf.h"
#include "core/properties.h"
#include "textures/texture.h"

namespace columba {

class BumpMapBSDF : public PerturbedFrameBSDF {
 public:
  BumpMapBSDF(std::shared_ptr<const BSDF> nested, std::shared_ptr<const Texture> height, float scale)
      : PerturbedFrameBSDF(std::move(nested)), height_(std::move(height)), scale_(scale) {}
  Frame perturbedFrame(const BSDFContext& ctx) const override;

 private:
  std::shared_ptr<const Texture> height_;
  float scale_;
};

// <bsdf type="bumpmap">: its parameters are in docs/reference/bsdfs.md.
std::shared_ptr<Object> makeBumpMapBSDF(const Properties& props);

}  // namespace columba
