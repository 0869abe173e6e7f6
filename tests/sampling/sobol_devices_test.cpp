// --sampler sobol on both devices: the OpenCL kernel and the CPU reference draw the same
// Owen-scrambled Sobol numbers, so their pixel sums agree bit for bit, on path-traced and
// ray-tree cameras, with depth of field, motion blur and glossy reflection, at square and
// non-square sample counts; and the flag reaches the kernel (the image is not the
// independent sampler's).
#include <gtest/gtest.h>

#include <cstring>
#include <fstream>
#include <string>

#include "prepare/flat_scene.h"
#include "scene/scene.h"
#include "support/device_harness.h"

namespace {

const std::string kScenes = RT_SHARED_SCENES_DIR;

rt::FlatScene Flatten(const rt::SceneDesc& scene, int camera, int spp, rt::SamplerChoice sampler) {
  rt::RenderOptions opt;
  opt.spp = spp;
  opt.seed = 3;
  opt.sampler = sampler;
  rt::FlatScene flat = rt::prepare_scene(scene, opt);
  rt::prepare_camera(flat, scene, camera, opt);
  return flat;
}

size_t SameSums(const rt::RenderResult& a, const rt::RenderResult& b) {
  size_t same = 0;
  for (size_t i = 0; i < a.accum.size() && i < b.accum.size(); ++i)
    same += std::memcmp(&a.accum[i].sum, &b.accum[i].sum, sizeof(float4)) == 0;
  return same;
}

// The pixels of a with light in them, and those of them b matches bit for bit.
size_t LitPixels(const rt::RenderResult& a) {
  size_t lit = 0;
  for (const PixelAccum& p : a.accum) lit += p.sum.x + p.sum.y + p.sum.z > 0;
  return lit;
}
size_t SameLitSums(const rt::RenderResult& a, const rt::RenderResult& b) {
  size_t same = 0;
  for (size_t i = 0; i < a.accum.size() && i < b.accum.size(); ++i)
    same += a.accum[i].sum.x + a.accum[i].sum.y + a.accum[i].sum.z > 0 &&
            std::memcmp(&a.accum[i].sum, &b.accum[i].sum, sizeof(float4)) == 0;
  return same;
}

void ExpectDevicesAgree(const std::string& rel, int camera, int size) {
  std::string why;
  rt::RenderDevice* cl = rt::test::shared_device(rt::Device::kOpenCl, &why);
  if (!cl) GTEST_SKIP() << "no OpenCL device: " << why;
  if (!std::ifstream(kScenes + rel)) GTEST_SKIP() << rel << " is not in ../shared/scenes";
  rt::SceneDesc scene = rt::load_scene(kScenes + rel);
  for (rt::CameraDesc& c : scene.cameras) c.width = c.height = size;
  for (int spp : {16, 5}) {
    rt::FlatScene flat = Flatten(scene, camera, spp, rt::SamplerChoice::kSobol);
    ASSERT_NE(flat.header.flags & RT_FLAG_SOBOL_SAMPLER, 0);
    rt::RenderResult a = rt::test::render_on(*cl, flat), b = rt::test::render_cpu(flat);
    ASSERT_EQ(a.accum.size(), b.accum.size());
    EXPECT_EQ(a.rays, b.rays) << rel << " at " << spp << " spp";
    EXPECT_EQ(SameSums(a, b), a.accum.size()) << rel << " at " << spp << " spp";
    size_t lit = LitPixels(b);
    EXPECT_GT(lit, b.accum.size() / 8) << rel << ": too few lit pixels to compare";
    rt::FlatScene plain = Flatten(scene, camera, spp, rt::SamplerChoice::kAuto);
    EXPECT_EQ(plain.header.flags & RT_FLAG_SOBOL_SAMPLER, 0);
    rt::RenderResult c = rt::test::render_cpu(plain);
    EXPECT_LT(SameLitSums(b, c), lit / 2) << rel << ": sobol drew the independent numbers";
  }
}

TEST(SobolDevices, PathTracedCornellBoxNextEvent) {
  ExpectDevicesAgree("/hw6/pathTracing/cornellbox_jaroslav_path_diffuse.xml", 0, 32);
}

TEST(SobolDevices, PathTracedCornellBoxUniform) {
  ExpectDevicesAgree("/hw6/pathTracing/cornellbox_jaroslav_path_diffuse.xml", 4, 32);
}

TEST(SobolDevices, DepthOfField) { ExpectDevicesAgree("/hw3/spheres_dof.xml", 0, 32); }

TEST(SobolDevices, MotionBlur) { ExpectDevicesAgree("/hw3/cornellbox_boxes_dynamic.xml", 0, 32); }

TEST(SobolDevices, GlossyAndAreaLight) {
  ExpectDevicesAgree("/hw3/cornellbox_brushed_metal.xml", 0, 32);
}

}  // namespace
