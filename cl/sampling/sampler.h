// Counter-based sampling: every number is a hash of (pixel, sample, dimension, seed).
// The first camera dimensions are stratified: sample s of an n x n pattern falls in
// stratum PermutationElement(s), jittered inside it, with a permutation per dimension
// so the pixel, lens, time and light patterns are decorrelated.
// With the Sobol sampler (SampleKey.sobol, RT_FLAG_SOBOL_SAMPLER) every dimension, the camera's
// and each ray's alike, is instead an Owen-scrambled Sobol point of the sample's index
// (cl/sampling/sobol.h), keyed by (pixel, dimension, seed): stratified in every 2D dimension at
// every power-of-two prefix of the samples, still a pure function of the key.
#ifndef RT_SAMPLER_H
#define RT_SAMPLER_H

#include "../util/hash.h"
#include "../util/math.h"
#include "dimensions.h"
#include "sobol.h"

// A bit of PixelKey.cached and SampleKey.cached: the key holds the camera ray's first light
// sample (CacheCameraRaySamples).
#define RT_CACHE_LIGHT 1u

typedef struct SampleKey {
  uint pixel_hash;  // HashUint(pixel), the first round of every key of the pixel.
  uint sample;
  uint samples;  // Samples per pixel.
  uint strata;   // sqrt(samples) when a perfect square, else 0.
  uint seed;
  uint prefix;        // Hash of (pixel, sample, seed): each dimension then costs one round.
  uint strata_magic;  // See StrataMagic.
  uint cached;        // RT_CACHE_* bits (CacheCameraRaySamples).
  // 1: the Sobol sampler; prefix is then the pixel's (SobolPixelPrefix), the same for every
  // sample, and the sample's index picks the point.
  uint sobol;
  real2 light_u;  // The camera ray's first light sample, under RT_CACHE_LIGHT.
} SampleKey;

// The part of the key every sample of a pixel shares, hashed once per pixel: a sample's
// key then costs three rounds instead of four.
typedef struct PixelKey {
  uint samples;
  uint strata;
  uint seed;
  uint hash;  // HashUint(pixel), the first round of every sample's prefix.
  uint strata_magic;
  uint cached;  // RT_CACHE_* bits (CacheCameraRaySamples).
  // The stratum key of the camera ray's light sample: the camera ray's key is the same for
  // every sample of the pixel, so it is a per-pixel constant.
  uint light_strata;
  uint sobol;  // SampleKey.sobol.
} PixelKey;

// The keys of the stratum permutations, Hash4(pixel, dimension, seed, salt): one per pixel
// and dimension, the same for every sample of the pixel (the camera's are computed once
// per pixel, see cl/camera/camera.h).
RT_DEVICE uint StratumKey(uint pixel_hash, uint seed, uint dimension, uint salt) {
  return HashCombine(HashCombine(HashCombine(pixel_hash, dimension), seed), salt);
}

#define RT_STRATA_SALT_2D 0x51ed2701u
#define RT_STRATA_SALT_1D 0x2c1b3c6du

// floor(2^32 / strata) + 1, so a stratum index i < strata^2 divides by strata as
// (i * magic) >> 32 exactly when strata is 2..1024 (Lemire, Kaser and Kurz 2019: exact for
// 32 >= bits(i) + ceil(log2(strata))), saving the camera ray's integer division on every
// light sample; 0 elsewhere, where the division stays.
RT_DEVICE uint StrataMagic(uint strata) {
  return strata >= 2u && strata <= 1024u ? 0xffffffffu / strata + 1u : 0u;
}

RT_DEVICE uint StratumRow(uint stratum, uint strata, uint magic) {
#ifdef __OPENCL_C_VERSION__
  return magic != 0u ? mul_hi(stratum, magic) : stratum / strata;
#else
  return magic != 0u ? (uint)(((std::uint64_t)stratum * magic) >> 32) : stratum / strata;
#endif
}

// A sample's random number of `dimension`, from the sample's prefix (SampleKey.prefix).
RT_DEVICE real RandomOfPrefix(uint prefix, uint dimension) {
  return UintToUnitFloat(HashCombine(prefix, dimension));
}

// The Sobol sampler's number and point of the dimension of key HashCombine(prefix, dimension).
RT_DEVICE real Sobol1D(uint sample, uint key) {
  return UintToUnitFloat(SobolScrambledX(SobolShuffledIndex(sample, key), key));
}

RT_DEVICE real2 Sobol2D(uint sample, uint key) {
  uint index = SobolShuffledIndex(sample, key);
  return make_real2(UintToUnitFloat(SobolScrambledX(index, key)),
                    UintToUnitFloat(SobolScrambledY(index, key)));
}

RT_DEVICE real Random1D(SampleKey k, uint dimension) {
  return k.sobol != 0u ? Sobol1D(k.sample, HashCombine(k.prefix, dimension))
                       : RandomOfPrefix(k.prefix, dimension);
}

RT_DEVICE real2 Random2D(SampleKey k, uint dimension) {
  if (k.sobol != 0u) return Sobol2D(k.sample, HashCombine(k.prefix, dimension));
  return make_real2(RandomOfPrefix(k.prefix, dimension),
                    RandomOfPrefix(k.prefix, RT_DIM_SECOND(dimension)));
}

// One point of a jittered n x n pattern per sample, in [0, 1)^2, its stratum permuted by
// `stratum_key` (StratumKey of the dimension); random when the sample count is not a
// perfect square, or Random2D itself under the Sobol sampler, whose points are stratified
// already. One sample per pixel is one stratum, whose point is xi itself
// ((0 + xi) * 1, exactly), so the permutation is skipped. StratumPoint2D is the point in
// stratum `stratum` (the permutation element, made by the caller: cl/integrator/pixel.h makes a
// batch's film and lens strata at once, PermutationElements). One coordinate of the point of a
// stratum: its column or row `cell` jittered by xi, scaled by inv = 1 / strata. The cell comes as
// an int (a stratum index is below 2^31, so the conversion gives the uint's value): converting a
// signed int is one instruction, and the camera batch's loops (cl/camera/camera_batch.h) stay eight
// lanes wide with it.
RT_DEVICE real StratumCoordinate(int cell, real xi, real inv) { return ((real)cell + xi) * inv; }

// StratumPointOf is StratumPoint2D with the jitter xi = Random2D(k, dimension) given.
RT_DEVICE_INLINE real2 StratumPointOf(SampleKey k, real2 xi, uint stratum) {
  if (k.strata <= 1u || k.sobol != 0u) return xi;
  real inv = 1.0f / (real)k.strata;
  uint row = StratumRow(stratum, k.strata, k.strata_magic);
  return make_real2(StratumCoordinate((int)(stratum - row * k.strata), xi.x, inv),
                    StratumCoordinate((int)row, xi.y, inv));
}

RT_DEVICE_INLINE real2 StratumPoint2D(SampleKey k, uint dimension, uint stratum) {
  return StratumPointOf(k, Random2D(k, dimension), stratum);
}

RT_DEVICE_INLINE real2 Stratified2DKeyed(SampleKey k, uint dimension, uint stratum_key) {
  return StratumPoint2D(
      k, dimension,
      k.strata <= 1u || k.sobol != 0u ? 0u : PermutationElement(k.sample, k.samples, stratum_key));
}

RT_DEVICE real2 Stratified2D(SampleKey k, uint dimension) {
  return k.strata == 0u || k.sobol != 0u
             ? Random2D(k, dimension)
             : Stratified2DKeyed(k, dimension,
                                 StratumKey(k.pixel_hash, k.seed, dimension, RT_STRATA_SALT_2D));
}

// A jittered 1D pattern of `samples` strata (for the shutter time); the Sobol sampler's
// number is stratified already.
RT_DEVICE real Stratified1DKeyed(SampleKey k, uint dimension, uint stratum_key) {
  real xi = Random1D(k, dimension);
  if (k.samples <= 1u || k.sobol != 0u) return xi;
  uint stratum = PermutationElement(k.sample, k.samples, stratum_key);
  return ((real)stratum + xi) / (real)k.samples;
}

RT_DEVICE real Stratified1D(SampleKey k, uint dimension) {
  return k.samples <= 1u || k.sobol != 0u
             ? Random1D(k, dimension)
             : Stratified1DKeyed(k, dimension,
                                 StratumKey(k.pixel_hash, k.seed, dimension, RT_STRATA_SALT_1D));
}

// The dimension of the camera ray's light sample: the camera ray's key is RT_DIM_FIRST_FREE
// (cl/integrator/integrator.h, path.h), so it is a constant.
#define RT_CAMERA_LIGHT_DIM HashCombine(RT_DIM_FIRST_FREE, RT_OFFSET_LIGHT)

RT_DEVICE PixelKey MakePixelKey(uint pixel, uint samples, uint strata, uint seed) {
  PixelKey p;
  p.samples = samples;
  p.strata = strata;
  p.seed = seed;
  p.hash = HashUint(pixel);
  p.strata_magic = StrataMagic(strata);
  p.cached = 0u;
  p.light_strata = 0u;
  p.sobol = 0u;
  return p;
}

// The pixel key of the Sobol sampler (before CacheCameraRaySamples).
RT_DEVICE void UseSobolSampler(RT_PRIVATE PixelKey* p) { p->sobol = 1u; }

// For scenes that draw it: makes every sample of the pixel carry its camera ray's first
// light sample (RT_CACHE_LIGHT). Where RaySample2D drew it, after the camera ray's
// traversal, it was a chain of four hash rounds for the stratum key (a per-pixel constant),
// two for the jitter, the permutation and a division, on the path to the shadow ray; made
// with the camera sample, the CPU's out-of-order window overlaps it with the other samples
// of the batch (cl/integrator/pixel.h). The values are the same bits. Most camera rays of a
// scene with area lights take a light sample; few hit a glossy surface, so the glossy sample
// (RT_DIM_GLOSSY) is not made this way: made for every sample, it would cost more than the
// few rays that draw it save.
RT_DEVICE void CacheCameraRaySamples(RT_PRIVATE PixelKey* p, uint which) {
  p->cached = which;
  if (p->strata > 1u && p->sobol == 0u && (which & RT_CACHE_LIGHT) != 0u)
    p->light_strata = StratumKey(p->hash, p->seed, RT_CAMERA_LIGHT_DIM, RT_STRATA_SALT_2D);
}

// The prefix of sample `sample` of the pixel: Hash4(pixel, sample, seed, 0x3c6ef372u).
RT_DEVICE uint PixelSamplePrefix(PixelKey p, uint sample) {
  return HashCombine(HashCombine(HashCombine(p.hash, sample), p.seed), 0x3c6ef372u);
}

// The Sobol sampler's prefix, Hash3(pixel, seed, 0x9b05688cu): the sample's index, not its
// prefix, tells its samples apart.
RT_DEVICE uint SobolPixelPrefix(PixelKey p) {
  return HashCombine(HashCombine(p.hash, p.seed), 0x9b05688cu);
}

// Sample `sample` of the pixel, whose prefix is PixelSamplePrefix(p, sample) (SobolPixelPrefix
// under the Sobol sampler).
RT_DEVICE SampleKey PixelSampleKeyOf(PixelKey p, uint sample, uint prefix) {
  SampleKey k;
  k.pixel_hash = p.hash;
  k.sample = sample;
  k.samples = p.samples;
  k.strata = p.strata;
  k.seed = p.seed;
  k.prefix = prefix;
  k.strata_magic = p.strata_magic;
  k.cached = p.cached;
  k.sobol = p.sobol;
  k.light_u = make_real2(0.0f, 0.0f);
  // Stratified2DKeyed is Stratified2D with the stratum key given (and Random2D without
  // strata, which leaves the key unread).
  if ((p.cached & RT_CACHE_LIGHT) != 0u)
    k.light_u = Stratified2DKeyed(k, RT_CAMERA_LIGHT_DIM, p.light_strata);
  return k;
}

RT_DEVICE SampleKey PixelSampleKey(PixelKey p, uint sample) {
  return PixelSampleKeyOf(p, sample,
                          p.sobol != 0u ? SobolPixelPrefix(p) : PixelSamplePrefix(p, sample));
}

RT_DEVICE SampleKey MakeSampleKey(uint pixel, uint sample, uint samples, uint strata, uint seed) {
  return PixelSampleKey(MakePixelKey(pixel, samples, strata, seed), sample);
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

// The ray's 2D sample number `offset` (one per light, lobe...): stratified on camera rays,
// whose first light sample the sample key may already hold (CacheCameraRaySamples).
// The sampler comes by pointer: a by-value copy of the struct, stored field by field by the
// caller and reloaded whole, stalled on store-to-load forwarding.
RT_DEVICE real2 RaySample2D(RT_PRIVATE const RaySampler* rs, uint offset) {
  if (rs->primary && rs->key == RT_DIM_FIRST_FREE && offset == RT_OFFSET_LIGHT &&
      (rs->sk.cached & RT_CACHE_LIGHT) != 0u)
    return rs->sk.light_u;
  uint dim = HashCombine(rs->key, offset);
  return rs->primary ? Stratified2D(rs->sk, dim) : Random2D(rs->sk, dim);
}

// The ray's 1D sample number `offset`, never stratified.
RT_DEVICE real RaySample1D(RT_PRIVATE const RaySampler* rs, uint offset) {
  return Random1D(rs->sk, HashCombine(rs->key, offset));
}

#endif  // RT_SAMPLER_H
