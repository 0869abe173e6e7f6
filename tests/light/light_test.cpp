// Tests for light sampling (cl/light/): each type's sample against closed forms, the
// dispatch on the type tag, and the tagged array prepare_camera builds from the loader's
// point and area lights.
//
// Tolerances: a point light's sample is exact where the operands are dyadic; the area
// light's irradiance is a midpoint-rule average of its samples over a 512 x 512 grid,
// whose quadrature error here is below 1e-5 of the result, checked to 1e-4.
#include <gtest/gtest.h>

#include <cmath>
#include <cstddef>

#include "cl/light/light.h"
#include "prepare/flat_scene.h"

namespace rt {
namespace {

constexpr double kPi = 3.14159265358979323846;

// The named per-type parameters keep the layout both devices upload.
static_assert(offsetof(Light, scalar) == 80 && offsetof(Light, sample_index) == 96 &&
                  offsetof(Light, type) == 100 && offsetof(Light, slot) == 104,
              "Light layout");

float3 V(float x, float y, float z) { return make_float3(x, y, z); }

struct LightScene {
  SceneHeader header{};
  SceneData sd{};
  LightScene() {
    header.features = RT_FEATURE_ALL;
    sd.header = &header;
  }
};

Light PointAt(float3 position, float3 intensity) {
  Light l{};
  l.type = RT_LIGHT_POINT;
  l.position = position;
  l.emission = intensity;
  return l;
}

// A square of side `side` centred on `centre`, parallel to the xy plane, facing -z.
Light Square(float3 centre, float side, float3 radiance) {
  Light l{};
  l.type = RT_LIGHT_AREA;
  l.position = centre - V(side / 2, side / 2, 0);
  l.edge1 = V(side, 0, 0);
  l.edge2 = V(0, side, 0);
  l.normal = V(0, 0, -1);
  l.emission = radiance;
  RT_LIGHT_SURFACE_AREA(&l) = side * side;
  return l;
}

TEST(LightPoint, IrradianceFallsOffAsInverseSquare) {
  Light l = PointAt(V(0, 0, 2), V(8, 16, 32));
  LightSampleContext ctx = MakeLightSampleContext(V(0, 0, 0), V(0, 0, 1), V(0, 0, 1));
  LightSample ls = SamplePointLight(&l, &ctx);
  ASSERT_TRUE(ls.valid);
  EXPECT_EQ(ls.wi.x, 0.0f);
  EXPECT_EQ(ls.wi.z, 1.0f);
  EXPECT_EQ(ls.p_light.z, 2.0f);  // The shadow segment ends at the light.
  EXPECT_EQ(ls.irradiance.x, 2.0f);
  EXPECT_EQ(ls.irradiance.y, 4.0f);
  EXPECT_EQ(ls.irradiance.z, 8.0f);
  // Off axis: I / d^2 with d^2 = 9 + 16.
  ctx.p = V(3, 0, -2);
  ls = SamplePointLight(&l, &ctx);
  EXPECT_NEAR(ls.irradiance.x, 8.0 / 25.0, 1e-7);
  EXPECT_NEAR(ls.wi.x, -0.6, 1e-7);
  EXPECT_NEAR(ls.wi.z, 0.8, 1e-7);
}

TEST(LightPoint, NothingReachesThePointItself) {
  Light l = PointAt(V(1, 2, 3), V(1, 1, 1));
  LightSampleContext ctx = MakeLightSampleContext(V(1, 2, 3), V(0, 0, 1), V(0, 0, 1));
  EXPECT_FALSE(SamplePointLight(&l, &ctx).valid);
}

TEST(LightArea, SamplesCoverTheParallelogram) {
  Light l = Square(V(0, 0, 1), 2, V(1, 1, 1));
  LightSampleContext ctx = MakeLightSampleContext(V(0, 0, 0), V(0, 0, 1), V(0, 0, 1));
  LightSample a = SampleAreaLight(&l, &ctx, make_float2(0, 0));
  LightSample b = SampleAreaLight(&l, &ctx, make_float2(0.5f, 0.25f));
  EXPECT_EQ(a.p_light.x, -1.0f);
  EXPECT_EQ(a.p_light.y, -1.0f);
  EXPECT_EQ(b.p_light.x, 0.0f);
  EXPECT_EQ(b.p_light.y, -0.5f);
  EXPECT_EQ(b.p_light.z, 1.0f);
}

// Irradiance under the centre of a square light of radiance L, side s, height h, on a
// surface facing it: E = 4 L X / sqrt(1 + X^2) atan(X / sqrt(1 + X^2)), X = s / (2h)
// (four corner rectangles of the differential-area-to-parallel-rectangle form factor).
double SquareIrradiance(double radiance, double side, double height) {
  double x = side / (2 * height), r = std::sqrt(1 + x * x);
  return 4 * radiance * x / r * std::atan(x / r);
}

double AverageIrradiance(const Light& l, float3 p, float3 n) {
  LightSampleContext ctx = MakeLightSampleContext(p, n, n);
  const int k = 512;
  double sum = 0;
  for (int i = 0; i < k; ++i)
    for (int j = 0; j < k; ++j) {
      float2 u = make_float2((i + 0.5f) / k, (j + 0.5f) / k);
      LightSample ls = SampleAreaLight(&l, &ctx, u);
      sum += ls.irradiance.x * std::fmax(0.0f, Dot(n, ls.wi));
    }
  return sum / (double(k) * k);
}

TEST(LightArea, AverageSampleIsTheSquaresIrradiance) {
  for (double side : {0.5, 2.0, 6.0}) {
    Light l = Square(V(0, 0, 2), static_cast<float>(side), V(3, 3, 3));
    double expect = SquareIrradiance(3, side, 2);
    EXPECT_NEAR(AverageIrradiance(l, V(0, 0, 0), V(0, 0, 1)), expect, 1e-4 * expect)
        << "side " << side;
  }
  // A tiny light tends to a point light of intensity L * A.
  Light tiny = Square(V(0, 0, 2), 0.01f, V(1, 1, 1));
  EXPECT_NEAR(AverageIrradiance(tiny, V(0, 0, 0), V(0, 0, 1)), 1e-4 / 4, 1e-4 * 1e-4 / 4);
}

TEST(LightArea, BothFacesEmit) {
  Light l = Square(V(0, 0, 0), 1, V(1, 1, 1));
  double below = AverageIrradiance(l, V(0, 0, -1.5f), V(0, 0, 1));
  double above = AverageIrradiance(l, V(0, 0, 1.5f), V(0, 0, -1));
  EXPECT_NEAR(below, SquareIrradiance(1, 1, 1.5), 1e-4 * below);
  EXPECT_EQ(below, above);  // Mirror images: every sample matches bit for bit.
}

TEST(LightDispatch, TypeTagChoosesTheSampler) {
  LightScene scene;
  LightSampleContext ctx = MakeLightSampleContext(V(0, 0, 0), V(0, 0, 1), V(0, 0, 1));
  RaySampler rs = MakeRaySampler(MakeSampleKey(7, 3, 16, 4, 0), 1234u, 0);
  Light p = PointAt(V(0, 0, 2), V(4, 4, 4));
  LightSample a = SampleLight(&scene.sd, &p, &ctx, &rs);
  LightSample b = SamplePointLight(&p, &ctx);
  EXPECT_EQ(a.irradiance.x, b.irradiance.x);
  Light s = Square(V(0, 0, 2), 1, V(1, 1, 1));
  s.sample_index = 5;
  a = SampleLight(&scene.sd, &s, &ctx, &rs);
  b = SampleAreaLight(&s, &ctx, RaySample2D(&rs, 0x1000u + 5u));
  EXPECT_EQ(a.p_light.x, b.p_light.x);
  EXPECT_EQ(a.p_light.y, b.p_light.y);
  // A type the kernel was compiled without is never sampled.
  scene.header.features = RT_FEATURE_ALL & ~RT_LIGHT_AREA;
  EXPECT_FALSE(SampleLight(&scene.sd, &s, &ctx, &rs).valid);
}

TEST(LightArray, FlattenTagsPointLightsFirstAndNumbersTheSampledOnes) {
  SceneDesc desc;
  desc.cameras.emplace_back();
  AreaLight a{};
  a.corner = {0, 0, 1};
  a.edge1 = V(1, 0, 0);
  a.edge2 = V(0, 1, 0);
  a.normal = V(0, 0, -1);
  a.radiance = V(2, 2, 2);
  a.area = 1;
  desc.area_lights = {a, a};
  PointLight p{};
  p.position = {0, 0, 3};
  p.intensity = V(5, 5, 5);
  desc.point_lights = {p};
  FlatScene f = prepare_scene(desc, RenderOptions());
  prepare_camera(f, desc, 0, RenderOptions());
  ASSERT_EQ(f.header.num_lights, 3);
  EXPECT_EQ(f.lights[0].type, RT_LIGHT_POINT);
  EXPECT_EQ(f.lights[0].emission.x, 5.0f);
  EXPECT_EQ(f.lights[1].type, RT_LIGHT_AREA);
  EXPECT_EQ(f.lights[1].sample_index, 0);
  EXPECT_EQ(f.lights[2].sample_index, 1);
  EXPECT_EQ(RT_LIGHT_SURFACE_AREA(&f.lights[2]), 1.0f);
  EXPECT_EQ(f.header.features & (RT_LIGHT_POINT | RT_LIGHT_AREA), RT_LIGHT_POINT | RT_LIGHT_AREA);
}

}  // namespace
}  // namespace rt
