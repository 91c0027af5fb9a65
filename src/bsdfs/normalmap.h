#pragma once
// Mitsuba's `normalmap`: a nested BSDF seen through shading normals read from a texture of raw
// triples (an image read with raw=true, a 3-component rawconstant, a mesh attribute). The triple
// c at a point gives the normal n = 2c - 1 in the tangent frame there (x along dp/du, z along the
// shading normal), as normal maps are usually stored; the nested BSDF is evaluated in the frame
// around n whose x axis is the one closest to dp/du.
#include <memory>
#include "bsdfs/perturbed_frame_bsdf.h"
#include "core/properties.h"
#include "textures/texture.h"

namespace columba {

class NormalMapBSDF : public PerturbedFrameBSDF {
 public:
  NormalMapBSDF(std::shared_ptr<const BSDF> nested, std::shared_ptr<const Texture> normals)
      : PerturbedFrameBSDF(std::move(nested)), normals_(std::move(normals)) {}
  Frame perturbedFrame(const BSDFContext& ctx) const override;

 private:
  std::shared_ptr<const Texture> normals_;
};

// <bsdf type="normalmap">: its parameters are in docs/reference/bsdfs.md.
std::shared_ptr<Object> makeNormalMapBSDF(const Properties& props);

}  // namespace columba
