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
