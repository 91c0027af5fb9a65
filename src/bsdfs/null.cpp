/*! plugin bsdf null
The surface is not there for light: rays and shadow rays pass straight through and nothing is scattered (a shape that only carries an emitter).
Mitsuba 3: as Mitsuba 3's `null`.
*/
#include "bsdfs/null.h"

namespace columba {

std::optional<BSDFSample> NullBSDF::sample(const BSDFContext&, const Vec3& wi, const Wavelengths&, float, Vec2) const {
  BSDFSample s;
  s.wo = -wi;
  s.weight = Spectrum(1.0f);
  s.pdf = 1.0f;
  s.delta = s.passThrough = true;
  return s;
}

std::shared_ptr<Object> makeNullBSDF(const Properties&) { return std::make_shared<NullBSDF>(); }

}  // namespace columba
