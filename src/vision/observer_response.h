#pragma once
// What a film records for a visual system (hdrfilm's `observer`): every cone's quantum catch of the
// radiance each camera sample carries, estimated from the sample's wavelengths, and the density those
// wavelengths are drawn with, which follows the cones (docs/vision.md, "Rendering for a bird").
#include <string>
#include <vector>
#include "core/spectrum.h"
#include "vision/observer.h"

namespace columba {

// The light whose white the catches are relative to (von Kries adaptation).
//   D65:  each catch divided by that of a white reflector under D65 of luminance 1, the white of
//         Columba's emitters: a white diffuse surface lit as it is white in RGB catches 1 in every cone;
//   None: absolute catches, the integral of radiance times sensitivity; each sensitivity has area
//         1, so this is also the adaptation to an equal-quantum white.
enum class Adaptation { D65, None };

class ObserverResponse {
 public:
  ObserverResponse(Observer observer, Adaptation adaptation);
  const Observer& observer() const { return observer_; }
  Adaptation adaptation() const { return adaptation_; }
  // The chromatic channels, then the achromatic one where the observer has it.
  const std::vector<std::string>& channels() const { return channels_; }
  // The density the wavelengths are drawn with over 300-830 nm: 9/10 the mean of the sensitivities,
  // so each cone's catch is estimated from the wavelengths it sees, and 1/10 uniform, so that every
  // wavelength the RGB beside it needs has some.
  const WavelengthTable& wavelengths() const { return wavelengths_; }
  // Adds one camera sample's estimate of every channel's catch, times `scale`, to `values`: the
  // mean over the path's wavelengths of L S_c / pdf, divided by the adapting white's catch.
  void accumulate(const Spectrum& L, const Wavelengths& wl, float scale, float* values) const;
  // The sensitivity of channel c at lambda (linear between the grid's wavelengths, 0 outside it).
  float sensitivity(size_t c, float lambda) const;

 private:
  Observer observer_;
  Adaptation adaptation_;
  std::vector<std::string> channels_;  // chromatic, then achromatic
  std::vector<double> white_;          // the adapting white's catch per channel
  WavelengthTable wavelengths_;
};

// What the cone channels of an image hold, for its metadata: the observer, its channels, the
// adaptation and how its PNG shows them.
std::string describeObserver(const ObserverResponse& response);

// "d65" or "none"; throws std::invalid_argument naming the known ones.
Adaptation adaptationNamed(const std::string& name);

}  // namespace columba
