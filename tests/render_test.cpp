// Whole-render properties of the CPU reference: the image does not depend on the thread
// count, and equal seeds give equal images.
#include <gtest/gtest.h>

#include <cstring>

#include "flat_scene.h"
#include "render.h"

namespace {

rt::RenderResult RenderExample(int threads, uint32_t seed) {
  rt::SceneDesc scene = rt::load_scene(RT_SOURCE_DIR "/scenes/example.xml");
  scene.cameras[0].width = 64;
  scene.cameras[0].height = 48;
  rt::RenderOptions opt;
  opt.seed = seed;
  opt.spp = 4;
  rt::FlatScene flat = rt::flatten_scene(scene, opt);
  rt::set_camera(flat, scene, 0, opt);
  rt::Progress quiet(false, "", 0);
  return rt::render_cpu(flat, threads, quiet);
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
