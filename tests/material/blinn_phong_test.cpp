// Tests for the Blinn-Phong model (cl/material/blinn_phong.h) and Reflect (cl/util/math.h),
// against closed forms evaluated in double precision. Tolerances as in shading_test.cpp:
// exact operations compared with ==, others within a few float roundings.
#include <gtest/gtest.h>

#include <cmath>
#include <random>

#include "cl/material/blinn_phong.h"

namespace rt {
namespace {

float3 V(float x, float y, float z) { return make_float3(x, y, z); }
// ------------------------------------------------------------------------------------------
// BlinnPhong
// ------------------------------------------------------------------------------------------

Material Phong(float3 kd, float3 ks, float exponent) {
  Material m{};
  m.diffuse = kd;
  m.specular = ks;
  m.phong_exponent = exponent;
  return m;
}

void ExpectExact(float3 a, float3 b) {
  EXPECT_EQ(a.x, b.x);
  EXPECT_EQ(a.y, b.y);
  EXPECT_EQ(a.z, b.z);
}

TEST(ShadingBlinnPhong, NoLightFromBehindTheSurface) {
  Material m = Phong(V(1, 1, 1), V(1, 1, 1), 10);
  const float3 n = V(0, 0, 1), wo = V(0, 0.6f, 0.8f), e = V(5, 5, 5);
  ExpectExact(BlinnPhong(&m, n, wo, V(0, 0, -1), e), V(0, 0, 0));
  ExpectExact(BlinnPhong(&m, n, wo, V(0.6f, 0, -0.8f), e), V(0, 0, 0));
  ExpectExact(BlinnPhong(&m, n, wo, V(1, 0, 0), e), V(0, 0, 0));  // In the tangent plane.
  // Just above the plane some light arrives.
  float3 r = BlinnPhong(&m, n, wo, Normalize(V(1, 0, 0.01f)), e);
  EXPECT_GT(r.x, 0.0f);
}

TEST(ShadingBlinnPhong, DiffuseIsKdTimesCosineTimesIrradiance) {
  // cos_i = Dot((sqrt(3)/2, 0, 1/2), (0,0,1)) = 0.5 exactly; no specular.
  const float3 n = V(0, 0, 1), wi = V(0.8660254f, 0, 0.5f), wo = V(0, 0.6f, 0.8f);
  Material m = Phong(V(1, 1, 1), V(0, 0, 0), 50);
  ExpectExact(BlinnPhong(&m, n, wo, wi, V(2, 2, 2)), V(1, 1, 1));
  m = Phong(V(0.25f, 0.5f, 0.75f), V(0, 0, 0), 50);
  ExpectExact(BlinnPhong(&m, n, wo, wi, V(2, 4, 8)), V(0.25f, 1.0f, 3.0f));
}

TEST(ShadingBlinnPhong, SpecularPeakWhenHalfVectorIsTheNormal) {
  // wi and wo mirror each other about n, so h = normalize((0, 0, 1.6)) = n exactly.
  const float3 n = V(0, 0, 1), wi = V(0.6f, 0, 0.8f), wo = V(-0.6f, 0, 0.8f);
  const float3 ks = V(0.5f, 0.25f, 1.0f), e = V(2, 4, 8);
  for (float p : {1.0f, 10.0f, 100.0f, 1000.0f}) {
    Material m = Phong(V(0, 0, 0), ks, p);
    ExpectExact(BlinnPhong(&m, n, wo, wi, e), ks * e);
  }
  Material m = Phong(V(0.5f, 0.5f, 0.5f), ks, 20);
  float3 r = BlinnPhong(&m, n, wo, wi, e);
  // (kd * 0.8 + ks) * e, with 0.8 not dyadic: one rounding.
  EXPECT_NEAR(r.x, (0.5 * 0.8 + 0.5) * 2, 1e-6);
  EXPECT_NEAR(r.y, (0.5 * 0.8 + 0.25) * 4, 1e-6);
  EXPECT_NEAR(r.z, (0.5 * 0.8 + 1.0) * 8, 1e-5);
}

TEST(ShadingBlinnPhong, SpecularLobeFollowsPowerOfHalfVectorCosine) {
  const float3 n = V(0, 0, 1), wi = Normalize(V(0.3f, 0.1f, 0.9f));
  const float3 ks = V(1, 1, 1), e = V(1, 1, 1);
  float prev_p = 0;
  for (float p : {1.0f, 8.0f, 64.0f}) {
    Material m = Phong(V(0, 0, 0), ks, p);
    float prev = 2;
    for (float a = 0.0f; a < 1.2f; a += 0.1f) {
      float3 wo = Normalize(V(-0.3f + std::sin(a), -0.1f, 0.9f));
      float3 r = BlinnPhong(&m, n, wo, wi, e);
      double hx = double(wi.x) + wo.x, hy = double(wi.y) + wo.y, hz = double(wi.z) + wo.z;
      double cos_h = hz / std::sqrt(hx * hx + hy * hy + hz * hz);
      double expect = std::pow(cos_h, p);
      // pow amplifies the ~1e-7 error of cos_h by p.
      EXPECT_NEAR(r.x, expect, expect * 3e-7 * (p + 2) + 1e-9) << "p " << p << " a " << a;
      EXPECT_LE(r.x, prev) << "lobe must fall off away from the peak";
      prev = r.x;
    }
    EXPECT_GT(prev_p == 0 ? 1.0f : prev_p, prev);  // Sharper lobes fall further.
    prev_p = prev;
  }
}

// ------------------------------------------------------------------------------------------
// Reflect
// ------------------------------------------------------------------------------------------

TEST(ShadingReflect, MirrorDirectionForAxisAlignedNormals) {
  // Reflect(wo, n) = 2 (wo . n) n - wo: both directions point away from the surface.
  ExpectExact(Reflect(V(1, 2, 3), V(0, 0, 1)), V(-1, -2, 3));
  ExpectExact(Reflect(V(1, 2, 3), V(0, -1, 0)), V(-1, 2, -3));
  ExpectExact(Reflect(V(1, 2, 3), V(1, 0, 0)), V(1, -2, -3));
  ExpectExact(Reflect(V(0.6f, 0, 0.8f), V(0, 0, 1)), V(-0.6f, 0, 0.8f));
  ExpectExact(Reflect(V(0, 0, 1), V(0, 0, 1)), V(0, 0, 1));  // Along the normal: itself.
  ExpectExact(Reflect(V(0, 0, -1), V(0, 0, 1)), V(0, 0, -1));
  ExpectExact(Reflect(V(-0.5f, 0.5f, 0.5f), V(0, 0, -1)), V(0.5f, -0.5f, 0.5f));
}

TEST(ShadingReflect, PreservesAnglesAndIsAnInvolution) {
  std::mt19937 rng(4);
  std::normal_distribution<float> g;
  for (int i = 0; i < 1000; ++i) {
    float3 n = Normalize(V(g(rng), g(rng), g(rng)));
    float3 w = Normalize(V(g(rng), g(rng), g(rng)));
    float3 r = Reflect(w, n);
    EXPECT_NEAR(Length(r), 1.0f, 1e-6);
    EXPECT_NEAR(Dot(r, n), Dot(w, n), 1e-6);
    // The bisector of w and r is along n.
    float3 sum = w + r;
    EXPECT_NEAR(Length(Cross(sum, n)), 0.0f, 1e-6);
    float3 back = Reflect(r, n);
    EXPECT_NEAR(back.x, w.x, 1e-6);
    EXPECT_NEAR(back.y, w.y, 1e-6);
    EXPECT_NEAR(back.z, w.z, 1e-6);
  }
}

}  // namespace
}  // namespace rt
