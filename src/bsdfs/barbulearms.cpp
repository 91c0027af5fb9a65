/*! plugin bsdf barbulearms
Barbules whose cross-section is a chain of flat arms: a V, a boomerang, or the three mirrors of Lawes' parotia's breast barbules (Stavenga et al. 2011), which the ellipse of `barbulebsdf` cannot describe. Each arm is a superellipse (semi-axes `b` across it and 1 along it, exponent `profile_exponent`) tilted by its angle; the arms are joined end to end, and the side of each that faces along its own tilted normal carries the keratin film (over any `layers`). The barbule shadows and masks itself and its neighbours, exactly (docs/model.md, "Cross-sections made of arms"). Its lobes are R, the film's specular reflection, and T, light passing between the barbules or meeting their uncoated sides (a pass-through). Light the film transmits is taken as absorbed inside the barbule (there is no TRT lobe), and light reflected from one arm onto another is not followed. The frame is barbulebsdf's: z along the vane normal, y along the barbule axis.

On a feather whose file gives per-vertex `height`, that wins over a constant given here (with a warning naming the line); per-vertex `mu` and `H` have no effect (one warning), and a feather choosing a layer stack other than 0 is an error.
Mitsuba 3: not in Mitsuba 3.
| parameter | type | default | meaning | Mitsuba 3 |
| arm_tilts | string | — (required) | the arms' tilts in degrees, from one end of the chain to the other (toward +x), each the angle from the vane normal to the arm's face normal, from −89 to 89: `-30, 0, 30` is a roof of three mirrors, `30, 0, -30` a trough; 1 to 8 arms | not in Mitsuba 3 |
| b | float | 0.25 | each arm's semi-axis across it, in units of its half-length, from 10⁻⁴ to 100 | not in Mitsuba 3 |
| profile_exponent | float | 4 | each arm's superellipse exponent, 2 (an ellipse) to 16 (a slab with rounded corners) | not in Mitsuba 3 |
| mu | float | 0 | the tilt of the whole cross-section about the barbule axis, in radians | not in Mitsuba 3 |
| H | float | 0 | the barbule spacing, in units of an arm's half-length; below the spacing at which neighbours touch it is that spacing (0: packed edge to edge) | not in Mitsuba 3 |
| height | float | 0.6 | the keratin film's thickness in micrometres, as barbulebsdf's | not in Mitsuba 3 |
| film_ior | float, string or spectrum | `keratin` | the film's index, as barbulebsdf's | not in Mitsuba 3 |
| film_cauchy_a | float | — | the film's index as a Cauchy law a + b/λ², instead of `film_ior` | not in Mitsuba 3 |
| film_cauchy_b | float | 0 | the Cauchy law's b (λ in nanometres) | not in Mitsuba 3 |
| ext_ior | float or string | `air` (1.000277) | the surrounding medium's constant index | not in Mitsuba 3 |
| layers | string | — | layers under the cortex, as barbulebsdf's `layers` takes them (written out, rows of rods, repeats, or a published stack's name) | not in Mitsuba 3 |
*/
#include "bsdfs/barbulearms.h"

#include <fmt/format.h>
#include <algorithm>
#include <cmath>

#include "barbule/barbule_film.h"
#include "barbule/normals.h"
#include "barbule/parameter_reader.h"

namespace columba {

namespace {

// The half vector of (wi, wo) with its in-plane part, where it can be one of the barbules'
// normals (|theta_m| below thetaD).
struct HalfVector {
  Vec3 m;
  InPlaneDirection plane;
};
std::optional<HalfVector> barbuleHalfVector(const Vec3& wi, const Vec3& wo) {
  const Vec3 sum = wi + wo;
  const float lengthSqr = lengthSquared(sum);
  if (!(lengthSqr > 0.0f)) return std::nullopt;
  HalfVector h;
  h.m = sum / std::sqrt(lengthSqr);
  if (!(std::abs(h.m.y) < kSinBarbuleThetaD)) return std::nullopt;
  h.plane = inPlane(h.m);
  if (!(h.plane.cosTheta > 0.0f)) return std::nullopt;
  return h;
}

}  // namespace

BarbuleArmsBSDF::BarbuleArmsBSDF(ArmedCrossSection geometry, BarbuleParameters film)
    : geometry_(std::move(geometry)), film_(std::move(film)) {}

float BarbuleArmsBSDF::coverage(const Vec3& omegaI) const {
  // Light crossing from below follows the line of light along -w from above (as barbulebsdf's).
  const InPlaneDirection p = inPlane(omegaI.z < 0.0f ? -omegaI : omegaI);
  if (!(p.cosTheta > 0.0f) || p.dir.x == 0.0f) return 0.0f;
  return float(geometry_.coverage(toDouble(p.dir)));
}

BSDFEvalPdf BarbuleArmsBSDF::valueAndPdf(const BSDFContext& ctx, const Vec3& wi, const Vec3& wo,
                                         const Wavelengths& wl) const {
  BSDFEvalPdf out;
  if (!(wi.z > 0.0f) || wo.z == 0.0f) return out;
  const std::optional<HalfVector> half = barbuleHalfVector(wi, wo);
  if (!half) return out;
  const InPlaneDirection in = inPlane(wi), outPlane = inPlane(wo);
  const Vec2 n = half->plane.dir;
  if (!(in.cosTheta > 0.0f) || !(outPlane.cosTheta > 0.0f) || !(dot2(n, in.dir) > 0.0f) ||
      !(dot2(n, outPlane.dir) > 0.0f))
    return out;
  // The arms' points with this normal that both directions reach: their radii of curvature add up
  // in D (each is surface per unit normal angle) and in the density of the offset drawn.
  double radii = 0.0;
  for (const ArmPoint& p : geometry_.pointsWithNormal(toDouble(n)))
    if (geometry_.isReached(p.arm, p.point, toDouble(in.dir)) &&
        geometry_.isReached(p.arm, p.point, toDouble(outPlane.dir)))
      radii += p.radiusOfCurvature;
  if (!(radii > 0.0)) return out;
  const float H = float(geometry_.spacing());

  // f_R |cos_o| = F D S_i S_o / (4 |cos_i|), D = sum rho / (H 2 sin(thetaD) cos(theta_m)), as
  // barbulebsdf's R lobe with its single point replaced by the reached ones (docs/model.md §7).
  const float A = inPlaneProjection(wi, n);
  const float ndf = float(radii) / (H * 2.0f * kSinBarbuleThetaD * half->plane.cosTheta);
  const float shadowIn = longitudinalShadowing(A, wi.y);
  const float shadowOut = longitudinalShadowing(inPlaneProjection(wo, n), wo.y);
  const float cosHalf = dot(wi, half->m);
  // A feather's per-vertex thickness, 0 standing for the BSDF's own (as barbulebsdf reads it).
  const std::optional<float> given = ctx.attribute(kCortexThicknessAttribute);
  const float thickness = std::max(given && *given != 0.0f ? *given : film_.height, 0.0f);
  const FreeStandingFilm::Reflectance film = BarbuleFilm(film_, thickness, wl).reflectance(cosHalf);
  out.value = (0.5f * ndf * shadowIn * shadowOut / (4.0f * wi.z)) * (film.s + film.p);

  // The sampler draws the offset uniformly over a period seen from wi, H |cos gamma_i|, so the
  // normal angle with density rho cos(gamma_i - phi) / (H |cos gamma_i|) summed over the points;
  // theta given it from LongitudinalDensity; dm = cos(theta_m) dtheta dphi; wo = reflect(wi, m).
  const float pdfPhi = float(radii) * (A / in.cosTheta) / (H * std::abs(in.dir.x));
  const float pdfTheta = LongitudinalDensity(A, wi.y).pdfFromProjection(cosHalf);
  if (cosHalf > 0.0f) out.pdf = pdfPhi * pdfTheta / half->plane.cosTheta / (4.0f * cosHalf);
  return out;
}

BarbuleLobes BarbuleArmsBSDF::lobes(const Vec3& omegaI, const Vec3& omegaO, const Wavelengths& wl) const {
  if (omegaO.z == 0.0f) return {};
  return {valueAndPdf({}, omegaI, omegaO, wl).value / std::abs(omegaO.z), Spectrum(0.0f)};
}

Spectrum BarbuleArmsBSDF::eval(const BSDFContext& ctx, const Vec3& wi, const Vec3& wo, const Wavelengths& wl) const {
  return valueAndPdf(ctx, wi, wo, wl).value;
}

float BarbuleArmsBSDF::pdf(const BSDFContext& ctx, const Vec3& wi, const Vec3& wo, const Wavelengths& wl) const {
  return valueAndPdf(ctx, wi, wo, wl).pdf;
}

std::optional<BSDFSample> BarbuleArmsBSDF::sample(const BSDFContext& ctx, const Vec3& wi, const Wavelengths& wl,
                                                  float uComponent, Vec2 u) const {
  const InPlaneDirection in = inPlane(wi);
  // Light passing on, chosen with `probability`, carries T = 1 - coverage over it.
  auto passingThrough = [&](float t, float probability) -> std::optional<BSDFSample> {
    if (!(t > 0.0f) || !(probability > 0.0f)) return std::nullopt;
    BSDFSample bs;
    bs.wo = -wi;
    bs.pdf = probability;
    bs.weight = Spectrum(t / probability);
    bs.delta = bs.passThrough = true;
    return bs;
  };
  // From below, or along the barbules, nothing is reflected.
  if (!(wi.z > 0.0f) || !(in.cosTheta > 0.0f) || in.dir.x == 0.0f) return passingThrough(1.0f - coverage(wi), 1.0f);

  // The line at an offset uniform over one period seen from wi: what it meets first is a point
  // lit from wi, drawn in proportion to its projected width; a line meeting no coated side passes.
  const Vec2d d = toDouble(in.dir);
  const double period = geometry_.spacing() * std::abs(d.x);
  const std::optional<ArmHit> hit = geometry_.firstHit(d, double(uComponent) * period);
  if (!hit || !hit->coated) {
    const float t = 1.0f - coverage(wi);  // also the probability of this branch
    return passingThrough(t, t);
  }

  const Vec2 n(float(hit->normal.x), float(hit->normal.y));
  const float theta = LongitudinalDensity(inPlaneProjection(wi, n), wi.y).sample(u.x);
  BSDFSample bs;
  bs.wo = reflect(wi, barbuleNormal(n, std::cos(theta), std::sin(theta)));
  // The point must also be seen from wo: the barbule or a neighbour may mask it.
  const InPlaneDirection out = inPlane(bs.wo);
  if (bs.wo.z == 0.0f || !(out.cosTheta > 0.0f) || !(dot2(n, out.dir) > 0.0f) ||
      !geometry_.isReached(hit->arm, hit->point, toDouble(out.dir)))
    return std::nullopt;
  const BSDFEvalPdf f = valueAndPdf(ctx, wi, bs.wo, wl);
  if (!(f.pdf > 0.0f)) return std::nullopt;
  bs.pdf = f.pdf;
  bs.weight = f.value / f.pdf;
  return bs;
}

Spectrum BarbuleArmsBSDF::passThrough(const BSDFContext&, const Vec3& wi, const Wavelengths&) const {
  return Spectrum(1.0f - coverage(wi));
}

void BarbuleArmsBSDF::noteValuesGivenByShape(const ShapePointValues& given) const {
  if (heightSource_) heightSource_->warnIfShadowed(given.everywhere, given.shape);
  if (given.largestLayerStack > 0)
    throw InputError(given.largestLayerStackAt, given.shape + " chooses layer stack " +
                                                    std::to_string(given.largestLayerStack) + " (" +
                                                    given.largestLayerStackElement + "), but its barbulearms (" +
                                                    declaredAt_.str() + ") has only stack 0, `layers`");
  const bool crossSection =
      given.everywhere.contains(kBarbuleTiltAttribute) || given.everywhere.contains(kBarbuleSpacingAttribute);
  if (crossSection && !warnedShapeValues_->exchange(true))
    warn(declaredAt_, "barbulearms: " + given.shape +
                          " gives per-vertex 'mu' or 'H', which have no effect on it: its cross-section is the same "
                          "everywhere (said once)");
}

std::shared_ptr<Object> makeBarbuleArmsBSDF(const Properties& props) {
  BarbuleParameters film;
  film.b = props.getFloat("b", 0.25f);
  film.profileExponent = props.getFloat("profile_exponent", 4.0f);
  film.mu = props.getFloat("mu", 0.0f);
  const float H = props.getFloat("H", 0.0f);
  readBarbuleFilm(props, film);
  if (!(film.b >= kMinArmSemiAxis && film.b <= kMaxArmSemiAxis))
    throw props.error("b", "an arm's semi-axis must lie between 1e-4 and 100 (its half-length is 1)");
  if (!(H >= 0.0f) || !std::isfinite(H)) throw props.error("H", "the barbule spacing must not be negative");
  film.H = std::max(H, 1.0f);  // for the check of H below; the spacing used is set after it
  throwIfProblem(props, film);
  if (std::optional<BarbuleParameterProblem> odd = findImplausibility(film))
    warn(props.locationOf(odd->parameter), "barbulearms, parameter '" + odd->parameter + "': " + odd->message);

  std::vector<double> tilts;
  for (double degrees : props.getNumberList("arm_tilts")) {
    if (!(std::abs(degrees) * kPiDouble / 180.0 <= kMaxArmTilt))
      throw props.error("arm_tilts", fmt::format("'{:g}' is not a tilt in degrees from -89 to 89", degrees));
    tilts.push_back(degrees * kPiDouble / 180.0);
  }
  if (tilts.empty() || tilts.size() > size_t(kMaxBarbuleArms))
    throw props.error("arm_tilts",
                      "give 1 to " + std::to_string(kMaxBarbuleArms) + " arms, got " + std::to_string(tilts.size()));
  ArmedCrossSection geometry(tilts, film.b, film.profileExponent, film.mu, H);
  film.H = float(geometry.spacing());
  auto bsdf = std::make_shared<BarbuleArmsBSDF>(std::move(geometry), std::move(film));
  const std::string noPreset;  // this BSDF has none
  bsdf->setSceneSources(
      std::make_shared<PerPointParameterSources>(
          props, noPreset,
          std::initializer_list<PerPointParameterSources::Parameter>{{"height", kCortexThicknessAttribute, false}}),
      props.location);
  return bsdf;
}

}  // namespace columba
