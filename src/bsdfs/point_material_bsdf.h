#pragma once
// A BSDF whose parameters (values or textures) are worked out into a Material at each shading
// point before anything else: eval, pdf, sample and a vertex's queries all start from materialAt,
// and a vertex's queries share one material (principled, principledthin).
#include <optional>
#include "bsdfs/bsdf.h"

namespace columba {

template <typename Material>
class PointMaterialBSDF : public BSDF {
 public:
  Spectrum eval(const BSDFContext& ctx, const Vec3& wi, const Vec3& wo, const Wavelengths& wl) const override {
    return valueFor(materialAt(ctx, wl), wi, wo);
  }
  float pdf(const BSDFContext& ctx, const Vec3& wi, const Vec3& wo, const Wavelengths& wl) const override {
    return densityFor(materialAt(ctx, wl), wi, wo);
  }
  std::optional<BSDFSample> sample(const BSDFContext& ctx, const Vec3& wi, const Wavelengths& wl, float uComponent,
                                   Vec2 u) const override {
    return sampleFor(materialAt(ctx, wl), wi, uComponent, u);
  }
  BSDFVertexQueries queryVertex(const BSDFContext& ctx, const Vec3& wi, const Wavelengths& wl,
                                const BSDFVertexRequest& request) const override {
    const Material material = materialAt(ctx, wl);
    return answerVertexQueries(
        request, [&](const Vec3& wo) { return valueFor(material, wi, wo); },
        [&](const Vec3& wo) { return densityFor(material, wi, wo); },
        [&](float uComponent, Vec2 u) { return sampleFor(material, wi, uComponent, u); },
        [&] { return passThrough(ctx, wi, wl); });
  }

 protected:
  virtual Material materialAt(const BSDFContext& ctx, const Wavelengths& wl) const = 0;
  // eval, pdf and sample for the material at the shading point.
  virtual Spectrum valueFor(const Material& material, const Vec3& wi, const Vec3& wo) const = 0;
  virtual float densityFor(const Material& material, const Vec3& wi, const Vec3& wo) const = 0;
  virtual std::optional<BSDFSample> sampleFor(const Material& material, const Vec3& wi, float uComponent,
                                              Vec2 u) const = 0;
};

}  // namespace columba
