#include "core/fast_math.h"

namespace columba {

namespace {
constexpr FloatLanes splat(float c) { return FloatLanes{c, c, c, c}; }
}  // namespace

const SinSqrConstants kSinSqrConstants = {splat(1.0f / kPi), splat(kPi), splat(kRoundToNearest)};

}  // namespace columba
