#pragma once
// Microfacet normal distributions (Beckmann and GGX / Trowbridge-Reitz), anisotropic along the
// local x and y axes, with Smith's shadowing-masking and sampling of the visible normals.
// Directions are in the local shading frame (z = macro-surface normal).
#include "core/vector.h"

namespace columba {

enum class MicrofacetType { Beckmann, GGX };

class MicrofacetDistribution {
 public:
  // Roughness below 1e-4 is raised to it: the distribution would be a delta there.
  MicrofacetDistribution(MicrofacetType type, float alphaX, float alphaY);

  MicrofacetType type() const { return type_; }
  float alphaX() const { return alphaX_; }
  float alphaY() const { return alphaY_; }

  // Density of microfacet normals, normalised so that the integral of D(m) cos(theta_m) is 1.
  float D(const Vec3& m) const;
  // Smith's auxiliary function: G1 = 1 / (1 + Lambda).
  float lambda(const Vec3& w) const;
  // Fraction of the microfacets with normal `m` that are visible from `w`; 0 if `w` sees their back.
  float G1(const Vec3& w, const Vec3& m) const;
  // Shadowing-masking of a reflection wi -> wo about `m`, as the product of the two G1 (the
  // separable form Mitsuba uses).
  float G(const Vec3& wi, const Vec3& wo, const Vec3& m) const;

  // A normal drawn from the distribution of normals visible from `wi` (wi.z > 0),
  // D_wi(m) = G1(wi, m) max(0, wi.m) D(m) / wi.z.
  Vec3 sampleVisible(const Vec3& wi, Vec2 u) const;
  float visiblePdf(const Vec3& wi, const Vec3& m) const;

 private:
  Vec3 sampleVisibleGGX(const Vec3& wi, Vec2 u) const;
  Vec3 sampleVisibleBeckmann(const Vec3& wi, Vec2 u) const;

  MicrofacetType type_;
  float alphaX_, alphaY_;
};

}  // namespace columba
