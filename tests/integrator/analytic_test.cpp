// Scenes whose correct pixel value is known in closed form, rendered by the CPU
// reference (pbrt-v4's habit: test the estimator against the integral it estimates).
#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>

#include "prepare/flat_scene.h"
#include "support/device_harness.h"
#include "support/test_scene.h"

namespace {

Material Diffuse(double kd) {
  Material m{};
  m.diffuse = make_float3(kd, kd, kd);
  m.phong_exponent = 1;
  m.refraction_index = 1;
  return m;
}

using rt::test::PointCamera;

rt::MeshDesc Quad(double half, double z) {
  rt::MeshDesc m;
  m.positions = {{-half, -half, z}, {half, -half, z}, {half, half, z}, {-half, half, z}};
  m.triangles = {{0, 1, 2}, {0, 2, 3}};
  return m;
}

// A diffuse floor (z = 0, kd given) whose point at the origin a point camera at height 5
// sees; the tests add their lights.
rt::SceneDesc FloorSeenFromAbove(double kd, int samples) {
  rt::SceneDesc s;
  s.cameras.push_back(PointCamera({0, 0, 5}, samples));
  s.materials.push_back(Diffuse(kd));
  s.meshes.push_back(Quad(10, 0));
  rt::ObjectDesc floor;
  floor.mesh = 0;
  s.objects.push_back(floor);
  return s;
}

struct PixelStats {
  double mean, standard_error;
};

PixelStats RenderOnePixel(const rt::SceneDesc& scene, uint32_t seed = 0) {
  rt::RenderOptions opt;
  opt.seed = seed;
  rt::FlatScene flat = rt::prepare_scene(scene, opt);
  rt::prepare_camera(flat, scene, 0, opt);
  rt::RenderResult r = rt::test::render_cpu(flat, 1);
  const PixelAccum& a = r.accum[0];
  double n = a.sum_sq.w, mean = a.sum.x / a.sum.w;
  double var = (a.sum_sq.x / n - mean * mean) * n / (n - 1);
  return {mean, std::sqrt(std::max(var, 0.0) / n)};
}

// Irradiance at a point below the corner of an a x b rectangle at height h that emits
// radiance L: pi * L * the differential form factor to a parallel rectangle.
double CornerIrradiance(double L, double a, double b, double h) {
  double x = a / h, y = b / h;
  double f = (x / std::sqrt(1 + x * x) * std::atan(y / std::sqrt(1 + x * x)) +
              y / std::sqrt(1 + y * y) * std::atan(x / std::sqrt(1 + y * y))) /
             (2 * M_PI);
  return M_PI * L * f;
}

TEST(Analytic, AreaLightIrradianceMatchesTheFormFactor) {
  // A floor at z=0 with kd = 1; a square light of side 2 at height 1.5 above (0.3, 0.2)
  // facing down; the camera sees the floor point at the origin.
  rt::SceneDesc s = FloorSeenFromAbove(1, 4096);
  const double L = 1000, side = 2, h = 1.5, cx = 0.3, cy = 0.2;
  AreaLight light{};
  light.corner = {cx - side / 2, cy - side / 2, h};
  light.edge1 = make_float3(side, 0, 0);
  light.edge2 = make_float3(0, side, 0);
  light.normal = make_float3(0, 0, -1);
  light.radiance = make_float3(L, L, L);
  light.area = side * side;
  s.area_lights.push_back(light);
  // The origin splits the light into four rectangles, each with a corner above it.
  double e = 0;
  for (double wx : {side / 2 + cx, side / 2 - cx})
    for (double wy : {side / 2 + cy, side / 2 - cy}) e += CornerIrradiance(L, wx, wy, h);
  PixelStats p = RenderOnePixel(s);
  // 4.4 standard errors: a correct estimator fails with probability about 1e-5.
  EXPECT_NEAR(p.mean, e, 4.4 * p.standard_error + 1e-4 * e)
      << "closed form " << e << ", estimate " << p.mean << " +- " << p.standard_error;
  EXPECT_GT(p.standard_error, 0);  // The estimator really sampled the light.
  std::printf("irradiance: closed form %.4f, estimate %.4f +- %.4f\n", e, p.mean, p.standard_error);
}

TEST(Analytic, MovingSphereLeavesItsTimeAveragedCoverage) {
  // A sphere of radius 1 at z=-5 moves from x=-1.5 to x=+2.5 (motion 4) over the shutter;
  // the ray through the origin along -z is covered while |x(t)| <= 1, i.e. for half of
  // the shutter. The sphere is lit by ambient light only, so the pixel is 100 * 0.5.
  rt::SceneDesc s;
  s.cameras.push_back(PointCamera({0, 0, 0}, 4096));
  Material m{};
  m.ambient = make_float3(1, 1, 1);
  m.refraction_index = 1;
  s.materials.push_back(m);
  s.ambient = {100, 100, 100};
  rt::ObjectDesc sphere;
  sphere.kind = rt::ObjectDesc::kSphere;
  sphere.transform = rt::Mat4::translation({-1.5, 0, -5});
  sphere.motion = {4, 0, 0};
  s.objects.push_back(sphere);
  PixelStats p = RenderOnePixel(s);
  // Time is stratified over 4096 intervals, so the error is far below one interval.
  EXPECT_NEAR(p.mean, 50.0, 100.0 / 4096 * 2);
}

TEST(Analytic, PointLightFollowsTheInverseSquareLaw) {
  // kd = 0.5, intensity 1000 at height 2 directly above the seen point: 0.5 * 1000 / 4.
  rt::SceneDesc s = FloorSeenFromAbove(0.5, 1);
  PointLight pl{};
  pl.position = {0, 0, 2};
  pl.intensity = make_float3(1000, 1000, 1000);
  s.point_lights.push_back(pl);
  EXPECT_FLOAT_EQ(static_cast<float>(RenderOnePixel(s).mean), 125.0f);
}

}  // namespace
