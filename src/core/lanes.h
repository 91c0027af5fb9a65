#pragma once
// Four floats in one SIMD register (GCC/Clang vector extension): arithmetic evaluated at several
// points at once (a path's wavelengths, a quadrature's nodes) that must not depend on the
// compiler choosing to vectorise a loop.
#include <cmath>
#if defined(__SSE__)
#include <xmmintrin.h>
#endif

namespace columba {

using FloatLanes = float __attribute__((vector_size(16)));
inline constexpr int kLaneCount = 4;

inline FloatLanes sqrtLanes(FloatLanes v) {
#if defined(__SSE__)
  return _mm_sqrt_ps(v);
#else
  return FloatLanes{std::sqrt(v[0]), std::sqrt(v[1]), std::sqrt(v[2]), std::sqrt(v[3])};
#endif
}

inline FloatLanes absLanes(FloatLanes v) { return v < 0.0f ? -v : v; }

}  // namespace columba
