// --hit-point ray|surface (cl/geometry/surface.h): by default (`ray`) a hit point is formed as
// origin + t * direction, as the course's renderer does, which decides some pixels of its
// images (docs/course_pixel_residue.md); `surface` rebuilds it from the primitive, for
// tools/explain_ensemble.py's member. The option changes the point and nothing else, and
// reaches both devices bit for bit.
#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <cstring>
#include <random>
#include <string>

#include "support/device_harness.h"
#include "support/geometry_harness.h"
#include "support/stability_scenes.h"

namespace rt {
namespace {

using Dev = rt::Device;

bool SameBits(float3 a, float3 b) { return std::memcmp(&a, &b, sizeof(a)) == 0; }

// A quad 3,000 units down the -z axis, seen from the origin: origin + t * direction rounds at
// ulp(3000) = 2.4e-4 per coordinate, while the barycentric point rounds at the quad's own
// coordinates. By default (`ray`) the point is RayAt(ray, t) to the bit and the normals are
// those of `surface`, whose point stays closer to the quad's plane.
TEST(HitPoint, RayModeIsOriginPlusTTimesDirectionAndChangesOnlyThePoint) {
  rt::SceneDesc s = rt::test::BaseScene();
  const double z = -3000;
  rt::test::AddMeshObject(
      s,
      rt::test::AddMesh(s, {{-900, -900, z}, {900, -900, z}, {900, 900, z}, {-900, 900, z}},
                        {{{0, 1, 2}}, {{0, 2, 3}}}),
      rt::Mat4());
  rt::FlatScene surface = rt::test::Flatten(s);
  rt::FlatScene ray_mode = rt::test::Flatten(s);
  ASSERT_TRUE(rt::RenderOptions().ray_hit_point);  // The course's point is the default.
  ASSERT_NE(ray_mode.header.flags & RT_FLAG_RAY_HIT_POINT, 0);
  surface.header.flags &= ~RT_FLAG_RAY_HIT_POINT;
  SceneData sd_surface = surface.view(), sd_ray = ray_mode.view();
  std::mt19937 rng(5);
  std::uniform_real_distribution<double> u(-0.25, 0.25);
  int hits = 0, moved = 0;
  double surface_off = 0, ray_off = 0;  // Largest distance to the plane z = -3000.
  for (int i = 0; i < 2000; ++i) {
    Ray ray =
        MakeRay(make_float3(0, 0, 0), Normalize(make_float3(u(rng), u(rng), -1.0f)), 1e30f, 0);
    Hit hit{};
    if (!IntersectScene(&sd_surface, &ray, 0, 0, &hit)) continue;
    ++hits;
    SurfacePoint a = ComputeSurface(&sd_surface, ray, hit);
    SurfacePoint b = ComputeSurface(&sd_ray, ray, hit);
    ASSERT_TRUE(SameBits(b.p, RayAt(ray, hit.t)));
    ASSERT_TRUE(SameBits(a.n, b.n) && SameBits(a.ng, b.ng) && SameBits(a.wo, b.wo));
    moved += !SameBits(a.p, b.p);
    surface_off = std::max(surface_off, std::fabs(a.p.z - z));
    ray_off = std::max(ray_off, std::fabs(b.p.z - z));
  }
  std::printf("[ hit point ] %d hits: %d points moved; off the plane: surface %.3g, ray %.3g\n",
              hits, moved, surface_off, ray_off);
  EXPECT_EQ(hits, 2000);
  EXPECT_GT(moved, 1000);
  EXPECT_EQ(surface_off, 0.0);  // The quad's z is a float; barycentrics keep it exactly.
  EXPECT_GT(ray_off, 0.0);
}

// A lit sphere on a floor 1e4 units from the origin in the world's own frame, where the two
// points differ by float's spacing there (about 1e-3): both devices render `ray` bit for bit
// alike, and differently from `surface`.
TEST(HitPoint, RayModeReachesBothDevicesBitIdentically) {
  using stab::V;
  stab::Builder b;
  rt::SceneDesc& s = b.scene();
  s.ambient = stab::Gray(8);
  const rt::Vec3d o = V(1e4, 1e4, 1e4);
  int red = b.material(stab::Plain(V(0.8, 0.25, 0.2), stab::Gray(0.5), 60, stab::Gray(1)));
  int floor = b.material(stab::Plain(stab::Gray(0.6), {}, 1, stab::Gray(1)));
  b.sphere(o + V(0, 0.3, 0), 0.3, red);
  b.quad(o + V(-2, 0, -2), o + V(-2, 0, 2), o + V(2, 0, 2), o + V(2, 0, -2), floor);
  b.point_light(o + V(1.5, 2.5, 2), stab::Gray(600));
  b.camera(o + V(0.4, 1.1, 2.8), o + V(0, 0.3, 0), V(0, 1, 0), 0.14, 0.14, 1, 48, 48);
  rt::RenderOptions opt;
  opt.camera_frame = false;
  auto render = [&](Dev d, bool ray_point) {
    opt.ray_hit_point = ray_point;
    rt::FlatScene f = rt::prepare_scene(s, opt);
    rt::prepare_camera(f, s, 0, opt);
    std::string why;
    return rt::test::render_on(*rt::test::shared_device(d, &why), f);
  };
  rt::RenderResult surface = render(Dev::kCpu, false), ray_cpu = render(Dev::kCpu, true);
  size_t changed = 0;
  for (size_t i = 0; i < surface.accum.size(); ++i)
    changed += std::memcmp(&surface.accum[i].sum, &ray_cpu.accum[i].sum, sizeof(float4)) != 0;
  std::printf("[ hit point ] ray against surface: %zu of %zu pixels differ\n", changed,
              surface.accum.size());
  EXPECT_GT(changed, 100u);
  std::string why;
  if (!rt::test::shared_device(Dev::kOpenCl, &why)) GTEST_SKIP() << "no OpenCL device: " << why;
  rt::RenderResult ray_cl = render(Dev::kOpenCl, true);
  ASSERT_EQ(ray_cl.accum.size(), ray_cpu.accum.size());
  for (size_t i = 0; i < ray_cpu.accum.size(); ++i)
    ASSERT_EQ(std::memcmp(&ray_cpu.accum[i].sum, &ray_cl.accum[i].sum, sizeof(float4)), 0)
        << "pixel " << i;
}

}  // namespace
}  // namespace rt
