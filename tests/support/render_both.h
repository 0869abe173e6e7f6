// The loader tests that compare renders (tests/scene/loader/*_test.cpp): camera 0 of a loaded
// scene on the CPU reference and, where one is usable, on OpenCL, the two expected equal
// bit for bit.
#pragma once

#include <gtest/gtest.h>

#include <cstring>
#include <string>
#include <vector>

#include "prepare/flat_scene.h"
#include "scene/scene.h"
#include "support/device_harness.h"

namespace rt::test {

// The radiance image (3 floats per pixel) of camera 0 at `spp` samples (0: the scene's).
// Equal floats are equal image bytes in every output format.
inline std::vector<float> RenderBoth(const SceneDesc& scene, int spp = 0) {
  RenderOptions opt;
  opt.spp = spp;
  FlatScene flat = prepare_scene(scene, opt);
  prepare_camera(flat, scene, 0, opt);
  RenderResult cpu = render_cpu(flat);
  std::string why;
  if (RenderDevice* cl = shared_device(Device::kOpenCl, &why)) {
    RenderResult gpu = render_on(*cl, flat);
    std::vector<float> a = cpu.rgb(), b = gpu.rgb();
    EXPECT_TRUE(a.size() == b.size() && std::memcmp(a.data(), b.data(), a.size() * 4) == 0)
        << "OpenCL and the CPU reference differ";
  }
  return cpu.rgb();
}

// Counts the floats of a and b whose bits differ (a.size() + 1 when the sizes differ).
inline size_t DifferingValues(const std::vector<float>& a, const std::vector<float>& b) {
  if (a.size() != b.size()) return a.size() + 1;
  size_t n = 0;
  for (size_t i = 0; i < a.size(); ++i) n += std::memcmp(&a[i], &b[i], sizeof(float)) != 0;
  return n;
}

// Expects a and b equal bit for bit and not black (so the equality says something).
inline void ExpectSameLitImage(const std::vector<float>& a, const std::vector<float>& b) {
  EXPECT_EQ(DifferingValues(a, b), 0u);
  float peak = 0;
  for (float v : a) peak = v > peak ? v : peak;
  EXPECT_GT(peak, 0.0f) << "black image";
}

}  // namespace rt::test
