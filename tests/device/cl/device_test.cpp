// The OpenCL device (src/device/cl/cl_device.cpp) against the CPU reference on course
// scenes: most per-pixel sums bit-identical and the colours within 1e-3 of the brightest,
// also for image sizes that are not a multiple of the work-group size.
#include <gtest/gtest.h>
#include <algorithm>
#include <cmath>
#include <cstdio>
#include <cstring>
#include <filesystem>
#include <string>
#include <vector>

#include "cl/features.h"
#include "support/cl_harness.h"
#include "support/device_harness.h"

namespace fs = std::filesystem;

namespace {

using namespace rt::test;

bool same_bits(const float4& a, const float4& b) { return std::memcmp(&a, &b, sizeof a) == 0; }

// Compares two renders: prints the share of bit-identical per-pixel sums and the largest
// difference of the reconstructed colour, and checks it against the tolerance.
void expect_agree(const std::string& label, const rt::RenderResult& cl,
                  const rt::RenderResult& cpu) {
  ASSERT_EQ(cl.width, cpu.width);
  ASSERT_EQ(cl.height, cpu.height);
  ASSERT_EQ(cl.accum.size(), cpu.accum.size());
  size_t identical = 0, same_primary = 0;
  for (size_t i = 0; i < cl.accum.size(); ++i) {
    if (same_bits(cl.accum[i].sum, cpu.accum[i].sum)) ++identical;
    if (cl.primary[i].instance == cpu.primary[i].instance &&
        cl.primary[i].primitive == cpu.primary[i].primitive)
      ++same_primary;
  }
  std::vector<float> a = cl.rgb(), b = cpu.rgb();
  float max_value = 0, max_diff = 0;
  size_t worst = 0;
  for (size_t i = 0; i < a.size(); ++i) {
    ASSERT_TRUE(std::isfinite(a[i])) << label << ": component " << i;
    max_value = std::max({max_value, std::fabs(a[i]), std::fabs(b[i])});
    float d = std::fabs(a[i] - b[i]);
    if (d > max_diff) {
      max_diff = d;
      worst = i / 3;
    }
  }
  double n = static_cast<double>(cl.accum.size());
  std::printf(
      "[ %s ] %dx%d: %.2f%% of pixel sums bit-identical, %.2f%% same primary hit, "
      "max |rgb difference| %.3g (max value %.3g, worst pixel %zu,%zu), rays %llu vs "
      "%llu\n",
      label.c_str(), cl.width, cl.height, 100.0 * identical / n, 100.0 * same_primary / n, max_diff,
      max_value, worst % cl.width, worst / cl.width, static_cast<unsigned long long>(cl.rays),
      static_cast<unsigned long long>(cpu.rays));
  EXPECT_GT(max_value, 0.0f) << label << ": black image";
  EXPECT_LE(max_diff, 1e-3f * max_value) << label;
  EXPECT_GE(identical, cl.accum.size() / 2) << label << ": most pixels should be bit-identical";
}

TEST(OpenCl, MatchesCpuOnSimple) {
  REQUIRE_DEVICE(r);
  SKIP_WITHOUT_SCENE("/hw1/simple.xml");
  Loaded l = load("/hw1/simple.xml", 0, 96);
  expect_agree("hw1/simple", render_on_cl(l.flat, false), render_cpu(l.flat));
}

TEST(OpenCl, MatchesCpuOnTransformedSpheres) {
  REQUIRE_DEVICE(r);
  SKIP_WITHOUT_SCENE("/hw2/spheres.xml");
  Loaded l = load("/hw2/spheres.xml", 0, 96);
  ASSERT_TRUE(l.flat.header.features & RT_FEATURE_TRANSFORMS);
  expect_agree("hw2/spheres", render_on_cl(l.flat, false), render_cpu(l.flat));
}

TEST(OpenCl, MatchesCpuOnAreaLightsWithSampling) {
  REQUIRE_DEVICE(r);
  SKIP_WITHOUT_SCENE("/hw3/cornellbox_area.xml");
  Loaded l = load("/hw3/cornellbox_area.xml", 4, 64);
  ASSERT_TRUE(l.flat.header.features & RT_FEATURE_AREA_LIGHTS);
  rt::RenderResult cl = render_on_cl(l.flat, false);
  EXPECT_EQ(cl.samples, 64u * 64u * 4u);
  expect_agree("hw3/cornellbox_area 4 spp", cl, render_cpu(l.flat));
}

// Odd sizes: the global size is rounded up to the work-group size, and the kernel must
// skip the extra work-items.
TEST(OpenCl, OddImageSize) {
  REQUIRE_DEVICE(r);
  SKIP_WITHOUT_SCENE("/hw1/simple.xml");
  Loaded l = load("/hw1/simple.xml", 0, 37);
  l.flat.header.camera.height = 13;
  expect_agree("hw1/simple 37x13", render_on_cl(l.flat, false), render_cpu(l.flat));
}

}  // namespace
