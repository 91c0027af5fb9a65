/*! plugin medium heterogeneous
A medium whose extinction σ_t and albedo vary in space, each given by a nested `<volume>` (`gridvolume`, `constvolume`) or as a value everywhere. The medium lies where the extinction volume's cube is (and where shapes bound it, as for `homogeneous`). Collisions are drawn against majorants, `scale` times the largest extinction within each cell of a coarse grid over the extinction volume's cube (one value for a `constvolume`; see `gridvolume`), so that a few dense voxels slow the tracking only where they are: a collision is real with probability σ_t / majorant, and scatters with weight albedo; otherwise it is null and the path goes on (delta tracking). Shadow rays estimate transmittance by ratio tracking. An albedo outside [0, 1], as a value or in a volume, is refused (Mitsuba takes it as given).
Mitsuba 3: `sample_emitters` and `has_spectral_extinction` are not read.
| parameter | type | default | meaning | Mitsuba 3 |
| sigma_t | volume | 1 | the extinction coefficient per unit of scene distance, before `scale`: a nested `<volume name="sigma_t">` or a `<float>`, `<rgb>` or `<spectrum>`; not negative | same |
| albedo | volume | 0.75 | the fraction of extinction that scatters, in [0, 1]: a nested `<volume name="albedo">` or a value | same, but not refused outside [0, 1] |
| scale | float | 1 | multiplies `sigma_t`; not negative | same |
*/
#include "media/heterogeneous_medium.h"

namespace columba {

MediumCoefficients HeterogeneousMedium::coefficients(const Vec3& p, const Wavelengths& wl) const {
  const Spectrum sigmaT = sigmaT_->eval(p, wl) * scale_;
  return {sigmaT, sigmaT * albedo_->eval(p, wl)};
}

MajorantIterator HeterogeneousMedium::majorant(const Ray& ray, const Wavelengths&) const {
  const auto inside = sigmaT_->clip(ray);
  if (!inside) return {};
  const std::array<int, 3>& cells = majorants_.resolution();
  if (cells[0] * cells[1] * cells[2] == 1)  // a volume of one value, possibly filling all space
    return MajorantIterator(inside->first, inside->second, Spectrum(scale_ * majorants_.bound({0, 0, 0})));
  // The cells are crossed in the volume's own space, where the ray keeps its parameter t.
  const Transform& toLocal = sigmaT_->worldToLocal();
  return MajorantIterator(majorants_, scale_, toLocal.point(ray.o), toLocal.vector(ray.d), inside->first,
                          inside->second);
}

std::shared_ptr<Object> makeHeterogeneousMedium(const Properties& props) {
  auto sigmaT = mediumVolume(props, "sigma_t", 1.0f, SpectrumUse::NonNegative);
  auto albedo = mediumVolume(props, "albedo", 0.75f, SpectrumUse::Fraction);
  return std::make_shared<HeterogeneousMedium>(std::move(sigmaT), std::move(albedo), mediumScale(props),
                                               mediumPhase(props), &props);
}

}  // namespace columba
