// Whole-render properties of the CPU reference: the image does not depend on the thread
// count, and equal seeds give equal images.
#include <gtest/gtest.h>

#include <cstring>

#include "prepare/flat_scene.h"
#include "support/device_harness.h"

namespace {

rt::RenderResult RenderExample(int threads, uint32_t seed) {
  rt::SceneDesc scene = rt::load_scene(RT_SOURCE_DIR "/scenes/example.xml");
  scene.cameras[0].width = 64;
  scene.cameras[0].height = 48;
  rt::RenderOptions opt;
  opt.seed = seed;
  opt.spp = 4;
  rt::FlatScene flat = rt::prepare_scene(scene, opt);
  rt::prepare_camera(flat, scene, 0, opt);
  return rt::test::render_cpu(flat, threads);
}

bool BitIdentical(const rt::RenderResult& a, const rt::RenderResult& b) {
  return a.accum.size() == b.accum.size() &&
         std::memcmp(a.accum.data(), b.accum.data(), a.accum.size() * sizeof(PixelAccum)) == 0;
}

TEST(Render, ImageIsBitIdenticalWhateverTheThreadCount) {
  rt::RenderResult one = RenderExample(1, 0);
  EXPECT_TRUE(BitIdentical(one, RenderExample(2, 0)));
  EXPECT_TRUE(BitIdentical(one, RenderExample(7, 0)));
}

TEST(Render, SeedSelectsTheRandomStream) {
  rt::RenderResult a = RenderExample(2, 1);
  EXPECT_TRUE(BitIdentical(a, RenderExample(2, 1)));
  rt::RenderResult b = RenderExample(2, 2);
  size_t differing = 0;
  for (size_t i = 0; i < a.accum.size(); ++i)
    differing += std::memcmp(&a.accum[i].sum, &b.accum[i].sum, sizeof(float4)) != 0;
  // The area light, lens, glossy lobe and time make nearly every pixel seed-dependent.
  EXPECT_GT(differing, a.accum.size() / 2);
}

}  // namespace

namespace {

rt::RenderResult RenderAreaWithStop(const rt::StopRule& stop, int spp) {
  rt::SceneDesc scene = rt::load_scene(RT_SOURCE_DIR "/scenes/example.xml");
  scene.cameras[0].width = 48;
  scene.cameras[0].height = 36;
  rt::RenderOptions opt;
  opt.spp = spp;
  rt::FlatScene flat = rt::prepare_scene(scene, opt);
  rt::prepare_camera(flat, scene, 0, opt);
  return rt::test::render_cpu(flat, 2, stop);
}

TEST(Render, NoiseTargetStopsEarlyWithEqualSampleCounts) {
  rt::StopRule stop;
  stop.noise_target = 0.05;
  rt::RenderResult r = RenderAreaWithStop(stop, 4096);
  EXPECT_LT(r.spp, 4096);
  EXPECT_EQ(rt::test::common_sample_count(r), r.spp);
  EXPECT_LT(rt::relative_noise(r.accum, r.width), 0.05);
  // The pass before the last (half as many samples, or fewer) was still too noisy, or the
  // rule would have stopped there: the estimate falls with more samples.
  rt::RenderResult half = RenderAreaWithStop({}, r.spp / 2);
  EXPECT_GT(rt::relative_noise(half.accum, half.width), rt::relative_noise(r.accum, r.width));
}

TEST(Render, TimeLimitKeepsEqualSampleCounts) {
  rt::StopRule stop;
  stop.time_limit_s = 0.05;
  rt::RenderResult r = RenderAreaWithStop(stop, 1 << 16);
  EXPECT_GE(r.spp, 1);
  EXPECT_LT(r.spp, 1 << 16);
  EXPECT_EQ(rt::test::common_sample_count(r), r.spp);
  EXPECT_LT(r.seconds, 2.0);  // Far below the 65536 samples asked (about 30 s here).
}

TEST(Render, RelativeNoiseIsZeroWithoutVarianceInformation) {
  rt::RenderResult once = RenderAreaWithStop({}, 1);
  EXPECT_EQ(rt::relative_noise(once.accum, once.width), 0.0);
}

}  // namespace
