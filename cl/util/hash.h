// Stateless integer hashing. Random numbers are a pure function of
// (pixel, sample, dimension, seed), so both devices draw identical values in any thread
// order and any run can be reproduced.
#ifndef RT_UTIL_HASH_H
#define RT_UTIL_HASH_H

#include "../compat.h"

// PCG's output permutation applied to one state step (Jarzynski & Olano 2020, "pcg").
RT_DEVICE uint HashUint(uint v) {
  uint state = v * 747796405u + 2891336453u;
  uint word = ((state >> ((state >> 28u) + 4u)) ^ state) * 277803737u;
  return (word >> 22u) ^ word;
}

// Order-dependent combination, so (a, b) and (b, a) give different keys.
RT_DEVICE uint HashCombine(uint seed, uint v) {
  return HashUint(seed ^ (v + 0x9e3779b9u + (seed << 6) + (seed >> 2)));
}

RT_DEVICE uint Hash4(uint a, uint b, uint c, uint d) {
  return HashCombine(HashCombine(HashCombine(HashUint(a), b), c), d);
}

// Maps 32 random bits to [0, 1) with 24 bits of precision; exact in float on both devices.
RT_DEVICE float UintToUnitFloat(uint bits) { return (float)(bits >> 8) * (1.0f / 16777216.0f); }

// The permutation of Kensler ("Correlated Multi-Jittered Sampling", 2013): element i of a
// random permutation of [0, n), found without storing the permutation.
RT_DEVICE uint PermutationElement(uint i, uint n, uint key) {
  uint w = n - 1u;
  w |= w >> 1;
  w |= w >> 2;
  w |= w >> 4;
  w |= w >> 8;
  w |= w >> 16;
  do {
    i ^= key;
    i *= 0xe170893du;
    i ^= key >> 16;
    i ^= (i & w) >> 4;
    i ^= key >> 8;
    i *= 0x0929eb3fu;
    i ^= key >> 23;
    i ^= (i & w) >> 1;
    i *= 1u | key >> 27;
    i *= 0x6935fa69u;
    i ^= (i & w) >> 11;
    i *= 0x74dcb303u;
    i ^= (i & w) >> 2;
    i *= 0x9e501cc3u;
    i ^= (i & w) >> 2;
    i *= 0xc860a3dfu;
    i &= w;
    i ^= i >> 5;
  } while (i >= n);
  return (i + key) % n;
}

#endif  // RT_UTIL_HASH_H
