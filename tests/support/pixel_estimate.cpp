#include "support/pixel_estimate.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>

#include "cl/material/brdf.h"
#include "integrator/render.h"
#include "support/device_harness.h"

namespace rt::test {

PixelStats RenderOnePixel(const SceneDesc& scene, const RenderOptions& opt) {
  FlatScene flat = prepare_scene(scene, opt);
  prepare_camera(flat, scene, 0, opt);
  RenderResult r = render_cpu(flat);
  EXPECT_EQ(r.accum[0].nonfinite, 0u);
  const PixelEstimate e = estimate_pixel(r.accum[0]);
  return {e.mean[0], std::sqrt(e.var[0] / e.n)};
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
