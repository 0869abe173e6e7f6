// The Owen-scrambled Sobol sampler (cl/sampling/sobol.h, --sampler sobol): the exact net
// properties of the sequence and of its scramble, the index shuffle, the sampler's interface
// in Sobol mode, and its integration error against the independent sampler.
#include <gtest/gtest.h>

#include <cmath>
#include <cstdint>
#include <cstdio>
#include <set>
#include <vector>

#include "cl/sampling/sampler.h"

namespace {

const uint kKeys[] = {0u, 1u, 0xdeadbeefu, 0x12345678u, 0x9e3779b9u, 0xffffffffu, 77u, 0x80000000u};

// Whether the 2^k points (x[i], y[i]) (32-bit fractions) are a (0,k,2)-net in base 2: each
// elementary interval of 2^a by 2^(k-a) cells holds exactly one point, for every a.
::testing::AssertionResult IsNet(const std::vector<uint>& x, const std::vector<uint>& y, int k) {
  for (int a = 0; a <= k; ++a) {
    std::vector<int> count(size_t{1} << k, 0);
    for (size_t i = 0; i < x.size(); ++i) {
      uint64_t cx = static_cast<uint64_t>(x[i]) >> (32 - a);
      uint64_t cy = static_cast<uint64_t>(y[i]) >> (32 - (k - a));
      if (++count[cy << a | cx] > 1)
        return ::testing::AssertionFailure()
               << "k = " << k << ", intervals 2^-" << a << " x 2^-" << (k - a) << ": cell (" << cx
               << ", " << cy << ") holds two points";
    }
  }
  return ::testing::AssertionSuccess();
}

// The 32-bit fraction of a sampler value, exact for the 24 bits UintToUnitFloat keeps.
uint Bits(float u) { return static_cast<uint>(std::ldexp(static_cast<double>(u), 32)); }

PixelKey SobolPixel(uint pixel, uint samples, uint seed) {
  uint root = static_cast<uint>(std::lround(std::sqrt(static_cast<double>(samples))));
  PixelKey p = MakePixelKey(pixel, samples, root * root == samples ? root : 0u, seed);
  UseSobolSampler(&p);
  return p;
}

TEST(Sobol, FirstPointsAreSobolsFirstTwoDimensions) {
  // Van der Corput and the second dimension (direction numbers 1, 3, 5, 15, ... / 2^j).
  const double first[8] = {0, 0.5, 0.25, 0.75, 0.125, 0.625, 0.375, 0.875};
  const double second[8] = {0, 0.5, 0.75, 0.25, 0.625, 0.125, 0.375, 0.875};
  for (uint i = 0; i < 8; ++i) {
    EXPECT_EQ(SobolFirst(i), static_cast<uint>(first[i] * 4294967296.0)) << i;
    EXPECT_EQ(SobolSecond(i), static_cast<uint>(second[i] * 4294967296.0)) << i;
  }
  // Direction j is row j of Pascal's triangle mod 2: row 16 is 1 at 0 and 16 only, every
  // binomial of row 31 = 2^5 - 1 is odd.
  EXPECT_EQ(SobolSecond(1u << 16), 0x80008000u);
  EXPECT_EQ(SobolSecond(1u << 31), 0xffffffffu);
  EXPECT_EQ(ReverseBits(0x00000001u), 0x80000000u);
  EXPECT_EQ(ReverseBits(0x12345678u), 0x1e6a2c48u);
}

// SobolSecondReversed's five folds against the plain sum of the direction numbers,
// w_0 = 1, w_k = w_(k-1) ^ (w_(k-1) << 1), over every bit alone and a spread of indices.
TEST(Sobol, SecondDimensionIsTheSumOfItsDirectionNumbers) {
  auto plain = [](uint index) {
    uint r = 0u, w = 1u;
    for (int k = 0; k < 32; ++k, w ^= w << 1)
      if ((index >> k) & 1u) r ^= w;
    return r;
  };
  for (int k = 0; k < 32; ++k) ASSERT_EQ(SobolSecondReversed(1u << k), plain(1u << k)) << k;
  for (uint i = 0, x = 12345u; i < 100000; ++i, x = HashUint(x))
    ASSERT_EQ(SobolSecondReversed(x), plain(x)) << x;
  for (uint i = 0; i < 4096; ++i) ASSERT_EQ(SobolSecondReversed(i), plain(i)) << i;
}

TEST(Sobol, UnscrambledBlocksAreNets) {
  for (int k = 0; k <= 10; ++k)
    for (uint block : {0u, 1u, 5u, 1000u}) {
      std::vector<uint> x, y;
      for (uint i = 0; i < (1u << k); ++i) {
        x.push_back(SobolFirst((block << k) + i));
        y.push_back(SobolSecond((block << k) + i));
      }
      EXPECT_TRUE(IsNet(x, y, k)) << "block " << block;
    }
}

// Samples [0, 2^k) go to one aligned block of 2^k indices: a permutation of the block, whose
// place the key alone decides.
TEST(Sobol, ShuffleMapsEachPrefixOntoOneBlock) {
  for (uint key : kKeys)
    for (int k = 0; k <= 10; ++k) {
      std::set<uint> low;
      uint block = SobolShuffledIndex(0u, key) >> k;
      for (uint i = 0; i < (1u << k); ++i) {
        uint s = SobolShuffledIndex(i, key);
        ASSERT_EQ(s >> k, block) << "key " << key << ", k " << k << ", sample " << i;
        low.insert(s & ((1u << k) - 1u));
      }
      EXPECT_EQ(low.size(), size_t{1} << k) << "key " << key << ", k " << k;
    }
  // Different keys shuffle differently.
  EXPECT_NE(SobolShuffledIndex(1u, kKeys[2]), SobolShuffledIndex(1u, kKeys[3]));
}

TEST(Sobol, ScrambledPrefixesAreNets) {
  for (uint key : kKeys)
    for (int k = 0; k <= 10; ++k) {
      std::vector<uint> x, y;
      for (uint i = 0; i < (1u << k); ++i) {
        uint index = SobolShuffledIndex(i, key);
        x.push_back(SobolScrambledX(index, key));
        y.push_back(SobolScrambledY(index, key));
      }
      EXPECT_TRUE(IsNet(x, y, k)) << "key " << key;
    }
}

// Through the sampler: every 2D dimension of a pixel, camera or ray, is a net at each
// power-of-two prefix, and every 1D one holds one number per interval of 2^-k.
TEST(Sobol, SamplerDimensionsAreStratifiedAtEveryPowerOfTwo) {
  const uint dims[] = {RT_DIM_PIXEL, RT_DIM_LENS, HashCombine(RT_DIM_FIRST_FREE, RT_OFFSET_LIGHT),
                       HashCombine(HashCombine(RT_DIM_FIRST_FREE, 77u), RT_DIM_BSDF_DIRECTION)};
  for (uint pixel : {0u, 3u, 4096u})
    for (int k = 0; k <= 10; ++k) {
      PixelKey p = SobolPixel(pixel, 1u << k, 7u);
      for (uint d : dims) {
        std::vector<uint> x, y;
        std::set<uint> one;
        for (uint s = 0; s < (1u << k); ++s) {
          SampleKey sk = PixelSampleKey(p, s);
          real2 u = Random2D(sk, d);
          ASSERT_EQ(Stratified2D(sk, d).x, u.x);
          ASSERT_EQ(Stratified2D(sk, d).y, u.y);
          x.push_back(Bits(u.x));
          y.push_back(Bits(u.y));
          one.insert(static_cast<uint>(static_cast<uint64_t>(Bits(Random1D(sk, d))) >> (32 - k)));
        }
        EXPECT_TRUE(IsNet(x, y, k)) << "pixel " << pixel << ", dimension " << d;
        EXPECT_EQ(one.size(), size_t{1} << k) << "pixel " << pixel << ", dimension " << d;
      }
    }
}

TEST(Sobol, ValuesLieInTheUnitInterval) {
  for (uint pixel = 0; pixel < 64; ++pixel) {
    PixelKey p = SobolPixel(pixel * 7919u, 100u, pixel % 3u);
    for (uint s = 0; s < 100; ++s) {
      SampleKey sk = PixelSampleKey(p, s);
      for (uint d = 0; d < 8; ++d) {
        real2 u = Random2D(sk, d);
        real v = Random1D(sk, d);
        ASSERT_TRUE(u.x >= 0 && u.x < 1 && u.y >= 0 && u.y < 1 && v >= 0 && v < 1);
      }
    }
  }
  EXPECT_LT(UintToUnitFloat(0xffffffffu), 1.0f);
}

// The camera ray's light sample the key carries (CacheCameraRaySamples) is the one
// RaySample2D draws, and Sobol mode changes every number of the sample.
TEST(Sobol, CachedLightSampleIsTheDrawnOne) {
  for (uint pixel : {1u, 99u}) {
    PixelKey p = SobolPixel(pixel, 16u, 3u);
    PixelKey cached = p;
    CacheCameraRaySamples(&cached, RT_CACHE_LIGHT);
    PixelKey independent = MakePixelKey(pixel, 16u, 4u, 3u);
    for (uint s = 0; s < 16; ++s) {
      RaySampler a = MakeRaySampler(PixelSampleKey(p, s), RT_DIM_FIRST_FREE, 1);
      RaySampler b = MakeRaySampler(PixelSampleKey(cached, s), RT_DIM_FIRST_FREE, 1);
      RaySampler c = MakeRaySampler(PixelSampleKey(independent, s), RT_DIM_FIRST_FREE, 1);
      real2 want = RaySample2D(&a, RT_OFFSET_LIGHT);
      EXPECT_EQ(RaySample2D(&b, RT_OFFSET_LIGHT).x, want.x);
      EXPECT_EQ(RaySample2D(&b, RT_OFFSET_LIGHT).y, want.y);
      EXPECT_NE(RaySample2D(&c, RT_OFFSET_LIGHT).x, want.x);
      EXPECT_NE(RaySample1D(&c, RT_DIM_RUSSIAN_ROULETTE), RaySample1D(&a, RT_DIM_RUSSIAN_ROULETTE));
    }
  }
}

// Two dimensions of a pixel are scrambled apart: over 64 pixels x 256 samples the
// correlation of two 1D dimensions, and of a 2D dimension's coordinates, is within 5 / sqrt(N)
// (5 sigma for independent uniforms; 1 in 3.5 million to fail by chance).
TEST(Sobol, DimensionsAreUncorrelated) {
  const uint pairs[][2] = {{RT_DIM_PIXEL, RT_DIM_LENS},
                           {RT_DIM_TIME, RT_DIM_FIRST_FREE},
                           {HashCombine(5u, 1u), HashCombine(5u, 2u)}};
  for (const auto& d : pairs) {
    double sxy = 0, sx = 0, sy = 0, sxx = 0, syy = 0, n = 0;
    double cxy = 0;
    for (uint pixel = 0; pixel < 64; ++pixel) {
      PixelKey p = SobolPixel(pixel, 256u, 0u);
      for (uint s = 0; s < 256; ++s) {
        SampleKey sk = PixelSampleKey(p, s);
        double x = Random1D(sk, d[0]) - 0.5, y = Random1D(sk, d[1]) - 0.5;
        real2 u = Random2D(sk, d[0]);
        sxy += x * y, sx += x, sy += y, sxx += x * x, syy += y * y, n += 1;
        cxy += (u.x - 0.5) * (u.y - 0.5);
      }
    }
    double r = (sxy / n - sx / n * sy / n) /
               std::sqrt((sxx / n - sx * sx / n / n) * (syy / n - sy * sy / n / n));
    EXPECT_LT(std::fabs(r), 5.0 / std::sqrt(n)) << d[0] << ", " << d[1];
    EXPECT_LT(std::fabs(cxy / n * 12.0), 5.0 / std::sqrt(n)) << d[0];
  }
}

// A Gaussian bump on [0,1)^2, sigma 0.15, and its exact integral.
double Bump(double x, double y) {
  const double s = 0.15;
  return std::exp(-((x - 0.5) * (x - 0.5) + (y - 0.5) * (y - 0.5)) / (2 * s * s));
}
double BumpIntegral() {
  const double s = 0.15, pi = 3.14159265358979323846;
  double one = s * std::sqrt(2 * pi) * std::erf(0.5 / (s * std::sqrt(2.0)));
  return one * one;
}

// 256 samples over 64 pixels: the Sobol sampler's RMSE is at least 4 times below the
// independent sampler's (Owen-scrambled nets converge as N^-1.5 on smooth integrands, the
// independent sampler as N^-0.5: about 16 times here), and its mean over the pixels lies within
// 4 standard errors of the exact integral (unbiased; 1 in 15,000 to fail by chance).
TEST(Sobol, IntegratesASmoothBumpFarBetterThanIndependentSamples) {
  const double exact = BumpIntegral();
  const uint dim = HashCombine(RT_DIM_FIRST_FREE, RT_OFFSET_LIGHT);
  double sobol_se = 0, independent_se = 0, sobol_sum = 0;
  const int pixels = 64, n = 256;
  for (int pixel = 0; pixel < pixels; ++pixel) {
    PixelKey sobol = SobolPixel(static_cast<uint>(pixel) * 31u + 5u, n, 1u);
    PixelKey independent = MakePixelKey(static_cast<uint>(pixel) * 31u + 5u, n, 16u, 1u);
    double a = 0, b = 0;
    for (int s = 0; s < n; ++s) {
      real2 u = Random2D(PixelSampleKey(sobol, static_cast<uint>(s)), dim);
      real2 v = Random2D(PixelSampleKey(independent, static_cast<uint>(s)), dim);
      a += Bump(u.x, u.y);
      b += Bump(v.x, v.y);
    }
    a /= n, b /= n;
    sobol_sum += a;
    sobol_se += (a - exact) * (a - exact);
    independent_se += (b - exact) * (b - exact);
  }
  double sobol_rmse = std::sqrt(sobol_se / pixels);
  double independent_rmse = std::sqrt(independent_se / pixels);
  std::printf("[ bump, 256 samples, 64 pixels ] RMSE sobol %.3g, independent %.3g\n", sobol_rmse,
              independent_rmse);
  EXPECT_LT(sobol_rmse * 4, independent_rmse) << sobol_rmse << " vs " << independent_rmse;
  double mean = sobol_sum / pixels;
  EXPECT_LT(std::fabs(mean - exact), 4 * sobol_rmse / std::sqrt(static_cast<double>(pixels)))
      << "mean " << mean << ", exact " << exact;
}

}  // namespace
