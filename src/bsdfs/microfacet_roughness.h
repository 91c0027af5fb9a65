#pragma once
// A microfacet distribution whose roughness may vary over the surface: Mitsuba lets `alpha`, or
// `alpha_u` and `alpha_v`, of roughconductor and roughdielectric be textures. The distribution at
// a shading point is built from the roughness there.
#include "bsdfs/microfacet.h"
#include "textures/textured_parameter.h"

namespace columba {

class MicrofacetRoughness {
 public:
  MicrofacetRoughness(const MicrofacetDistribution& constant)  // NOLINT: a constant is the common case
      : type_(constant.type()), alphaU_(constant.alphaX()), alphaV_(constant.alphaY()) {}
  MicrofacetRoughness(MicrofacetType type, FloatParameter alphaU, FloatParameter alphaV)
      : type_(type), alphaU_(std::move(alphaU)), alphaV_(std::move(alphaV)) {}

  MicrofacetDistribution at(const TexturePoint& p) const {
    return MicrofacetDistribution(type_, alphaU_.eval(p), alphaV_.eval(p));
  }
  bool isTextured() const { return alphaU_.isTextured() || alphaV_.isTextured(); }

 private:
  MicrofacetType type_;
  FloatParameter alphaU_, alphaV_;
};

}  // namespace columba
