#pragma once
// The first two dimensions of the Sobol sequence, which together form a (0, 2)-sequence in
// base 2, and hash-based Owen scrambling that keeps that structure.
#include <cstdint>

namespace columba {

inline uint32_t reverseBits(uint32_t v) {
  v = __builtin_bswap32(v);  // the byte order; then the bits within each byte
  v = ((v & 0x0f0f0f0fu) << 4) | ((v & 0xf0f0f0f0u) >> 4);
  v = ((v & 0x33333333u) << 2) | ((v & 0xccccccccu) >> 2);
  v = ((v & 0x55555555u) << 1) | ((v & 0xaaaaaaaau) >> 1);
  return v;
}

// Both dimensions are generated with their bits reversed, the order in which Owen scrambling
// works. Dimension 0 (the van der Corput radical inverse) reversed is the index itself.
// Dimension 1 has the generator columns v_0 = 2^31, v_k = v_{k-1} ^ (v_{k-1} >> 1) (Pascal's
// triangle mod 2); reversed, r_k holds the coefficients of (1 + x)^k over GF(2), xor-ed together
// for the set bits of the index.
namespace detail {
// r_k summed over the set bits k of a byte.
struct SobolDimension1ByteTable {
  uint32_t value[256];
  constexpr SobolDimension1ByteTable() : value() {
    for (uint32_t byte = 0; byte < 256; ++byte) {
      uint32_t sum = 0, r = 1;
      for (uint32_t bits = byte; bits != 0; bits >>= 1, r ^= r << 1)
        if (bits & 1u) sum ^= r;
      value[byte] = sum;
    }
  }
};
inline constexpr SobolDimension1ByteTable kSobolDimension1Bytes{};
}  // namespace detail

inline uint32_t sobolDimension1Reversed(uint32_t index) {
  // Byte j of the index contributes (1 + x)^(8j) times its byte's sum, and over GF(2)
  // (1 + x)^8 = 1 + x^8, (1 + x)^16 = 1 + x^16: multiplications become shifted xors.
  const uint32_t* table = detail::kSobolDimension1Bytes.value;
  uint32_t b0 = table[index & 0xffu], b1 = table[(index >> 8) & 0xffu];
  uint32_t b2 = table[(index >> 16) & 0xffu], b3 = table[index >> 24];
  b1 ^= b1 << 8;
  b2 ^= b2 << 16;
  b3 ^= b3 << 8;
  b3 ^= b3 << 16;
  return b0 ^ b1 ^ b2 ^ b3;
}

// Nested uniform (Owen) scrambling (Burley 2020, "Practical Hash-based Owen Scrambling", after
// Laine and Karras 2011) of a 0.32 fraction given with its bits reversed; returns the scrambled
// fraction in the usual bit order. On reversed bits each step below changes a bit only as a
// function of the bits below it, so after reversing back every digit is flipped depending only on
// the digits before it: elementary intervals map onto elementary intervals.
inline uint32_t owenScrambleReversed(uint32_t reversed, uint32_t seed) {
  uint32_t v = reversed;
  v ^= v * 0x3d20adeau;
  v += seed;
  v *= (seed >> 16) | 1u;
  v ^= v * 0x05526c56u;
  v ^= v * 0x53a22864u;
  return reverseBits(v);
}

// A 0.32 fraction as a float in [0, 1), truncated to the float's 24 bits so it never rounds to 1.
inline float fractionToFloat(uint32_t v) { return float(v >> 8) * 0x1p-24f; }

}  // namespace columba
