#pragma once
/*! parameters sampler
| parameter | type | default | meaning | Mitsuba 3 |
| sample_count | integer | 4 | samples per pixel, 1 to 2^24 (the command line's `--spp` overrides it) | same |
| seed | integer | 0 | mixed into the seed of every pixel sample: renders with different seeds are independent | same |
*/
// The parameters every sampler plug-in shares (Mitsuba 3 names and defaults).
#include <cstdint>
#include "core/properties.h"

namespace columba {

// The most samples per pixel a render may take (scene files and the command line alike).
constexpr int kMaxSamplesPerPixel = 1 << 24;

struct SamplerParameters {
  int sampleCount = 4;
  // Mixed into the seed of every pixel sample, so renders with different seeds are independent.
  uint64_t seed = 0;
};

inline SamplerParameters readSamplerParameters(const Properties& props) {
  SamplerParameters p;
  p.sampleCount = props.getInt("sample_count", 4);
  if (p.sampleCount < 1 || p.sampleCount > kMaxSamplesPerPixel)
    throw props.error("sample_count", "must be between 1 and 2^24, got " + std::to_string(p.sampleCount));
  p.seed = uint64_t(int64_t(props.getInt("seed", 0)));
  return p;
}

}  // namespace columba
