#pragma once
// The geometry of microfacet reflection and refraction at a rough interface between two
// dielectrics (Walter et al. 2007, "Microfacet models for refraction through rough surfaces"),
// without Fresnel terms or colours: what `roughdielectric` and the principled BSDF's specular
// lobes share. A pair (wi, wo) is handled from wi's side: both directions are mirrored through
// the surface when wi is below it.
#include "bsdfs/microfacet.h"

namespace columba {

inline Vec3 mirroredThroughSurface(const Vec3& w) { return Vec3(w.x, w.y, -w.z); }

struct InterfacePair {
  Vec3 wi, wo;       // seen from wi's side: wi.z > 0
  float eta = 1.0f;  // relative index from wi's side to the other
  bool reflection = false;
  Vec3 m;              // the (generalised) half vector, toward wi's side
  bool valid = false;  // wi meets the front of m and wo leaves on its side (or through it)
};

// eta = index below / index above the surface (the normal, local +z, points to the exterior).
InterfacePair interfacePair(const Vec3& wi, const Vec3& wo, float eta);

// f |cos wo| of a valid pair without the Fresnel factor (F for reflection, 1 - F for refraction).
// Paths start at the camera: refraction includes the radiance scale 1 / eta^2.
float interfaceValue(const MicrofacetDistribution& distribution, const InterfacePair& p);
// Solid-angle density of wo when m is drawn from the normals visible from wi, before the choice
// between reflection and refraction.
float interfaceDensity(const MicrofacetDistribution& distribution, const InterfacePair& p);

// wi (wi.m = cosI > 0) refracted through a microfacet with normal m into a medium of relative
// index eta, with the refracted angle's cosine cosT.
inline Vec3 refractThrough(const Vec3& wi, const Vec3& m, float cosI, float eta, float cosT) {
  return -wi / eta + (cosI / eta - cosT) * m;
}

}  // namespace columba
