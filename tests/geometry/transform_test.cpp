// Transforms (mat4.h) and their use by the scene path: rotations are right-handed,
// translations move points and not vectors, inverses, and ellipsoid normals.
#include <gtest/gtest.h>

#include <cmath>
#include <random>

#include "support/geometry_harness.h"

namespace rt {
namespace {

using namespace test;

TEST(GeometryTransform, RightHandedQuarterTurns) {
  // cos(90 degrees) in double is 6e-17; everything else is exact.
  ExpectVecNear(Mat4::rotation(90, {0, 0, 1}).point({1, 0, 0}), {0, 1, 0}, 1e-15);
  ExpectVecNear(Mat4::rotation(90, {0, 0, 1}).point({0, 1, 0}), {-1, 0, 0}, 1e-15);
  ExpectVecNear(Mat4::rotation(90, {0, 0, 7}).point({1, 0, 0}), {0, 1, 0}, 1e-15);
  ExpectVecNear(Mat4::rotation(90, {1, 0, 0}).point({0, 1, 0}), {0, 0, 1}, 1e-15);
  ExpectVecNear(Mat4::rotation(90, {0, 1, 0}).point({0, 0, 1}), {1, 0, 0}, 1e-15);
  ExpectVecNear(Mat4::rotation(-90, {0, 0, 1}).point({1, 0, 0}), {0, -1, 0}, 1e-15);
  // 120 degrees about (1,1,1) cycles the axes.
  ExpectVecNear(Mat4::rotation(120, {1, 1, 1}).point({1, 0, 0}), {0, 1, 0}, 1e-15);
}

TEST(GeometryTransform, TranslationAffectsPointsNotVectors) {
  Mat4 m = Mat4::translation({1, -2, 3}) * Mat4::scaling({2, 3, 4});
  ExpectVecNear(m.point({1, 1, 1}), {3, 1, 7}, 0);
  ExpectVecNear(m.vector({1, 1, 1}), {2, 3, 4}, 0);
  EXPECT_TRUE(Mat4().is_identity());
  EXPECT_FALSE(Mat4::translation({0, 0, 1e-300}).is_identity());
}

TEST(GeometryTransform, AffineInverseTimesMatrixIsIdentity) {
  std::mt19937 rng(3);
  std::uniform_real_distribution<double> u(-1, 1);
  for (int i = 0; i < 200; ++i) {
    Mat4 m = Mat4::translation({100 * u(rng), 100 * u(rng), 100 * u(rng)}) *
             Mat4::rotation(180 * u(rng), {u(rng), u(rng), u(rng) + 2}) *
             Mat4::scaling({0.1 + std::fabs(u(rng)), 0.5 + u(rng) * 0.4, 3 + u(rng)}) *
             Mat4::rotation(180 * u(rng), {u(rng) + 2, u(rng), u(rng)});
    bool ok = false;
    Mat4 inv = m.affine_inverse(&ok);
    ASSERT_TRUE(ok);
    Mat4 a = inv * m, b = m * inv;
    for (int r = 0; r < 4; ++r)
      for (int c = 0; c < 4; ++c) {
        // Translations up to 100 and scales down to 0.1: 1e-12 is ~1e4 ulps of headroom.
        EXPECT_NEAR(a(r, c), r == c ? 1.0 : 0.0, 1e-12) << "matrix " << i;
        EXPECT_NEAR(b(r, c), r == c ? 1.0 : 0.0, 1e-12) << "matrix " << i;
      }
  }
  bool ok = true;
  Mat4::scaling({1, 0, 1}).affine_inverse(&ok);
  EXPECT_FALSE(ok);
}

TEST(GeometryTransform, EllipsoidNormalsThroughScenePath) {
  // Unit sphere scaled by (a, b, c) = (2, 1, 1), then optionally rotated and moved: in the
  // ellipsoid's own frame the normal at x is normalize(x / a^2, y / b^2, z / c^2). The
  // rotated case also catches normals transformed by the inverse instead of its transpose.
  // Tolerance 1e-5: the point is rebuilt by normalizing in object space and the normal
  // goes through float matrix rows (a few float roundings of O(1) values).
  struct Case {
    Vec3d centre;
    Mat4 rotation;
  };
  const Case cases[] = {{{0, 0, 0}, Mat4()},
                        {{5, -3, 2}, Mat4()},
                        {{5, -3, 2}, Mat4::rotation(40, {1, 1, 0})},
                        {{-1, 2, 0.5}, Mat4::rotation(-75, {0.2, -1, 0.6})}};
  for (const Case& c : cases) {
    SceneDesc s = BaseScene();
    AddSphere(s, Mat4::translation(c.centre) * c.rotation * Mat4::scaling({2, 1, 1}));
    FlatScene scene = Flatten(s);
    SceneData sd = scene.view();
    bool ok = false;
    Mat4 unrotate = c.rotation.affine_inverse(&ok);
    ASSERT_TRUE(ok);
    std::mt19937 rng(11);
    std::normal_distribution<double> g;
    std::uniform_real_distribution<double> u(-1, 1);
    int hits = 0;
    for (int i = 0; i < 2000; ++i) {
      Vec3d o = c.centre + normalize({g(rng), g(rng), g(rng)}) * 6.0;
      Vec3d aim = c.centre + c.rotation.vector({1.9 * u(rng), 0.9 * u(rng), 0.9 * u(rng)});
      Ray ray = MakeRay(F3(o), F3(aim - o), kInf, 0);
      Hit hit{};  // A sphere hit leaves b1 and b2 unset.
      if (!IntersectScene(&sd, &ray, 0, 0, &hit)) continue;
      ++hits;
      SurfacePoint sp = ComputeSurface(&sd, ray, hit);
      Vec3d x = unrotate.vector(D3(sp.p) - c.centre);  // In the ellipsoid's frame.
      EXPECT_NEAR(x.x * x.x / 4 + x.y * x.y + x.z * x.z, 1.0, 1e-5);
      Vec3d n = c.rotation.vector(normalize({x.x / 4, x.y, x.z}));
      ExpectVecNear(D3(sp.n), n, 1e-5);
      ExpectVecNear(D3(sp.ng), n, 1e-5);
      // The hit point also lies on the ray (|p| <= 8: 1e-5 relative).
      ExpectVecNear(D3(RayAt(ray, hit.t)), D3(sp.p), 8e-5);
    }
    EXPECT_GT(hits, 1500);
  }
}

}  // namespace
}  // namespace rt
