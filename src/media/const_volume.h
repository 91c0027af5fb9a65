#pragma once
// `constvolume`: one spectrum everywhere in the volume's unit cube.
#include "media/volume.h"

namespace columba {

class ConstVolume final : public Volume {
 public:
  ConstVolume(SpectralDistribution value, const std::optional<Transform>& toWorld)
      : Volume(toWorld), value_(std::move(value)), max_(maxOf(value_)) {}
  float maxValue(const Vec3&, const Vec3&) const override { return max_; }
  float largestGivenValue() const override { return max_; }

 protected:
  Spectrum evalLocal(const Vec3&, const Wavelengths& wl) const override { return value_.sample(wl); }

 private:
  static float maxOf(const SpectralDistribution& value);
  SpectralDistribution value_;
  float max_;
};

std::shared_ptr<Object> makeConstVolume(const Properties& props);

}  // namespace columba
