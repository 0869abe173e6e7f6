// The counter-based sampler: reproducibility, stratification and uniformity.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <numeric>
#include <random>
#include <set>
#include <vector>

#include "cl/sampling/sampler.h"

namespace {

SampleKey Key(uint pixel, uint sample, uint samples, uint seed = 0) {
  uint root = static_cast<uint>(std::lround(std::sqrt(static_cast<double>(samples))));
  return MakeSampleKey(pixel, sample, samples, root * root == samples ? root : 0u, seed);
}

// Upper critical value of chi-square with `df` degrees of freedom at significance 1e-3
// (Wilson-Hilferty approximation; accurate to a few percent for df >= 10).
double ChiSquareCritical(int df) {
  const double z = 3.0902;  // Standard normal quantile at 1 - 1e-3.
  double h = 2.0 / (9.0 * df);
  return df * std::pow(1 - h + z * std::sqrt(h), 3);
}

// One sample per pixel is one stratum: Stratified2D returns the jitter without permuting,
// which must be what the n x n formula gives for n = 1 (stratum 0, (0 + xi) * 1), bit for
// bit, so skipping the permutation changed no image.
TEST(Sampler, OneStratumIsTheJitterItself) {
  for (uint p = 0; p < 2000; ++p)
    for (uint d : {0u, 2u, 5u, 0x9e3779b9u}) {
      SampleKey k = Key(p, 0, 1, p % 3);
      ASSERT_EQ(k.strata, 1u);
      uint key = StratumKey(k.pixel_hash, k.seed, d, RT_STRATA_SALT_2D);
      uint stratum = PermutationElement(0, 1, key);
      ASSERT_EQ(stratum, 0u);
      real2 xi = Random2D(k, d);
      real inv = 1.0f / (real)k.strata;
      real2 formula =
          make_real2(((real)(stratum % 1u) + xi.x) * inv, ((real)(stratum / 1u) + xi.y) * inv);
      real2 got = Stratified2D(k, d);
      ASSERT_EQ(got.x, formula.x);
      ASSERT_EQ(got.y, formula.y);
    }
}

// The keys hashed once per pixel (PixelKey, StratumKey) are the same Hash4 values as the
// keys of every random number before that split, so images did not change with it.
TEST(Sampler, PixelKeysAreTheHashesOfTheirCoordinates) {
  for (uint p : {0u, 1u, 12345u, 0xffffffffu})
    for (uint seed : {0u, 7u})
      for (uint s : {0u, 3u, 63u}) {
        PixelKey pk = MakePixelKey(p, 64, 8, seed);
        EXPECT_EQ(PixelSampleKey(pk, s).prefix, Hash4(p, s, seed, 0x3c6ef372u));
        for (uint d : {0u, 2u, 4u, 0x9e3779b9u}) {
          EXPECT_EQ(StratumKey(pk.hash, seed, d, RT_STRATA_SALT_2D),
                    Hash4(p, d, seed, 0x51ed2701u));
          EXPECT_EQ(StratumKey(pk.hash, seed, d, RT_STRATA_SALT_1D),
                    Hash4(p, d, seed, 0x2c1b3c6du));
        }
      }
}

TEST(Sampler, SameKeySameValueWhateverTheOrder) {
  std::vector<uint> dims = {0, 1, 2, 3, 4, 77, 1u << 31};
  std::vector<float> first;
  for (uint p = 0; p < 50; ++p)
    for (uint s = 0; s < 16; ++s)
      for (uint d : dims) first.push_back(Random1D(Key(p, s, 16), d));
  std::vector<size_t> order(first.size());
  std::iota(order.begin(), order.end(), 0);
  std::shuffle(order.begin(), order.end(), std::mt19937(7));
  for (size_t i : order) {
    uint d = dims[i % dims.size()];
    uint s = (i / dims.size()) % 16, p = static_cast<uint>(i / (dims.size() * 16));
    ASSERT_EQ(Random1D(Key(p, s, 16), d), first[i]);
  }
}

TEST(Sampler, SeedChangesTheStream) {
  int equal = 0;
  for (uint p = 0; p < 1000; ++p)
    equal += Random1D(Key(p, 0, 1, 0), 5) == Random1D(Key(p, 0, 1, 1), 5);
  EXPECT_LE(equal, 2);  // 24-bit values: a chance collision is about 1000 / 2^24.
}

TEST(Sampler, ValuesLieInUnitInterval) {
  for (uint p = 0; p < 20000; ++p) {
    float u = Random1D(Key(p, p % 7, 16), p % 13);
    ASSERT_GE(u, 0.0f);
    ASSERT_LT(u, 1.0f);
  }
  EXPECT_EQ(UintToUnitFloat(0xffffffffu) < 1.0f, true);
}

TEST(Sampler, JitteredPatternPutsOneSampleInEachStratum) {
  for (uint n : {2u, 3u, 4u, 10u, 20u, 30u}) {
    uint samples = n * n;
    for (uint pixel : {0u, 1u, 12345u})
      for (uint dim : {static_cast<uint>(RT_DIM_PIXEL), static_cast<uint>(RT_DIM_LENS), 999u}) {
        std::set<std::pair<int, int>> strata;
        for (uint s = 0; s < samples; ++s) {
          float2 u = Stratified2D(Key(pixel, s, samples), dim);
          strata.insert({static_cast<int>(u.x * n), static_cast<int>(u.y * n)});
        }
        ASSERT_EQ(strata.size(), samples) << "n=" << n << " pixel=" << pixel << " dim=" << dim;
      }
  }
}

TEST(Sampler, TimePatternPutsOneSampleInEachInterval) {
  for (uint samples : {1u, 7u, 16u, 100u, 900u}) {
    std::set<int> bins;
    for (uint s = 0; s < samples; ++s)
      bins.insert(static_cast<int>(Stratified1D(Key(42, s, samples), RT_DIM_TIME) * samples));
    ASSERT_EQ(bins.size(), samples);
  }
}

// Chi-square tests of uniformity at significance 1e-3 over 10 x 10 bins: a correct sampler
// fails each with probability 0.001.
void ExpectUniform2D(bool stratified, uint dim, uint samples) {
  const int bins = 10;
  std::vector<int> count(bins * bins, 0);
  int total = 0;
  for (uint p = 0; p < 4000; ++p)
    for (uint s = 0; s < samples; ++s) {
      SampleKey k = Key(p, s, samples);
      float2 u = stratified ? Stratified2D(k, dim) : Random2D(k, dim);
      ++count[static_cast<int>(u.y * bins) * bins + static_cast<int>(u.x * bins)];
      ++total;
    }
  double expected = static_cast<double>(total) / count.size(), chi2 = 0;
  for (int c : count) chi2 += (c - expected) * (c - expected) / expected;
  EXPECT_LT(chi2, ChiSquareCritical(bins * bins - 1)) << "dimension " << dim;
}

TEST(Sampler, LensSamplesAreUniform) { ExpectUniform2D(true, RT_DIM_LENS, 9); }
TEST(Sampler, LightSamplesAreUniform) {
  ExpectUniform2D(true, HashCombine(RT_DIM_FIRST_FREE, 0x1000u), 16);
  ExpectUniform2D(false, HashCombine(HashCombine(RT_DIM_FIRST_FREE, 1u), 0x1000u), 4);
}
TEST(Sampler, NonSquareCountsFallBackToRandom) { ExpectUniform2D(true, RT_DIM_PIXEL, 5); }

TEST(Sampler, TimeSamplesAreUniform) {
  const int bins = 50;
  std::vector<int> count(bins, 0);
  int total = 0;
  for (uint p = 0; p < 20000; ++p)
    for (uint s = 0; s < 3; ++s, ++total)
      ++count[static_cast<int>(Stratified1D(Key(p, s, 3), RT_DIM_TIME) * bins)];
  double expected = static_cast<double>(total) / bins, chi2 = 0;
  for (int c : count) chi2 += (c - expected) * (c - expected) / expected;
  EXPECT_LT(chi2, ChiSquareCritical(bins - 1));
}

TEST(Sampler, PermutationIsABijection) {
  for (uint n : {1u, 2u, 5u, 16u, 100u, 1000u}) {
    std::vector<bool> seen(n, false);
    for (uint i = 0; i < n; ++i) {
      uint e = PermutationElement(i, n, 0xdeadbeefu + n);
      ASSERT_LT(e, n);
      ASSERT_FALSE(seen[e]);
      seen[e] = true;
    }
  }
}

}  // namespace
