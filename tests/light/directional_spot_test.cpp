// The lights of assignment 5 (cl/light/directional.h, cl/light/spot.h) against closed
// forms: samples of each type, and rendered pixels of a diffuse floor under them.
#include <gtest/gtest.h>

#include <cmath>

#include "cl/light/light.h"
#include "integrator/render.h"
#include "prepare/flat_scene.h"
#include "support/device_harness.h"

namespace rt {
namespace {

float3 V(float x, float y, float z) { return make_float3(x, y, z); }

Light Directional(float3 direction, float3 radiance, float distance) {
  Light l{};
  l.type = RT_LIGHT_DIRECTIONAL;
  l.normal = direction;
  l.emission = radiance;
  RT_LIGHT_REACH(&l) = distance;
  return l;
}

// A spot light at `position` shining along unit `axis`, with full angles in degrees.
Light Spot(float3 position, float3 axis, float intensity, double coverage, double falloff) {
  Light l{};
  l.type = RT_LIGHT_SPOT;
  l.position = position;
  l.normal = axis;
  l.emission = V(intensity, intensity, intensity);
  RT_SPOT_COS_FALLOFF(&l) = static_cast<float>(std::cos(falloff * M_PI / 360));
  RT_SPOT_COS_COVERAGE(&l) = static_cast<float>(std::cos(coverage * M_PI / 360));
  return l;
}

TEST(LightDirectional, SameIrradianceEverywhereFromOneDirection) {
  Light l = Directional(V(0, 0, -1), V(3, 4, 5), 100);
  for (float x : {0.0f, 10.0f, -1000.0f}) {
    LightSampleContext ctx = MakeLightSampleContext(V(x, 2, 0), V(0, 0, 1), V(0, 0, 1));
    LightSample ls = SampleDirectionalLight(&l, &ctx);
    ASSERT_TRUE(ls.valid);
    EXPECT_EQ(ls.wi.z, 1.0f);  // Towards the light: against its direction of travel.
    EXPECT_EQ(ls.irradiance.x, 3.0f);
    EXPECT_EQ(ls.irradiance.z, 5.0f);
    EXPECT_EQ(ls.p_light.z, 100.0f);  // The shadow segment reaches past the scene.
    EXPECT_EQ(ls.p_light.x, x);
  }
}

// Inside half the fall-off angle a point light; between it and half the coverage angle
// ((cos a - cos(cov / 2)) / (cos(fall / 2) - cos(cov / 2)))^4 of it; outside, nothing.
TEST(LightSpot, ConeAndFalloff) {
  const double coverage = 60, falloff = 20;
  Light l = Spot(V(0, 0, 2), V(0, 0, -1), 400, coverage, falloff);
  double cc = std::cos(coverage * M_PI / 360), cf = std::cos(falloff * M_PI / 360);
  for (double deg : {0.0, 5.0, 9.9, 10.1, 15.0, 20.0, 25.0, 29.9, 30.1, 45.0, 120.0}) {
    double a = deg * M_PI / 180;
    // A point at distance 2 from the light, at angle a from its axis.
    float3 p = V(static_cast<float>(2 * std::sin(a)), 0, static_cast<float>(2 - 2 * std::cos(a)));
    LightSampleContext ctx = MakeLightSampleContext(p, V(0, 0, 1), V(0, 0, 1));
    LightSample ls = SampleSpotLight(&l, &ctx);
    ASSERT_TRUE(ls.valid);
    double s = deg <= falloff / 2    ? 1.0
               : deg >= coverage / 2 ? 0.0
                                     : std::pow((std::cos(a) - cc) / (cf - cc), 4);
    EXPECT_NEAR(ls.irradiance.x, 100 * s, 1e-4 * 100) << deg << " degrees";
  }
  // Continuous at both edges: the weight tends to 1 and to 0.
  EXPECT_NEAR(SpotFalloff(&l, static_cast<float>(cf) - 1e-6f), 1.0f, 1e-3f);
  EXPECT_NEAR(SpotFalloff(&l, static_cast<float>(cc) + 1e-6f), 0.0f, 1e-6f);
}

TEST(LightDispatch, DirectionalAndSpotTags) {
  SceneHeader header{};
  header.features = RT_FEATURE_ALL;
  SceneData sd{};
  sd.header = &header;
  LightSampleContext ctx = MakeLightSampleContext(V(0, 0, 0), V(0, 0, 1), V(0, 0, 1));
  RaySampler rs{};
  Light d = Directional(V(0, 0, -1), V(7, 7, 7), 10);
  EXPECT_EQ(SampleLight(&sd, &d, &ctx, &rs).irradiance.x, 7.0f);
  Light s = Spot(V(0, 0, 2), V(0, 0, -1), 8, 90, 30);
  EXPECT_EQ(SampleLight(&sd, &s, &ctx, &rs).irradiance.x, 2.0f);
  header.features = RT_FEATURE_ALL & ~(RT_LIGHT_DIRECTIONAL | RT_LIGHT_SPOT);
  EXPECT_FALSE(SampleLight(&sd, &d, &ctx, &rs).valid);  // Compiled out: never sampled.
  EXPECT_FALSE(SampleLight(&sd, &s, &ctx, &rs).valid);
}

// ---- Rendered closed forms: a diffuse floor (kd = 0.5) at z = 0 seen at the origin ----

rt::SceneDesc Floor() {
  rt::SceneDesc s;
  rt::CameraDesc c;
  c.image_name = "x.png";
  c.position = {0, 0, 5};
  c.gaze = {0, 0, -1};
  c.up = {0, 1, 0};
  c.left = c.bottom = -1e-7;
  c.right = c.top = 1e-7;
  c.width = c.height = 1;
  s.cameras.push_back(c);
  Material m{};
  m.diffuse = V(0.5f, 0.5f, 0.5f);
  m.phong_exponent = 1;
  m.refraction_index = 1;
  s.materials.push_back(m);
  rt::MeshDesc quad;
  quad.positions = {{-10, -10, 0}, {10, -10, 0}, {10, 10, 0}, {-10, 10, 0}};
  quad.triangles = {{0, 1, 2}, {0, 2, 3}};
  s.meshes.push_back(quad);
  rt::ObjectDesc floor;
  floor.mesh = 0;
  s.objects.push_back(floor);
  return s;
}

float Render(const rt::SceneDesc& s) {
  rt::RenderOptions opt;
  rt::FlatScene flat = rt::prepare_scene(s, opt);
  rt::prepare_camera(flat, s, 0, opt);
  rt::RenderResult r = rt::test::render_cpu(flat, 1);
  return r.accum[0].sum.x / r.accum[0].sum.w;
}

// Radiance 100 arriving at 45 degrees: 0.5 * 100 * cos 45.
TEST(LightRendered, DirectionalLightOnAFloor) {
  rt::SceneDesc s = Floor();
  Light d =
      Directional(V(static_cast<float>(std::sqrt(0.5)), 0, -static_cast<float>(std::sqrt(0.5))),
                  V(100, 100, 100), 0);
  s.lights.push_back(d);
  EXPECT_NEAR(Render(s), 50 * std::sqrt(0.5), 1e-4);
  // A sphere far up the light's path casts its shadow: flatten sets the segment's length
  // from the scene's bounds, so it reaches the sphere.
  rt::ObjectDesc sphere;
  sphere.kind = rt::ObjectDesc::kSphere;
  sphere.transform = rt::Mat4::translation({-40, 0, 40});
  s.objects.push_back(sphere);
  EXPECT_EQ(Render(s), 0.0f);
}

// Intensity 400 two units above, pointing down: 0.5 * 400 / 4 inside the cone; turned
// 40 degrees away with a 60-degree coverage, nothing.
TEST(LightRendered, SpotLightOnAFloor) {
  rt::SceneDesc s = Floor();
  s.lights.push_back(Spot(V(0, 0, 2), V(0, 0, -1), 400, 60, 20));
  EXPECT_FLOAT_EQ(Render(s), 50.0f);
  s.lights[0].normal = V(static_cast<float>(std::sin(40 * M_PI / 180)), 0,
                         -static_cast<float>(std::cos(40 * M_PI / 180)));
  EXPECT_EQ(Render(s), 0.0f);
}

}  // namespace
}  // namespace rt
