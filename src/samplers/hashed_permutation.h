#pragma once
// Random permutations of {0, ..., n-1} evaluated one element at a time from a hash, without
// storing them (Kensler 2013, "Correlated Multi-Jittered Sampling": an invertible integer hash
// on the smallest power-of-two domain covering n, cycle-walked until it lands below n).
#include <cstdint>

namespace columba {

// One pass of the hash: a bijection on the low bits selected by `mask` (2^k - 1). Every step is
// one: xor with a constant, multiply by an odd constant, or xor with a right shift of the masked
// value.
inline uint32_t permuteMaskedBits(uint32_t i, uint32_t mask, uint32_t seed) {
  i ^= seed;
  i *= 0xe170893du;
  i ^= seed >> 16;
  i ^= (i & mask) >> 4;
  i ^= seed >> 8;
  i *= 0x0929eb3fu;
  i ^= seed >> 23;
  i ^= (i & mask) >> 1;
  i *= 1u | seed >> 27;
  i *= 0x6935fa69u;
  i ^= (i & mask) >> 11;
  i *= 0x74dcb303u;
  i ^= (i & mask) >> 2;
  i *= 0x9e501cc3u;
  i ^= (i & mask) >> 2;
  i *= 0xc860a3dfu;
  i &= mask;
  i ^= i >> 5;
  return i;
}

// Element i of a permutation of {0, ..., n-1}.
inline uint32_t permutationElement(uint32_t i, uint32_t n, uint32_t seed) {
  uint32_t mask = n - 1;
  mask |= mask >> 1;
  mask |= mask >> 2;
  mask |= mask >> 4;
  mask |= mask >> 8;
  mask |= mask >> 16;
  do {
    i = permuteMaskedBits(i, mask, seed);
  } while (i >= n);
  // A power-of-two n (the low-discrepancy sampler's counts) needs no division.
  return (n & mask) == 0 ? (i + seed) & mask : (i + seed) % n;
}

// The same for n = mask + 1 a power of two, the mask given: no cycle walking is needed.
inline uint32_t permutationElementPowerOfTwo(uint32_t i, uint32_t mask, uint32_t seed) {
  return (permuteMaskedBits(i, mask, seed) + seed) & mask;
}

}  // namespace columba
