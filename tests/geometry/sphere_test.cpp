// IntersectUnitSphere and spheres through the scene path: exact distances on axis rays, the
// far root from inside, tangents and tmax, and accuracy far from the origin.
#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <random>

#include "support/geometry_harness.h"

namespace rt {
namespace {

using namespace test;

TEST(GeometrySphere, AxisRaysGiveExactDistances) {
  float t = -1;
  ASSERT_EQ(IntersectUnitSphere(make_float3(0, 0, 5), make_float3(0, 0, -1), kInf, &t), 1);
  EXPECT_EQ(t, 4.0f);
  // Non-unit direction: t in units of the direction.
  ASSERT_EQ(IntersectUnitSphere(make_float3(0, 0, 5), make_float3(0, 0, -2), kInf, &t), 1);
  EXPECT_EQ(t, 2.0f);
  ASSERT_EQ(IntersectUnitSphere(make_float3(-3, 0, 0), make_float3(1, 0, 0), kInf, &t), 1);
  EXPECT_EQ(t, 2.0f);
  ASSERT_EQ(IntersectUnitSphere(make_float3(0, 9, 0), make_float3(0, -0.5f, 0), kInf, &t), 1);
  EXPECT_EQ(t, 16.0f);
  // Off-axis but exact: from (0.6, 0, 5) along -z the surface is at z = 0.8.
  ASSERT_EQ(IntersectUnitSphere(make_float3(0.6f, 0, 5), make_float3(0, 0, -1), kInf, &t), 1);
  EXPECT_NEAR(t, 4.2f, 4.2e-7);  // 0.8 is not dyadic: one rounding of sqrt.
}

TEST(GeometrySphere, OriginInsideGivesTheFarRoot) {
  float t = -1;
  ASSERT_EQ(IntersectUnitSphere(make_float3(0, 0, 0.5f), make_float3(0, 0, 1), kInf, &t), 1);
  EXPECT_EQ(t, 0.5f);
  ASSERT_EQ(IntersectUnitSphere(make_float3(0, 0, 0.5f), make_float3(0, 0, -1), kInf, &t), 1);
  EXPECT_EQ(t, 1.5f);
  ASSERT_EQ(IntersectUnitSphere(make_float3(0, 0, 0), make_float3(0, 0.25f, 0), kInf, &t), 1);
  EXPECT_EQ(t, 4.0f);
  ASSERT_EQ(IntersectUnitSphere(make_float3(0, 0, 0), make_float3(-1, 0, 0), kInf, &t), 1);
  EXPECT_EQ(t, 1.0f);
}

TEST(GeometrySphere, TangentMissBehindAndTmax) {
  float t = -1;
  // Tangent at (1, 0, 0): the discriminant is exactly 0, a single touching hit at t = 5.
  ASSERT_EQ(IntersectUnitSphere(make_float3(1, 0, 5), make_float3(0, 0, -1), kInf, &t), 1);
  EXPECT_EQ(t, 5.0f);
  EXPECT_EQ(IntersectUnitSphere(make_float3(std::nextafter(1.0f, 2.0f), 0, 5),
                                make_float3(0, 0, -1), kInf, &t),
            0);
  EXPECT_EQ(IntersectUnitSphere(make_float3(1.5f, 0, 5), make_float3(0, 0, -1), kInf, &t), 0);
  EXPECT_EQ(IntersectUnitSphere(make_float3(0, 0.75f, -3), make_float3(1, 0, 0), kInf, &t), 0);
  // Sphere behind the origin.
  EXPECT_EQ(IntersectUnitSphere(make_float3(0, 0, 5), make_float3(0, 0, 1), kInf, &t), 0);
  // tmax: the near root 4 must be < tmax; tmax = 4 rejects both roots (the far one is 6).
  EXPECT_EQ(IntersectUnitSphere(make_float3(0, 0, 5), make_float3(0, 0, -1), 4.0f, &t), 0);
  ASSERT_EQ(IntersectUnitSphere(make_float3(0, 0, 5), make_float3(0, 0, -1), 5.0f, &t), 1);
  EXPECT_EQ(t, 4.0f);
}

// Distance along (o, d) to the sphere |x - c| = r in double, nearest positive root.
double ReferenceSphere(Vec3d o, Vec3d d, Vec3d c, double r);

TEST(GeometrySphere, FarAwayUnitSphereStaysAccurateInRadiusUnits) {
  // From 1e3 and 1e4 radii away, b^2 - ac cancels all but a few bits (a textbook solver is
  // off by ~0.5 radii at 1e3 and misses grazing rays); the distance-to-line form stays
  // within a few ulps of the origin's magnitude: measured 2.3e-4 and 2.8e-3 radii.
  SceneDesc s = BaseScene();
  AddSphere(s, Mat4());
  FlatScene scene = Flatten(s);
  // --hit-point surface projects the point back onto the sphere; the default (ray, the
  // course's o + t d) rounds it at the distance travelled.
  FlatScene surface_scene = Flatten(s);
  surface_scene.header.flags &= ~RT_FLAG_RAY_HIT_POINT;
  double worst_ray[2] = {0, 0};
  std::mt19937 rng(17);
  std::normal_distribution<double> g;
  for (double dist : {1e3, 1e4}) {
    const double tol = dist * 2e-6;  // 2e-3 and 2e-2 radii.
    for (int i = 0; i < 1000; ++i) {
      Vec3d eye = normalize({g(rng), g(rng), g(rng)});
      Vec3d side = normalize(cross(eye, {g(rng), g(rng), g(rng)}));
      float3 o = F3(eye * dist);
      Vec3d aim = side * ((i % 100) / 100.0);
      float3 d = F3(normalize(aim - D3(o)));
      double expect = ReferenceSphere(D3(o), D3(d), {0, 0, 0}, 1.0);
      if (expect < 0) continue;
      float t = -1;
      ASSERT_EQ(IntersectUnitSphere(o, d, kInf, &t), 1) << "distance " << dist << " ray " << i;
      EXPECT_NEAR(t, expect, tol) << "distance " << dist << " ray " << i;
      // With --hit-point surface the point is projected back onto the sphere, so its error
      // does not grow with the distance travelled; the default's o + t d is off by about
      // two ulps of the distance (measured 1.3e-4 at 1e3, 2.2e-3 at 1e4: t's error and the
      // rounding of o + t d), its normal the sphere's all the same.
      Hit hit;
      ASSERT_TRUE(Trace(scene, o, d, kInf, 0, &hit));
      SceneData sd = surface_scene.view();
      SurfacePoint sp = ComputeSurface(&sd, MakeRay(o, d, kInf, 0), hit);
      EXPECT_NEAR(length(D3(sp.p)), 1.0, 1e-6);
      ExpectVecNear(D3(sp.n), D3(sp.p), 1e-6);
      SceneData sd_ray = scene.view();
      SurfacePoint sp_ray = ComputeSurface(&sd_ray, MakeRay(o, d, kInf, 0), hit);
      const double off = std::fabs(length(D3(sp_ray.p)) - 1.0);
      EXPECT_LE(off, dist * 4e-7) << "distance " << dist << " ray " << i;  // 3.4 ulps.
      ExpectVecNear(D3(sp_ray.n), D3(sp.n), 0);
      worst_ray[dist > 5e3] = std::max(worst_ray[dist > 5e3], off);
    }
  }
  std::printf("[ sphere ] o + t d off the unit sphere: %.3g at 1e3, %.3g at 1e4\n", worst_ray[0],
              worst_ray[1]);
  EXPECT_GT(worst_ray[1], 1e-5);  // The default really is o + t d.
}

double ReferenceSphere(Vec3d o, Vec3d d, Vec3d c, double r) {
  Vec3d oc = o - c;
  double a = dot(d, d);
  double tc = -dot(oc, d) / a;
  Vec3d l = oc + d * tc;
  double disc = (r * r - dot(l, l)) / a;
  if (disc < 0) return -1;
  double root = std::sqrt(disc);
  return tc - root > 0 ? tc - root : tc + root;
}

TEST(GeometrySphere, LargeDistantSphereThroughScenePath) {
  // Radius 1e4 seen from 1e5 away: the ray meets a unit sphere 10 radii away in object
  // space, with a direction of length 1e-4. Relative 1e-5 is what float inputs allow.
  const Vec3d centre{3e4, -2e4, 1e4};
  const double radius = 1e4;
  SceneDesc s = BaseScene();
  AddSphere(s, Mat4::translation(centre) * Mat4::scaling({radius, radius, radius}));
  FlatScene scene = Flatten(s);
  std::mt19937 rng(5);
  std::normal_distribution<double> g;
  int hits = 0;
  for (int i = 0; i < 200; ++i) {
    Vec3d eye = normalize({g(rng), g(rng), g(rng)});
    Vec3d o = centre + eye * 1e5;
    // Aim at closest-approach distance h * radius, h from 0 to 0.99.
    Vec3d side = normalize(cross(eye, {g(rng), g(rng), g(rng)}));
    double h = (i % 100) / 100.0;
    Vec3d aim = centre + side * (h * radius);
    float3 of = F3(o), df = F3(normalize(aim - o));
    double expect = ReferenceSphere(D3(of), D3(df), centre, radius);
    ASSERT_GT(expect, 0);
    Hit hit;
    ASSERT_TRUE(Trace(scene, of, df, kInf, 0, &hit)) << "ray " << i;
    EXPECT_EQ(hit.primitive, -1);
    EXPECT_NEAR(hit.t, expect, 1e-5 * expect) << "ray " << i << " h " << h;
    // The reconstructed point is on the sphere.
    SceneData sd = scene.view();
    SurfacePoint sp = ComputeSurface(&sd, MakeRay(of, df, kInf, 0), hit);
    EXPECT_NEAR(length(D3(sp.p) - centre), radius, 1e-5 * radius);
    ++hits;
  }
  EXPECT_EQ(hits, 200);
  // Closest approach 1.001 radii misses; 0.999 radii hits.
  Vec3d o = centre + Vec3d{0, 0, 1e5};
  for (double h : {1.001, 0.999}) {
    double sin_a = h * radius / 1e5;
    Hit hit;
    EXPECT_EQ(Trace(scene, F3(o), F3(sin_a, 0, -std::sqrt(1 - sin_a * sin_a)), kInf, 0, &hit),
              h < 1)
        << "closest approach " << h << " radii";
  }
}

}  // namespace
}  // namespace rt
