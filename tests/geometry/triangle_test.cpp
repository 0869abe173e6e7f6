// IntersectTriangle, the watertight ray-triangle test of cl/: exact hits of axis-aligned
// triangles, edges counted as inside, the open distance interval, parallel rays, back-face
// culling, and agreement with a double-precision reference in general position.
#include <gtest/gtest.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <random>
#include <string>

#include "support/geometry_harness.h"

namespace rt {
namespace {

using namespace test;

// The triangle (-1,-1), (1,-1), (-1,1) in the plane of axes (a, b) = (k+1, k+2) at
// coordinate `plane` along axis k. Its geometric normal cross(v1-v0, v2-v0) is 4 e_k.
std::array<float3, 3> AxisTriangle(int k, float plane) {
  std::array<float3, 3> out;
  const float ab[3][2] = {{-1, -1}, {1, -1}, {-1, 1}};
  for (int i = 0; i < 3; ++i) {
    float c[3];
    c[k] = plane;
    c[(k + 1) % 3] = ab[i][0];
    c[(k + 2) % 3] = ab[i][1];
    out[i] = make_float3(c[0], c[1], c[2]);
  }
  return out;
}

float3 AxisPoint(int k, float along, float a, float b) {
  float c[3];
  c[k] = along;
  c[(k + 1) % 3] = a;
  c[(k + 2) % 3] = b;
  return make_float3(c[0], c[1], c[2]);
}

TEST(GeometryTriangle, AxisAlignedInteriorHitIsExactForEveryAxisAndDirection) {
  for (int k = 0; k < 3; ++k)
    for (float sign : {-1.0f, 1.0f}) {
      SCOPED_TRACE("axis " + std::to_string(k) + " sign " + std::to_string(sign));
      auto v = AxisTriangle(k, 2.0f * sign);
      // From in-plane position (-0.5, -0.25): b1 = 0.25, b2 = 0.375, distance 2. All inputs
      // are dyadic, so every intermediate of the sheared test is exact.
      float3 o = AxisPoint(k, 0.0f, -0.5f, -0.25f);
      float3 d = AxisPoint(k, sign, 0.0f, 0.0f);
      TriHit h = HitTriangle(o, d, v[0], v[1], v[2], kInf, 0);
      ASSERT_EQ(h.hit, 1);
      EXPECT_EQ(h.t, 2.0f);
      EXPECT_EQ(h.b1, 0.25f);
      EXPECT_EQ(h.b2, 0.375f);
      // t is measured in units of the (non-unit) direction.
      h = HitTriangle(o, d * 4.0f, v[0], v[1], v[2], kInf, 0);
      ASSERT_EQ(h.hit, 1);
      EXPECT_EQ(h.t, 0.5f);
      EXPECT_EQ(h.b1, 0.25f);
      EXPECT_EQ(h.b2, 0.375f);
      // Another interior point: (0.25, -0.5) -> b1 = 0.625, b2 = 0.25.
      h = HitTriangle(AxisPoint(k, 0.0f, 0.25f, -0.5f), d, v[0], v[1], v[2], kInf, 0);
      ASSERT_EQ(h.hit, 1);
      EXPECT_EQ(h.t, 2.0f);
      EXPECT_EQ(h.b1, 0.625f);
      EXPECT_EQ(h.b2, 0.25f);
    }
}

TEST(GeometryTriangle, MissesOutsideAndCountsExactEdgesAsInside) {
  auto v = AxisTriangle(2, -2.0f);  // Plane z = -2, ray along -z.
  const float3 d = make_float3(0, 0, -1);
  auto hit_at = [&](float x, float y) {
    return HitTriangle(make_float3(x, y, 0), d, v[0], v[1], v[2], kInf, 0).hit;
  };
  // The hypotenuse is x + y = 0; one 1/128 step either side of it.
  EXPECT_EQ(hit_at(0.0078125f, 0.0f), 0);
  EXPECT_EQ(hit_at(-0.0078125f, 0.0f), 1);
  EXPECT_EQ(hit_at(0.25f, -0.25f), 1);  // Exactly on the hypotenuse.
  EXPECT_EQ(hit_at(-1.0f, 0.0f), 1);    // Exactly on the edge x = -1.
  EXPECT_EQ(hit_at(-1.0f, -1.0f), 1);   // Exactly on vertex v0.
  EXPECT_EQ(hit_at(-1.0078125f, 0.0f), 0);
  EXPECT_EQ(hit_at(0.0f, -1.0078125f), 0);
  EXPECT_EQ(hit_at(1.5f, 0.0f), 0);
  EXPECT_EQ(hit_at(-0.5f, 3.0f), 0);
  EXPECT_EQ(hit_at(5.0f, 5.0f), 0);
  // The edge hit reports barycentrics on the edge: (0.25, -0.25) -> b1 = 0.625, b2 = 0.375.
  TriHit h = HitTriangle(make_float3(0.25f, -0.25f, 0), d, v[0], v[1], v[2], kInf, 0);
  EXPECT_EQ(h.b1 + h.b2, 1.0f);
  EXPECT_EQ(h.b1, 0.625f);
}

TEST(GeometryTriangle, DistanceMustLieStrictlyBetweenZeroAndTmax) {
  auto v = AxisTriangle(2, -2.0f);
  const float3 o = make_float3(-0.5f, -0.25f, 0.0f);
  const float3 down = make_float3(0, 0, -1), up = make_float3(0, 0, 1);
  EXPECT_EQ(HitTriangle(o, up, v[0], v[1], v[2], kInf, 0).hit, 0);    // Behind the origin.
  EXPECT_EQ(HitTriangle(o, down, v[0], v[1], v[2], 2.0f, 0).hit, 0);  // t == tmax.
  EXPECT_EQ(HitTriangle(o, down, v[0], v[1], v[2], 1.0f, 0).hit, 0);
  TriHit h = HitTriangle(o, down, v[0], v[1], v[2], std::nextafter(2.0f, 3.0f), 0);
  EXPECT_EQ(h.hit, 1);
  EXPECT_EQ(h.t, 2.0f);
  // Origin on the plane: t == 0 is not a hit, in either direction.
  const float3 on = make_float3(-0.5f, -0.25f, -2.0f);
  EXPECT_EQ(HitTriangle(on, down, v[0], v[1], v[2], kInf, 0).hit, 0);
  EXPECT_EQ(HitTriangle(on, up, v[0], v[1], v[2], kInf, 0).hit, 0);
  // Back-facing side, same rules (det < 0 branch).
  const float3 below = make_float3(-0.5f, -0.25f, -4.0f);
  h = HitTriangle(below, up, v[0], v[1], v[2], kInf, 0);
  EXPECT_EQ(h.hit, 1);
  EXPECT_EQ(h.t, 2.0f);
  EXPECT_EQ(HitTriangle(below, up, v[0], v[1], v[2], 2.0f, 0).hit, 0);
  EXPECT_EQ(HitTriangle(below, down, v[0], v[1], v[2], kInf, 0).hit, 0);
}

TEST(GeometryTriangle, ParallelRaysMiss) {
  auto v = AxisTriangle(2, -2.0f);
  // In the plane of the triangle, crossing its interior: every edge function is zero.
  const float3 dirs[] = {make_float3(1, 0, 0), make_float3(0, -1, 0), make_float3(0.6f, 0.8f, 0),
                         make_float3(-3, 1, 0)};
  for (float3 d : dirs) {
    SCOPED_TRACE(Str(d));
    float3 o = make_float3(-0.5f, -0.25f, -2.0f) - d * 4.0f;
    EXPECT_EQ(HitTriangle(o, d, v[0], v[1], v[2], kInf, 0).hit, 0);
    // Parallel above and below the plane.
    EXPECT_EQ(HitTriangle(o + make_float3(0, 0, 0.5f), d, v[0], v[1], v[2], kInf, 0).hit, 0);
    EXPECT_EQ(HitTriangle(o - make_float3(0, 0, 0.5f), d, v[0], v[1], v[2], kInf, 0).hit, 0);
  }
}

TEST(GeometryTriangle, CullSkipsOnlyBackFacesForAxisRays) {
  for (int k = 0; k < 3; ++k)
    for (float plane : {-2.0f, 2.0f})
      for (float sign : {-1.0f, 1.0f}) {
        SCOPED_TRACE("axis " + std::to_string(k) + " plane " + std::to_string(plane) + " sign " +
                     std::to_string(sign));
        // The normal is +e_k; the ray origin sits on the side of the normal when the plane
        // is at -2 and the ray comes from 0, or when it is at +2 and the ray comes from 4.
        auto v = AxisTriangle(k, plane);
        float start = plane - 2.0f * sign;  // Two units before the plane, moving by sign.
        float3 o = AxisPoint(k, start, -0.5f, -0.25f);
        float3 d = AxisPoint(k, sign, 0.0f, 0.0f);
        bool front = start > plane;  // Origin on the side the normal points to.
        EXPECT_EQ(HitTriangle(o, d, v[0], v[1], v[2], kInf, 0).hit, 1);
        EXPECT_EQ(HitTriangle(o, d, v[0], v[1], v[2], kInf, 1).hit, front ? 1 : 0);
      }
}

// Double-precision Möller-Trumbore for reference.
struct RefHit {
  bool valid;  // False when the ray is (nearly) parallel to the plane.
  double t, b1, b2;
};

RefHit ReferenceTriangle(Vec3d o, Vec3d d, Vec3d p0, Vec3d p1, Vec3d p2) {
  Vec3d e1 = p1 - p0, e2 = p2 - p0;
  Vec3d pv = cross(d, e2);
  double det = dot(e1, pv);
  if (std::fabs(det) < 1e-12) return {false, 0, 0, 0};
  Vec3d tv = o - p0;
  double b1 = dot(tv, pv) / det;
  Vec3d qv = cross(tv, e1);
  double b2 = dot(d, qv) / det;
  double t = dot(e2, qv) / det;
  return {true, t, b1, b2};
}

TEST(GeometryTriangle, AgreesWithDoublePrecisionReferenceInGeneralPosition) {
  std::mt19937 rng(12345);
  std::uniform_real_distribution<double> u(-1.0, 1.0);
  int hits = 0, misses = 0;
  for (int i = 0; i < 20000; ++i) {
    Vec3d p[3];
    for (auto& q : p) q = RoundToFloat({u(rng), u(rng), u(rng)});
    Vec3d o = RoundToFloat({3 * u(rng), 3 * u(rng), 3 * u(rng)});
    // Aim at a point of the plane with barycentrics in [-0.5, 1.5]: about half inside.
    double c1 = 0.5 + u(rng), c2 = 0.5 + u(rng);
    Vec3d target = p[0] + (p[1] - p[0]) * c1 + (p[2] - p[0]) * c2;
    Vec3d d = RoundToFloat((target - o) * (0.25 + 2 * std::fabs(u(rng))));
    RefHit r = ReferenceTriangle(o, d, p[0], p[1], p[2]);
    Vec3d n = cross(p[1] - p[0], p[2] - p[0]);
    double cosang = std::fabs(dot(n, d)) / (length(n) * length(d));
    if (!r.valid || cosang < 1e-2 || length(n) < 1e-3) continue;
    TriHit h = HitTriangle(F3(o), F3(d), F3(p[0]), F3(p[1]), F3(p[2]), kInf, 0);
    double bmin = std::min({1 - r.b1 - r.b2, r.b1, r.b2});
    // Away from the edges (1e-4 in barycentrics, far above float rounding) the answer is
    // unambiguous; t and the barycentrics must match to float accuracy (relative 1e-5
    // leaves room for the ~10 roundings of the sheared test on ill-conditioned rays).
    if (bmin > 1e-4 && r.t > 1e-3) {
      ++hits;
      ASSERT_EQ(h.hit, 1) << "ray " << i;
      EXPECT_NEAR(h.t, r.t, 1e-5 * r.t + 1e-6) << "ray " << i;
      EXPECT_NEAR(h.b1, r.b1, 1e-4) << "ray " << i;
      EXPECT_NEAR(h.b2, r.b2, 1e-4) << "ray " << i;
    } else if (bmin < -1e-4 || r.t < -1e-3) {
      ++misses;
      ASSERT_EQ(h.hit, 0) << "ray " << i << " ref t " << r.t << " bmin " << bmin;
    }
  }
  EXPECT_GT(hits, 1500);
  EXPECT_GT(misses, 5000);
}

TEST(GeometryTriangle, CullMatchesGeometricNormalInGeneralPosition) {
  // Front face: the geometric normal cross(v1-v0, v2-v0) points to the ray origin.
  std::mt19937 rng(777);
  std::uniform_real_distribution<double> u(-1.0, 1.0);
  int front = 0, back = 0;
  for (int i = 0; i < 5000; ++i) {
    Vec3d p[3];
    for (auto& q : p) q = RoundToFloat({u(rng), u(rng), u(rng)});
    Vec3d n = cross(p[1] - p[0], p[2] - p[0]);
    if (length(n) < 0.05) continue;
    Vec3d c = (p[0] + p[1] + p[2]) * (1.0 / 3.0);
    Vec3d o = RoundToFloat({3 * u(rng), 3 * u(rng), 3 * u(rng)});
    Vec3d d = c - o;
    double side = dot(n, o - p[0]);
    if (std::fabs(side) < 0.05 * length(n)) continue;
    TriHit h0 = HitTriangle(F3(o), F3(d), F3(p[0]), F3(p[1]), F3(p[2]), kInf, 0);
    TriHit h1 = HitTriangle(F3(o), F3(d), F3(p[0]), F3(p[1]), F3(p[2]), kInf, 1);
    ASSERT_EQ(h0.hit, 1) << "ray " << i;
    EXPECT_NEAR(h0.t, 1.0, 1e-5) << "ray " << i;
    if (side > 0) {
      ++front;
      EXPECT_EQ(h1.hit, 1) << "front face culled, ray " << i;
    } else {
      ++back;
      EXPECT_EQ(h1.hit, 0) << "back face not culled, ray " << i;
    }
  }
  EXPECT_GT(front, 1000);
  EXPECT_GT(back, 1000);
}

}  // namespace
}  // namespace rt
