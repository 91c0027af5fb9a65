/*! plugin volume constvolume
One value everywhere within the unit cube that `to_world` places in the scene (outside it a medium has none). A medium's `sigma_t` or `albedo` given directly as a `<float>`, `<rgb>` or `<spectrum>` is such a volume filling all space.
Mitsuba 3: as Mitsuba 3's `constvolume`; where `to_world` rotates, Columba's volume is the rotated cube, Mitsuba's the box around it.
| parameter | type | default | meaning | Mitsuba 3 |
| value | spectrum | 1 | the value: an extinction (non-negative, an `<rgb>` may exceed 1) or an albedo, as the medium reads it | same |
| to_world | transform | identity | places the unit cube [0, 1]³ in the scene | same |
*/
#include "media/const_volume.h"

#include <cmath>

namespace columba {

float ConstVolume::maxOf(const SpectralDistribution& value) {
  // A bound over the wavelengths a path may carry, every 1 nm (the spectra given in scenes are
  // smooth or piecewise linear between whole nanometres).
  float largest = 0.0f;
  for (float lambda = kSpectralMin; lambda <= kLambdaMax; lambda += 1.0f)
    largest = std::max(largest, value.eval(lambda));
  return largest;
}

std::shared_ptr<Object> makeConstVolume(const Properties& props) {
  return std::make_shared<ConstVolume>(props.getSpectrum("value", 1.0f, SpectrumUse::NonNegative),
                                       props.getTransform("to_world"));
}

}  // namespace columba
