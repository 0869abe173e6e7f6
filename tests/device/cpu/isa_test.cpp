// The CPU reference's float kernel compiled for AVX2 (src/device/cpu/cpu_kernel_avx2.cpp)
// against the baseline build of the same headers: every pixel's sums, sample counts and
// primary hit must be bit-identical, since only the instruction encoding differs (FP
// contraction is off for both).
#include <gtest/gtest.h>

#include <cstring>
#include <filesystem>
#include <string>

#include "device/cpu/cpu_kernel.h"
#include "prepare/flat_scene.h"
#include "scene/scene.h"

namespace {

const std::string kScenes = RT_SHARED_SCENES_DIR;

#ifdef RT_CPU_KERNEL_AVX2

bool SameBits(float a, float b) { return std::memcmp(&a, &b, sizeof a) == 0; }

// Field by field: the struct's padding (the normal's fourth lane) carries no value.
bool SamePrimary(const PrimaryInfo& a, const PrimaryInfo& b) {
  return SameBits(a.t, b.t) && a.instance == b.instance && a.primitive == b.primitive &&
         SameBits(a.normal.x, b.normal.x) && SameBits(a.normal.y, b.normal.y) &&
         SameBits(a.normal.z, b.normal.z);
}

// Renders every pixel of a size x size film of the scene's first camera with both kernels.
void ExpectSamePixels(const std::string& rel, int spp, int size) {
  if (!std::filesystem::exists(kScenes + rel))
    GTEST_SKIP() << kScenes + rel << " is not here (the course's scenes, ../shared)";
  if (!__builtin_cpu_supports("avx2")) GTEST_SKIP() << "this CPU has no AVX2";
  rt::SceneDesc scene = rt::load_scene(kScenes + rel);
  rt::RenderOptions opt;
  opt.spp = spp;
  rt::FlatScene flat = rt::prepare_scene(scene, opt);
  rt::prepare_camera(flat, scene, 0, opt);
  flat.header.camera.width = size;
  flat.header.camera.height = size;
  const SceneData sd = flat.view();
  int differ = 0, hits = 0;
  for (int y = 0; y < size; ++y) {
    for (int x = 0; x < size; ++x) {
      PixelAccum a{}, b{};
      PrimaryInfo pa{}, pb{};
      rt::accumulate_pixel_float(&sd, x, y, 0, spp, &a, &pa);
      rt::accumulate_pixel_float_avx2(&sd, x, y, 0, spp, &b, &pb);
      if (std::memcmp(&a, &b, sizeof a) != 0 || !SamePrimary(pa, pb)) ++differ;
      if (pa.instance >= 0) ++hits;
    }
  }
  EXPECT_EQ(differ, 0) << rel << ": pixels that differ between the two builds";
  EXPECT_GT(hits, size * size / 10) << rel << ": too few camera rays hit anything to tell";
}

TEST(CpuIsa, Avx2KernelMatchesBaselineOnTap) {
  ExpectSamePixels("/hw3/tap_water/xml/tap_0200.xml", 2, 40);
}

TEST(CpuIsa, Avx2KernelMatchesBaselineOnGlassAndMetal) {
  ExpectSamePixels("/hw3/metal_glass_plates.xml", 4, 40);
}

TEST(CpuIsa, Avx2KernelMatchesBaselineOnMovingBoxes) {
  ExpectSamePixels("/hw3/cornellbox_boxes_dynamic.xml", 4, 40);
}

TEST(CpuIsa, Avx2KernelMatchesBaselineOnPathTracedGlass) {
  ExpectSamePixels("/hw6/pathTracing/cornellbox_jaroslav_path_glass.xml", 4, 32);
}

#else

TEST(CpuIsa, Avx2KernelMatchesBaseline) { GTEST_SKIP() << "no AVX2 kernel on this target"; }

#endif

}  // namespace
