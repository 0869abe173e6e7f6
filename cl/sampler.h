// Counter-based sampling: every number is a hash of (pixel, sample, dimension, seed).
// The first camera dimensions are stratified: sample s of an n x n pattern falls in
// stratum PermutationElement(s), jittered inside it, with a permutation per dimension
// so the pixel, lens, time and light patterns are decorrelated.
#ifndef RT_SAMPLER_H
#define RT_SAMPLER_H

#include "util/hash.h"
#include "util/math.h"

// Dimensions of the camera sample, in the order the course names them.
#define RT_DIM_PIXEL 0
#define RT_DIM_LENS 2
#define RT_DIM_TIME 4
// Later dimensions are keyed by the ray's place in the ray tree (see RaySampler).
#define RT_DIM_FIRST_FREE 5

typedef struct SampleKey {
  uint pixel;
  uint sample;
  uint samples;  // Samples per pixel.
  uint strata;   // sqrt(samples) when a perfect square, else 0.
  uint seed;
  uint prefix;  // Hash of (pixel, sample, seed): each dimension then costs one round.
} SampleKey;

RT_DEVICE SampleKey MakeSampleKey(uint pixel, uint sample, uint samples, uint strata, uint seed) {
  SampleKey k;
  k.pixel = pixel;
  k.sample = sample;
  k.samples = samples;
  k.strata = strata;
  k.seed = seed;
  k.prefix = Hash4(pixel, sample, seed, 0x3c6ef372u);
  return k;
}

RT_DEVICE real Random1D(SampleKey k, uint dimension) {
  return UintToUnitFloat(HashCombine(k.prefix, dimension));
}

RT_DEVICE real2 Random2D(SampleKey k, uint dimension) {
  return make_real2(Random1D(k, dimension), Random1D(k, dimension ^ 0x68bc21ebu));
}

// One point of a jittered n x n pattern per sample, in [0, 1)^2; random when the sample
// count is not a perfect square.
RT_DEVICE real2 Stratified2D(SampleKey k, uint dimension) {
  real2 xi = Random2D(k, dimension);
  if (k.strata == 0u) return xi;
  uint key = Hash4(k.pixel, dimension, k.seed, 0x51ed2701u);
  uint stratum = PermutationElement(k.sample, k.samples, key);
  real inv = 1.0f / (real)k.strata;
  return make_real2(((real)(stratum % k.strata) + xi.x) * inv,
                    ((real)(stratum / k.strata) + xi.y) * inv);
}

// A jittered 1D pattern of `samples` strata (for the shutter time).
RT_DEVICE real Stratified1D(SampleKey k, uint dimension) {
  real xi = Random1D(k, dimension);
  if (k.samples <= 1u) return xi;
  uint key = Hash4(k.pixel, dimension, k.seed, 0x2c1b3c6du);
  uint stratum = PermutationElement(k.sample, k.samples, key);
  return ((real)stratum + xi) / (real)k.samples;
}

// The random numbers of one ray of the ray tree: its pixel sample, its key in the tree
// (cl/integrator/ray_tree.h), and whether it is a camera ray, whose first bounce draws
// stratified samples.
typedef struct RaySampler {
  SampleKey sk;
  uint key;
  int primary;
} RaySampler;

RT_DEVICE RaySampler MakeRaySampler(SampleKey sk, uint key, int primary) {
  RaySampler rs;
  rs.sk = sk;
  rs.key = key;
  rs.primary = primary;
  return rs;
}

// The ray's 2D sample number `offset` (one per light, lobe...): stratified on camera rays.
RT_DEVICE real2 RaySample2D(RaySampler rs, uint offset) {
  uint dim = HashCombine(rs.key, offset);
  return rs.primary ? Stratified2D(rs.sk, dim) : Random2D(rs.sk, dim);
}

// The ray's 1D sample number `offset`, never stratified.
RT_DEVICE real RaySample1D(RaySampler rs, uint offset) {
  return Random1D(rs.sk, HashCombine(rs.key, offset));
}

#endif  // RT_SAMPLER_H
