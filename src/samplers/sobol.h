#pragma once
// The first eight dimensions of the Sobol sequence (its first two together form a (0, 2)-sequence
// in base 2), and hash-based Owen scrambling that keeps their structure.
#include <cstdint>

namespace columba {

constexpr uint32_t reverseBits(uint32_t v) {
  v = __builtin_bswap32(v);  // the byte order; then the bits within each byte
  v = ((v & 0x0f0f0f0fu) << 4) | ((v & 0xf0f0f0f0u) >> 4);
  v = ((v & 0x33333333u) << 2) | ((v & 0xccccccccu) >> 2);
  v = ((v & 0x55555555u) << 1) | ((v & 0xaaaaaaaau) >> 1);
  return v;
}

// Points are generated with their bits reversed, the order in which Owen scrambling works.
// Dimension 0 (the van der Corput radical inverse) reversed is the index itself. Dimension 1 has
// the generator columns v_0 = 2^31, v_k = v_{k-1} ^ (v_{k-1} >> 1) (Pascal's triangle mod 2);
// reversed, r_k holds the coefficients of (1 + x)^k over GF(2), xor-ed together for the set bits
// of the index.
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

// Dimensions 0 to kSobolDimensions - 1 by their generator matrices' columns, bits reversed: point
// `index` of a dimension, reversed, is the xor of the columns of the index's set bits. Dimension 0
// is van der Corput's; from dimension 1 on, columns v_k = m_k 2^(31 - k) for k below the degree s
// of the dimension's primitive polynomial x^s + a_1 x^(s-1) + ... + a_(s-1) x + 1, then
//   v_k = v_(k-s) ^ (v_(k-s) >> s) ^ (a_1 v_(k-1)) ^ ... ^ (a_(s-1) v_(k-s+1)).
// Polynomials and initial m_k of Joe and Kuo, "Constructing Sobol sequences with better
// two-dimensional projections" (SIAM J. Sci. Comput. 30, 2008), table new-joe-kuo-6.21201,
// its dimensions 2 to 8.
inline constexpr int kSobolDimensions = 8;
namespace detail {
struct SobolMatrices {
  uint32_t reversedColumns[kSobolDimensions][32];
  constexpr SobolMatrices() : reversedColumns() {
    struct Primitive {
      int degree;
      uint32_t inner;  // a_1 ... a_(s-1), a_1 the most significant bit
      uint32_t m[5];
    };
    constexpr Primitive primitives[kSobolDimensions - 1] = {
        {1, 0, {1}},          {2, 1, {1, 3}},        {3, 1, {1, 3, 1}},       {3, 2, {1, 1, 1}},
        {4, 1, {1, 1, 3, 3}}, {4, 4, {1, 3, 5, 13}}, {5, 2, {1, 1, 5, 5, 17}}};
    for (int k = 0; k < 32; ++k) reversedColumns[0][k] = 1u << k;
    for (int d = 1; d < kSobolDimensions; ++d) {
      const Primitive& p = primitives[d - 1];
      uint32_t v[32] = {};
      for (int k = 0; k < 32; ++k) {
        if (k < p.degree) {
          v[k] = p.m[k] << (31 - k);
          continue;
        }
        v[k] = v[k - p.degree] ^ (v[k - p.degree] >> p.degree);
        for (int j = 1; j < p.degree; ++j)
          if ((p.inner >> (p.degree - 1 - j)) & 1u) v[k] ^= v[k - j];
      }
      for (int k = 0; k < 32; ++k) reversedColumns[d][k] = reverseBits(v[k]);
    }
  }
};
inline constexpr SobolMatrices kSobolMatrices{};
}  // namespace detail

inline const uint32_t* sobolReversedColumns(int dimension) { return detail::kSobolMatrices.reversedColumns[dimension]; }

// Point `index` of dimension `dimension` (below kSobolDimensions), its bits reversed.
inline uint32_t sobolReversed(int dimension, uint32_t index) {
  const uint32_t* columns = sobolReversedColumns(dimension);
  uint32_t v = 0;
  for (int k = 0; index != 0; ++k, index >>= 1) v ^= (0u - (index & 1u)) & columns[k];
  return v;
}

// Dimension 1 through a table of bytes (the padded pattern's every point needs it).
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
