#include "support/pixel_estimate.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>

#include "cl/material/brdf.h"
#include "support/device_harness.h"

namespace rt::test {

PixelStats RenderOnePixel(const SceneDesc& scene, const RenderOptions& opt) {
  FlatScene flat = flatten_scene(scene, opt);
  set_camera(flat, scene, 0, opt);
  RenderResult r = render_cpu(flat);
  const PixelAccum& a = r.accum[0];
  EXPECT_EQ(a.nonfinite, 0u);
  double n = a.sum_sq.w, mean = a.sum.x / a.sum.w;
  double var = (a.sum_sq.x / n - mean * mean) * n / (n - 1);
  return {mean, std::sqrt(std::max(var, 0.0) / n)};
}

void ExpectMean(const PixelStats& s, double expected, const std::string& what) {
  double tolerance = 4.5 * s.standard_error + 2e-4 * std::fabs(expected);
  EXPECT_NEAR(s.mean, expected, tolerance)
      << what << ": standard error " << s.standard_error << " ("
      << (s.mean - expected) / std::max(s.standard_error, 1e-30) << " of them)";
}

void ExpectSameMean(const PixelStats& a, const PixelStats& b, const std::string& what) {
  double se = std::hypot(a.standard_error, b.standard_error);
  EXPECT_NEAR(a.mean, b.mean, 4.5 * se + 2e-4 * std::fabs(a.mean))
      << what << ": standard error of the difference " << se;
}

Material Lambert(double a) {
  Material m{};
  m.diffuse = make_float3(a, a, a);
  m.phong_exponent = 1;
  m.refraction_index = 1;
  m.brdf = RT_BRDF_MODIFIED_PHONG;
  m.brdf_flags = RT_BRDF_NORMALIZED;
  return m;
}

}  // namespace rt::test
