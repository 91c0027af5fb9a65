#pragma once
// PCG32 (O'Neill 2014): small, fast, and seedable per pixel so renders are deterministic.
#include <cstdint>

namespace columba {

class PCG32 {
 public:
  PCG32(uint64_t seed = 0x853c49e6748fea9bULL, uint64_t stream = 0xda3e39cb94b95bdbULL) { seedWith(seed, stream); }
  void seedWith(uint64_t seed, uint64_t stream) {
    state_ = 0;
    inc_ = (stream << 1u) | 1u;
    nextUInt();
    state_ += seed;
    nextUInt();
  }
  uint32_t nextUInt() {
    uint64_t old = state_;
    state_ = old * 6364136223846793005ULL + inc_;
    uint32_t xorshifted = uint32_t(((old >> 18u) ^ old) >> 27u);
    uint32_t rot = uint32_t(old >> 59u);
    return (xorshifted >> rot) | (xorshifted << ((32 - rot) & 31));
  }
  // Uniform in [0, 1), never 1.
  float nextFloat() { return float(nextUInt() >> 8) * 0x1p-24f; }
  double nextDouble() { return double((uint64_t(nextUInt()) << 21) ^ nextUInt()) * 0x1p-53; }

 private:
  uint64_t state_, inc_;
};

// 64-bit finaliser (MurmurHash3 fmix64): decorrelates seeds built from pixel coordinates.
inline uint64_t mixBits(uint64_t v) {
  v ^= v >> 33;
  v *= 0xff51afd7ed558ccdULL;
  v ^= v >> 33;
  v *= 0xc4ceb9fe1a85ec53ULL;
  v ^= v >> 33;
  return v;
}
inline uint64_t hashCombine(uint64_t a, uint64_t b) {
  return mixBits(a ^ (mixBits(b) + 0x9e3779b97f4a7c15ULL + (a << 6) + (a >> 2)));
}

}  // namespace columba
