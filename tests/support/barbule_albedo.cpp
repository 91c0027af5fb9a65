#include "support/barbule_albedo.h"

#include "barbule/barbule_film.h"
#include "barbule/cross_section.h"
#include "core/frame.h"
#include "optics/melanin.h"

namespace columba::testing {

LobeAlbedo visibleNormalMeans(const BarbuleParameters& p, const Vec3& wi, const Wavelengths& wl) {
  BarbuleCrossSection geometry(p.b, p.phi0, p.phi1, p.mu, p.H, p.profileExponent);
  // The film: the cortex alone, whose transmittance is 1 - R, or with layers under it, whose
  // transmittance (absorbing layers take their share) comes from the transfer matrices.
  BarbuleFilm film(p, p.height, wl);
  const bool layeredFilm = !p.layersBelow.empty();
  Spectrum melanin;
  for (int k = 0; k < kSpectrumSamples; ++k)
    melanin[k] = p.melanin ? p.melanin->eval(wl[k]) : melaninReflectance(wl[k]);
  InPlaneDirection ip = inPlane(wi);
  LitArc arc = geometry.litArc(ip.dir);
  float r = geometry.coverage(arc, ip.dir);
  LobeAlbedo out;
  if (!(arc.width() > 0.0f)) return out;
  // R: visible normals on a fine grid of the (exact) visible-normal warp.
  const int hSteps = 2000, thetaSteps = 48;
  double sumR[kSpectrumSamples] = {};
  for (int i = 0; i < hSteps; ++i)
    for (int j = 0; j < thetaSteps; ++j) {
      VisibleNormal vn = sampleVisibleNormal(geometry, arc, wi, Vec2((i + 0.5f) / hSteps, (j + 0.5f) / thetaSteps));
      // The drawn point itself (on a superellipse's flat side its normal does not fix it).
      Vec2 point = geometry.pointAt(arc, arc.hMin + (i + 0.5f) / hSteps * arc.width());
      Vec3 wo = reflect(wi, vn.m);
      if (!geometry.isLitAt(geometry.litArc(inPlane(wo).dir), point, vn.localNormal)) continue;
      Vec2 n = geometry.toWorld(vn.localNormal);
      float shadow = LongitudinalDensity(inPlaneProjection(wo, n), wo.y).shadowing();
      FreeStandingFilm::Reflectance R = film.reflectance(dot(wi, vn.m));
      for (int k = 0; k < kSpectrumSamples; ++k) sumR[k] += 0.5 * shadow * (R.s[k] + R.p[k]);
    }
  for (int k = 0; k < kSpectrumSamples; ++k) out.reflection[k] = float(sumR[k] * r / (hSteps * thetaSteps));

  // TRT: coarser normals, and for each a grid of outgoing directions on the front side of its
  // in-plane normal (|cos theta_o| / pi integrates to 1 there).
  const int hCoarse = 48, thetaCoarse = 4, rows = 64, columns = 128;
  double sumTRT[kSpectrumSamples] = {};
  for (int i = 0; i < hCoarse; ++i)
    for (int j = 0; j < thetaCoarse; ++j) {
      VisibleNormal vn = sampleVisibleNormal(geometry, arc, wi, Vec2((i + 0.5f) / hCoarse, (j + 0.5f) / thetaCoarse));
      Vec2 point = geometry.pointAt(arc, arc.hMin + (i + 0.5f) / hCoarse * arc.width());
      Vec2 n2 = geometry.toWorld(vn.localNormal);
      Vec3 m0(n2.y, 0.0f, n2.x);  // theta = 0: its front side is the in-plane facing half-space
      Frame frame = Frame::fromNormal(m0);
      FreeStandingFilm::Reflectance in = film.reflectance(dot(wi, vn.m));
      for (int a = 0; a < rows; ++a)
        for (int b = 0; b < columns; ++b) {
          // Equal-area cells of the hemisphere around m0.
          float z = (a + 0.5f) / rows, phi = kTwoPi * (b + 0.5f) / columns, s = safeSqrt(1.0f - z * z);
          Vec3 wo = frame.toWorld(Vec3(s * std::cos(phi), s * std::sin(phi), z));
          if (!geometry.isLitAt(geometry.litArc(inPlane(wo).dir), point, vn.localNormal)) continue;
          FreeStandingFilm::Reflectance out = film.reflectance(std::abs(dot(wo, vn.m)));
          float weight = std::abs(wo.z) / kPi * (kTwoPi / (rows * columns));
          Spectrum energy =
              layeredFilm
                  ? weight * melanin * film.transmittanceProduct(dot(wi, vn.m), std::abs(dot(wo, vn.m)))
                  : (0.5f * weight) * melanin * ((1.0f - in.s) * (1.0f - out.s) + (1.0f - in.p) * (1.0f - out.p));
          for (int k = 0; k < kSpectrumSamples; ++k) sumTRT[k] += energy[k];
        }
    }
  for (int k = 0; k < kSpectrumSamples; ++k) out.trt[k] = float(sumTRT[k] * r / (hCoarse * thetaCoarse));
  return out;
}

}  // namespace columba::testing
