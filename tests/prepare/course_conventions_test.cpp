// Conventions of the course's renderer that its images show to the level of single pixels
// (the reference tests match those images byte for byte only with them): a shadow ray
// leaves along the shading normal. The ray offset of the epsilon alone is checked in
// tests/geometry/ray_offset_test.cpp. The course's float camera rays are checked by the
// reference tests (tests/course/course_scenes.txt), whose thresholds they raised; here,
// where they stop being used.
#include <gtest/gtest.h>

#include "prepare/course_camera.h"
#include "prepare/flat_scene.h"
#include "support/device_harness.h"
#include "support/test_scene.h"

namespace rt {
namespace {

bool Faithful(const CameraDesc& c) {
  Camera cam{};
  set_course_camera(cam, c);
  return course_camera_is_faithful(cam, c);
}

// A camera with a film pixel 1.406e-3 wide at distance 1, placed where grass_desert's is
// (368 units out: float's spacing bound 368 * 2^-23 = 4.4e-5, 1/32 of a pixel), keeps the
// course's rays; 1e5 units out (0.012, 8.5 pixels) it keeps the camera-relative ones.
TEST(CourseCamera, IsUsedOnlyWhereFloatResolvesTheFilm) {
  CameraDesc c;
  c.position = {-367.6, 0.35, 162.9};
  c.gaze = {1, 0, 0};
  c.up = {0, 1, 0};
  c.left = -1.35;
  c.right = 1.35;
  c.bottom = -0.76;
  c.top = 0.76;
  c.width = 1920;
  c.height = 1080;
  EXPECT_TRUE(Faithful(c));
  c.position = {1e5, 0.35, 162.9};
  EXPECT_FALSE(Faithful(c));
  // The bound is a twentieth of a pixel, reached 590 units out for this film: 2,100 units
  // (2.5e-4, 1/5.6 of a pixel) fail, 300 units (3.6e-5, 1/39) pass.
  c.position = {2100, 0, 0};
  EXPECT_FALSE(Faithful(c));
  c.position = {300, 0, 0};
  EXPECT_TRUE(Faithful(c));
}

Material Diffuse() {
  Material m{};
  m.diffuse = make_float3(1, 1, 1);
  m.phong_exponent = 1;
  m.refraction_index = 1;
  return m;
}

// The floor point at the origin of a smooth mesh whose shading normal there leans towards
// +x (a steep wall shares the vertex at (1, 1, 0)), seen from above, lit by a point light
// at (0, 3, 3). A small blocker at y = 0.3 lies across the shadow segment that leaves along
// the geometric normal (x = 0) but not across the one that leaves along the shading normal
// (x = 0.026 (1 - s) with the epsilon 0.1).
SceneDesc LeaningNormalScene() {
  SceneDesc s;
  s.cameras.push_back(test::PointCamera({0, 0, 5}, 1));
  s.materials.push_back(Diffuse());
  s.shadow_epsilon = 0.1;
  MeshDesc tent;
  tent.positions = {{-1, -1, 0}, {1, -1, 0}, {1, 1, 0}, {-1, 1, 0}, {1.5, 0, 2}};
  tent.triangles = {{0, 1, 2}, {0, 2, 3}, {1, 2, 4}};
  tent.smooth = true;
  MeshDesc blocker;
  blocker.positions = {{-0.05, 0.3, 0.2}, {0.01, 0.3, 0.2}, {0.01, 0.3, 0.6}};
  blocker.triangles = {{0, 1, 2}};
  s.meshes = {tent, blocker};
  for (int mesh = 0; mesh < 2; ++mesh) {
    ObjectDesc o;
    o.mesh = mesh;
    s.objects.push_back(o);
  }
  s.point_lights.push_back({{0, 3, 3}, make_float3(100, 100, 100)});
  return s;
}

double RenderRed(const SceneDesc& s, bool geometric_offset) {
  RenderOptions opt;
  opt.geometric_offset = geometric_offset;
  FlatScene flat = prepare_scene(s, opt);
  prepare_camera(flat, s, 0, opt);
  RenderResult r = test::render_cpu(flat, 1);
  return r.accum[0].sum.x / r.accum[0].sum.w;
}

TEST(CourseShadowOffset, LeavesAlongTheShadingNormal) {
  const SceneDesc s = LeaningNormalScene();
  // Shading normal at the origin: halfway between (0, 0, 1) and the wall vertex's
  // area-weighted normal (4, 0, 7) / |.|; lit, the pixel is I / d^2 * n.wi.
  const double nc = std::sqrt(65.0), nx = 0.5 * 4 / nc, nz = 0.5 + 0.5 * 7 / nc;
  const double cos_i = (nz * 3 / std::sqrt(18.0)) / std::sqrt(nx * nx + nz * nz);
  EXPECT_NEAR(RenderRed(s, false), 100.0 / 18.0 * cos_i, 1e-4);
  EXPECT_EQ(RenderRed(s, true), 0.0);  // --shadow-offset geometric: the blocker shadows it.
}

}  // namespace
}  // namespace rt
