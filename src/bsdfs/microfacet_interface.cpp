#include "bsdfs/microfacet_interface.h"

#include <cmath>
#include "bsdfs/bsdf.h"

namespace columba {

InterfacePair interfacePair(const Vec3& wi, const Vec3& wo, float eta) {
  InterfacePair p;
  if (cosTheta(wi) == 0.0f || cosTheta(wo) == 0.0f) return p;
  bool inside = cosTheta(wi) < 0.0f;
  p.wi = inside ? mirroredThroughSurface(wi) : wi;
  p.wo = inside ? mirroredThroughSurface(wo) : wo;
  p.eta = inside ? 1.0f / eta : eta;
  p.reflection = cosTheta(p.wo) > 0.0f;
  // Reflection: the half vector; refraction: Walter's -(wi + eta wo), both turned toward +z.
  Vec3 h = p.reflection ? p.wi + p.wo : -(p.wi + p.eta * p.wo);
  float len = length(h);
  if (!(len > 0.0f)) return p;
  p.m = h / len;
  if (p.m.z < 0.0f) p.m = -p.m;
  float iDotM = dot(p.wi, p.m), oDotM = dot(p.wo, p.m);
  p.valid = iDotM > 0.0f && (p.reflection ? oDotM > 0.0f : oDotM < 0.0f);
  return p;
}

float interfaceValue(const MicrofacetDistribution& distribution, const InterfacePair& p) {
  float D = distribution.D(p.m), G = distribution.G(p.wi, p.wo, p.m);
  if (p.reflection) return D * G / (4.0f * cosTheta(p.wi));
  // Walter's f_t |cos wo| = |i.m| |o.m| eta^2 (1 - F) D G / (|i.n| (i.m + eta o.m)^2), times
  // 1 / eta^2 for radiance.
  float iDotM = dot(p.wi, p.m), oDotM = dot(p.wo, p.m);
  float denom = iDotM + p.eta * oDotM;
  return D * G * iDotM * std::abs(oDotM) / (cosTheta(p.wi) * denom * denom);
}

float interfaceDensity(const MicrofacetDistribution& distribution, const InterfacePair& p) {
  float visible = distribution.visiblePdf(p.wi, p.m), oDotM = dot(p.wo, p.m);
  if (p.reflection) return visible / (4.0f * oDotM);
  // dm / dwo for refraction: eta^2 |o.m| / (i.m + eta o.m)^2.
  float denom = dot(p.wi, p.m) + p.eta * oDotM;
  return visible * p.eta * p.eta * std::abs(oDotM) / (denom * denom);
}

}  // namespace columba
