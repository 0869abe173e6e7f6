// Owen-scrambled Sobol points, hashed per dimension (Burley 2020, "Practical Hash-based Owen
// Scrambling", JCGT 9(4); pbrt-v4's PaddedSobolSampler). Each 1D or 2D dimension of a pixel has
// its own key; the sample index is shuffled by a nested uniform scramble of the key, the point
// is the first one or two Sobol dimensions of the shuffled index, and each coordinate is Owen
// scrambled by a key of its own. Sobol's first two dimensions are a (0,2)-sequence in base 2:
// every aligned block of 2^k indices is a (0,k,2)-net, one point in each elementary interval
// of volume 2^-k. The shuffle maps samples [0, 2^k) onto one such block and an Owen scramble
// keeps a net a net, so any 2^k first samples of a pixel are stratified on every 2D dimension,
// at any sample count, while distinct keys stay decorrelated. Pure functions of
// (sample, key), integer only, as the rest of the sampler.
#ifndef RT_SAMPLING_SOBOL_H
#define RT_SAMPLING_SOBOL_H

#include "../util/hash.h"

RT_DEVICE uint ReverseBits(uint v) {
  v = ((v >> 1) & 0x55555555u) | ((v & 0x55555555u) << 1);
  v = ((v >> 2) & 0x33333333u) | ((v & 0x33333333u) << 2);
  v = ((v >> 4) & 0x0f0f0f0fu) | ((v & 0x0f0f0f0fu) << 4);
  v = ((v >> 8) & 0x00ff00ffu) | ((v & 0x00ff00ffu) << 8);
  return (v >> 16) | (v << 16);
}

// A Laine-Karras style permutation of 32 bits: bit j of the result depends on bits 0..j of v
// only (a sum or product carries upward; v ^= v * even flips bit j by bits below it), and each
// step is a bijection. On a bit-reversed value (bit 0 the most significant digit) that is an
// Owen scramble: each digit is flipped by a hash of the digits above it. The constants are
// Vegdahl's improvement of Laine and Karras's, as pbrt-v4's FastOwenScrambler.
RT_DEVICE uint OwenPermutation(uint v, uint key) {
  v ^= v * 0x3d20adeau;
  v += key;
  v *= (key >> 16) | 1u;
  v ^= v * 0x05526c56u;
  v ^= v * 0x53a22864u;
  return v;
}

// The Owen scramble of a 32-bit fraction x (bit 31 the first binary digit).
RT_DEVICE uint NestedUniformScramble(uint x, uint key) {
  return ReverseBits(OwenPermutation(ReverseBits(x), key));
}

// Sobol's first dimension, van der Corput's radical inverse: the index's bits reversed.
RT_DEVICE uint SobolFirst(uint index) { return ReverseBits(index); }

// Sobol's second dimension with its bits reversed: the XOR of the direction numbers of the
// index's set bits, direction k being row k of Pascal's triangle mod 2 (primitive polynomial
// x + 1), reversed: w_0 = 1, w_k = w_(k-1) ^ (w_(k-1) << 1). By Lucas's theorem bit j of w_k is
// set exactly when the bits of j are among those of k, so bit j of the sum is the parity of
// the index's bits k that are supersets of j: five steps of a superset transform over the bit
// positions, each folding the positions with one position bit set onto those without it (the
// same values as the 32-step sum, tests/sampling/sobol_test.cpp).
RT_DEVICE uint SobolSecondReversed(uint index) {
  uint r = index;
  r ^= (r >> 1) & 0x55555555u;
  r ^= (r >> 2) & 0x33333333u;
  r ^= (r >> 4) & 0x0f0f0f0fu;
  r ^= (r >> 8) & 0x00ff00ffu;
  return r ^ (r >> 16);
}

RT_DEVICE uint SobolSecond(uint index) { return ReverseBits(SobolSecondReversed(index)); }

// The keys of a dimension: the index shuffle's is the dimension's key itself, each
// coordinate's scramble a hash of it.
#define RT_SOBOL_SALT_X 0x6a09e667u
#define RT_SOBOL_SALT_Y 0xbb67ae85u

// Sample `sample` of the dimension of key `key`, its index shuffled: samples [0, 2^k) go to
// one aligned block of 2^k indices (bits k and up are flipped by the key alone).
RT_DEVICE uint SobolShuffledIndex(uint sample, uint key) {
  return NestedUniformScramble(sample, key);
}

// The coordinates of the scrambled point, as 32-bit fractions. The scramble of the first
// dimension, reversed twice, is one Owen permutation of the index itself.
RT_DEVICE uint SobolScrambledX(uint index, uint key) {
  return ReverseBits(OwenPermutation(index, HashCombine(key, RT_SOBOL_SALT_X)));
}

RT_DEVICE uint SobolScrambledY(uint index, uint key) {
  return ReverseBits(
      OwenPermutation(SobolSecondReversed(index), HashCombine(key, RT_SOBOL_SALT_Y)));
}

#endif  // RT_SAMPLING_SOBOL_H
