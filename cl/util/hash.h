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
// random permutation of [0, n), found without storing the permutation. A round is a
// bijection of [0, w], w + 1 the power of two at or above n; rounds are applied until the
// value falls in [0, n) (cycle walking), then it is rotated by the key.
RT_DEVICE uint PermutationMask(uint n) {
  uint w = n - 1u;
  w |= w >> 1;
  w |= w >> 2;
  w |= w >> 4;
  w |= w >> 8;
  w |= w >> 16;
  return w;
}

// Always inlined: out of line, the batch's four rounds in PermutationElements cannot be
// vectorized, and GCC's size heuristics move it out of line once the pixel loop grows.
RT_DEVICE_INLINE uint PermutationRound(uint i, uint w, uint key) {
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
  return i;
}

// (i + key) % n for i < n, given key_mod = key % n: a key's remainder is the same for every
// element, and the division after the walk was on the stratum's dependency chain. The sum
// wraps past 2^32 only for keys within n of it (i > ~key), which keep the division.
RT_DEVICE uint PermutationRotate(uint i, uint n, uint key, uint key_mod) {
  if (i > ~key) return (i + key) % n;
  uint t = i + key_mod;
  return t >= n ? t - n : t;
}

// Two rounds are taken before the first test: the walk's exit was a mispredicted branch
// about every other element, and the second round is needed often (n = 9: 7 times in 16).
// Same values as the plain walk (tests/util/permutation_test.cpp). Always inlined in the kernel
// (PoCL kept it out of line: a call per stratified glossy sample and camera stratum).
RT_KERNEL_INLINE uint PermutationElement(uint i, uint n, uint key) {
  uint w = PermutationMask(n);
  uint key_mod = key % n;  // Off the walk's chain: the division overlaps the rounds.
  uint a = PermutationRound(i, w, key);
  uint b = PermutationRound(a, w, key);
  i = a < n ? a : b;
  while (i >= n) i = PermutationRound(i, w, key);
  return PermutationRotate(i, n, key, key_mod);
}

// Elements first .. first + count - 1 (count <= RT_PERMUTATION_BATCH, first + count <= n) of
// the permutation into out[]: the CPU reference's camera batch (cl/integrator/pixel.h). Four rounds
// of RT_PERMUTATION_BATCH elements run as one loop the compiler vectorizes, so no element waits on
// a branch; the few still outside [0, n) after them (n = 9: 2 % of elements) walk on alone. The
// same values as PermutationElement.
#define RT_PERMUTATION_BATCH 8
RT_DEVICE_INLINE void PermutationElements(uint first, int count, uint n, uint key,
                                          RT_PRIVATE uint* out) {
  uint w = PermutationMask(n);
  for (int k = 0; k < RT_PERMUTATION_BATCH; ++k) {
    uint a = PermutationRound(first + (uint)k, w, key);
    uint b = PermutationRound(a, w, key);
    uint c = PermutationRound(b, w, key);
    uint d = PermutationRound(c, w, key);
    out[k] = a < n ? a : b < n ? b : c < n ? c : d;
  }
  uint key_mod = key % n;
  // Only elements of [0, n) may walk on: a cycle of a round through none of them never ends.
  for (int k = 0; k < count; ++k) {
    uint i = out[k];
    while (i >= n) i = PermutationRound(i, w, key);
    out[k] = PermutationRotate(i, n, key, key_mod);
  }
}

#endif  // RT_UTIL_HASH_H
