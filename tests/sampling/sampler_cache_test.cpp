// The camera ray's light sample made with the camera sample (CacheCameraRaySamples in
// cl/sampling/sampler.h) must be the very bits RaySample2D draws without the cache, or the images
// would move.
#include <gtest/gtest.h>

#include "cl/sampling/sampler.h"

namespace {

void ExpectSame(real2 a, real2 b, const char* what, uint pixel, uint sample) {
  EXPECT_EQ(a.x, b.x) << what << " pixel " << pixel << " sample " << sample;
  EXPECT_EQ(a.y, b.y) << what << " pixel " << pixel << " sample " << sample;
}

// Every sample count shape: one sample (one stratum), a square (strata), not a square.
TEST(SamplerCache, CameraRaySamplesAreTheDrawnOnes) {
  const uint counts[][2] = {{1u, 1u}, {4u, 2u}, {7u, 0u}, {100u, 10u}, {400u, 20u}};
  for (const auto& c : counts)
    for (uint seed : {0u, 3u})
      for (uint pixel = 0u; pixel < 40u; ++pixel) {
        PixelKey plain = MakePixelKey(pixel * 7919u, c[0], c[1], seed);
        PixelKey cached = plain;
        CacheCameraRaySamples(&cached, RT_CACHE_LIGHT);
        for (uint s = 0u; s < c[0]; ++s) {
          RaySampler a = MakeRaySampler(PixelSampleKey(plain, s), RT_DIM_FIRST_FREE, 1);
          RaySampler b = MakeRaySampler(PixelSampleKey(cached, s), RT_DIM_FIRST_FREE, 1);
          ASSERT_EQ(b.sk.cached, RT_CACHE_LIGHT);
          ASSERT_EQ(a.sk.cached, 0u);
          real2 want_light = RaySample2D(&a, RT_OFFSET_LIGHT);
          ExpectSame(b.sk.light_u, want_light, "light", pixel, s);
          ExpectSame(RaySample2D(&b, RT_OFFSET_LIGHT), want_light, "light", pixel, s);
          // The glossy sample (0x2000) is not cached: drawn as before.
          ExpectSame(RaySample2D(&b, 0x2000u), RaySample2D(&a, 0x2000u), "glossy", pixel, s);
          // The second light is not cached: drawn as before.
          ExpectSame(RaySample2D(&b, RT_OFFSET_LIGHT + 1u), RaySample2D(&a, RT_OFFSET_LIGHT + 1u),
                     "second light", pixel, s);
        }
      }
}

// The cache holds the camera ray's samples only: a ray of another key, or a secondary ray,
// draws its own numbers from the same sample key.
TEST(SamplerCache, OtherRaysIgnoreTheCache) {
  PixelKey p = MakePixelKey(12345u, 16u, 4u, 0u);
  CacheCameraRaySamples(&p, RT_CACHE_LIGHT);
  SampleKey k = PixelSampleKey(p, 5u);
  RaySampler secondary = MakeRaySampler(k, RT_DIM_FIRST_FREE, 0);
  real2 random = Random2D(k, HashCombine(RT_DIM_FIRST_FREE, RT_OFFSET_LIGHT));
  ExpectSame(RaySample2D(&secondary, RT_OFFSET_LIGHT), random, "secondary", 12345u, 5u);
  EXPECT_NE(random.x, k.light_u.x);
  uint child = HashCombine(RT_DIM_FIRST_FREE, 1u);
  RaySampler other = MakeRaySampler(k, child, 1);
  ExpectSame(RaySample2D(&other, RT_OFFSET_LIGHT),
             Stratified2D(k, HashCombine(child, RT_OFFSET_LIGHT)), "other key", 12345u, 5u);
}

}  // namespace
