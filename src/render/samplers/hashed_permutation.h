#pragma once
// Random permutations of {0, ..., n-1} evaluated one element at a time from a hash, without
// storing them (Kensler 2013, "Correlated Multi-Jittered Sampling": an invertible integer hash
// on the smallest power-of-two domain covering n, cycle-walked until it lands below n).
#include <cstdint>

namespace columba {

inline uint32_t permutationElement(uint32_t i, uint32_t n, uint32_t seed) {
  uint32_t mask = n - 1;
  mask |= mask >> 1;
  mask |= mask >> 2;
  mask |= mask >> 4;
  mask |= mask >> 8;
  mask |= mask >> 16;
  // Every step is a bijection on the low bits selected by `mask`: xor with a constant, multiply
  // by an odd constant, or xor with a right shift of the masked value.
  do {
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
  } while (i >= n);
  // A power-of-two n (the low-discrepancy sampler's counts) needs no division.
  return (n & mask) == 0 ? (i + seed) & mask : (i + seed) % n;
}

}  // namespace columba
