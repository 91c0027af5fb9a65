/*! plugin medium homogeneous
A medium of the same extinction σ_t and single-scattering albedo everywhere: light travelling a distance d is attenuated by exp(−σ_t d), and of what is removed the albedo's fraction is scattered as the phase function (a nested `<phase>`, isotropic by default) says. A shape bounds it as its `interior` or `exterior` (`<ref name="interior" id="..."/>` or a nested `<medium name="interior">`), and a sensor may sit in one (a `<medium>` nested in the `<sensor>`); `volpath` and `volpathmis` render it. An `<rgb>` extinction is upsampled to a smooth spectrum (unbounded), so the extinction may vary with the wavelength.
Mitsuba 3: `sigma_t` and `albedo` take values only (no nested `<volume>`); `sample_emitters` and `has_spectral_extinction` are not read.
| parameter | type | default | meaning | Mitsuba 3 |
| sigma_t | spectrum | 1 | the extinction coefficient per unit of scene distance, before `scale`; not negative | same |
| albedo | spectrum | 0.75 | the fraction of extinction that scatters, in [0, 1] in every form (`<float>`, `<rgb>`, `<spectrum>`), refused outside it | same, but not refused outside [0, 1] (an `<rgb>` is clamped) |
| scale | float | 1 | multiplies `sigma_t` (the scene's unit of distance); not negative | same |
*/
#include "media/homogeneous_medium.h"

namespace columba {

MediumCoefficients HomogeneousMedium::coefficients(const Vec3&, const Wavelengths& wl) const {
  const Spectrum sigmaT = sigmaT_.sample(wl) * scale_;
  return {sigmaT, sigmaT * albedo_.sample(wl)};
}

MajorantIterator HomogeneousMedium::majorant(const Ray& ray, const Wavelengths& wl) const {
  return MajorantIterator(ray.tmin, ray.tmax, sigmaT_.sample(wl) * scale_);
}

std::shared_ptr<Object> makeHomogeneousMedium(const Properties& props) {
  return std::make_shared<HomogeneousMedium>(props.getSpectrum("sigma_t", 1.0f, SpectrumUse::NonNegative),
                                             props.getSpectrum("albedo", 0.75f, SpectrumUse::Fraction),
                                             mediumScale(props), mediumPhase(props), &props);
}

}  // namespace columba
