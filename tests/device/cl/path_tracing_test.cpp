// The path tracer on the OpenCL device against the CPU reference at equal seeds: the same
// paths and the same per-pixel sums, bit for bit (sampling uses util/transcendental.h's functions,
// not the libraries', whose last bits differ between devices).
#include <gtest/gtest.h>

#include <cmath>
#include <cstring>
#include <fstream>
#include <string>

#include "prepare/flat_scene.h"
#include "scene/scene.h"
#include "support/device_harness.h"

namespace {

const std::string kScenes = RT_SHARED_SCENES_DIR;

// Camera 0 of a course scene, path traced with `flags` at `size` x `size` pixels.
rt::FlatScene PathTraced(const std::string& rel, int flags, int spp, int size,
                         rt::SceneDesc* scene) {
  *scene = rt::load_scene(kScenes + rel);
  scene->cameras[0].path_tracing = true;
  scene->cameras[0].path_flags = flags;
  rt::RenderOptions opt;
  opt.spp = spp;
  rt::FlatScene flat = rt::prepare_scene(*scene, opt);
  rt::prepare_camera(flat, *scene, 0, opt);
  flat.header.camera.width = size;
  flat.header.camera.height = size;
  return flat;
}

void ExpectSamePaths(const std::string& rel, int flags) {
  std::string why;
  rt::RenderDevice* cl = rt::test::shared_device(rt::Device::kOpenCl, &why);
  if (!cl) GTEST_SKIP() << "no OpenCL device: " << why;
  if (!std::ifstream(kScenes + rel)) GTEST_SKIP() << rel << " is not in ../shared/scenes";
  rt::SceneDesc scene;
  rt::FlatScene flat = PathTraced(rel, flags, 4, 40, &scene);
  rt::RenderResult a = rt::test::render_on(*cl, flat), b = rt::test::render_cpu(flat);
  ASSERT_EQ(a.accum.size(), b.accum.size());
  size_t identical = 0;
  double max_value = 0;
  for (size_t i = 0; i < a.accum.size(); ++i) {
    identical += std::memcmp(&a.accum[i].sum, &b.accum[i].sum, sizeof(float4)) == 0;
    max_value = std::max<double>(max_value, b.accum[i].sum.x + b.accum[i].sum.y);
  }
  std::printf("[ %s flags %d ] %.2f%% of pixel sums bit-identical, rays %llu vs %llu\n",
              rel.c_str(), flags, 100.0 * identical / a.accum.size(),
              static_cast<unsigned long long>(a.rays), static_cast<unsigned long long>(b.rays));
  EXPECT_GT(max_value, 0.0) << "black image";
  EXPECT_EQ(a.rays, b.rays);
  EXPECT_EQ(identical, a.accum.size());
}

// Mirror and glass spheres in a box lit by a point light: splitting at the glass, light
// sampling, the course's roulette.
TEST(PathTracingOpenCl, MatchesCpuWithGlassAndRoulette) {
  ExpectSamePaths("/hw1/cornellbox_recursive.xml",
                  RT_FLAG_NEXT_EVENT | RT_FLAG_IMPORTANCE_SAMPLING | RT_FLAG_RUSSIAN_ROULETTE);
}

// An area light sampled at every bounce of uniformly sampled paths.
TEST(PathTracingOpenCl, MatchesCpuWithAreaLightUniform) {
  ExpectSamePaths("/hw3/cornellbox_area.xml", RT_FLAG_NEXT_EVENT);
}

}  // namespace
