// The environment light (cl/light/environment.h, environment_map.h,
// src/prepare/flat_environment.cpp) against closed forms: the mappings of known directions to known
// texels, the importance sampler against its density (chi-square), a constant environment over a
// diffuse floor, one bright texel against a directional light of the same power, and the two
// devices against each other.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstring>
#include <random>
#include <vector>

#include "cl/light/light.h"
#include "cl/material/brdf.h"
#include "integrator/render.h"
#include "prepare/flat_scene.h"
#include "support/device_harness.h"

namespace rt {
namespace {

float3 V(float x, float y, float z) { return make_float3(x, y, z); }

// ---- Mappings: exact texels of known directions ----

// The six axis directions under `mapping`, at their (u, v), in the order -z, +x, -x, +y, -y, +z.
void ExpectAxes(int mapping, const float (&uv)[6][2]) {
  const float3 axes[6] = {V(0, 0, -1), V(1, 0, 0),  V(-1, 0, 0),
                          V(0, 1, 0),  V(0, -1, 0), V(0, 0, 1)};
  for (int i = 0; i < 6; ++i) {
    float2 got = EnvDirectionToUV(mapping, axes[i]);
    EXPECT_FLOAT_EQ(got.x, uv[i][0]) << "mapping " << mapping << ", axis " << i;
    EXPECT_FLOAT_EQ(got.y, uv[i][1]) << "mapping " << mapping << ", axis " << i;
  }
}

TEST(EnvironmentMap, LatLongOfKnownDirections) {
  ExpectAxes(
      RT_ENV_LATLONG,
      {{0.5f, 0.5f}, {0.75f, 0.5f}, {0.25f, 0.5f}, {0.5f, 0.0f}, {0.5f, 1.0f}, {1.0f, 0.5f}});
  // An 8 x 4 map: +x is column 6 of row 2; straight up is row 0, straight down row 3.
  EXPECT_EQ(EnvTexelIndex(EnvDirectionToUV(RT_ENV_LATLONG, V(1, 0, 0)), 8, 4), 2 * 8 + 6);
  EXPECT_EQ(EnvTexelIndex(EnvDirectionToUV(RT_ENV_LATLONG, V(0, 1, 0)), 8, 4), 0 * 8 + 4);
  EXPECT_EQ(EnvTexelIndex(EnvDirectionToUV(RT_ENV_LATLONG, V(0, -1, 0)), 8, 4), 3 * 8 + 4);
  // 45 degrees up and 45 degrees to the left of -z: u = 3/8, v = 1/4, the corner of (3, 1).
  float s = std::sqrt(0.5f);
  float2 uv = EnvDirectionToUV(RT_ENV_LATLONG, V(-0.5f, s, -0.5f));
  EXPECT_NEAR(uv.x, 0.375f, 1e-6f);
  EXPECT_NEAR(uv.y, 0.25f, 1e-6f);
}

TEST(EnvironmentMap, ProbeOfKnownDirections) {
  ExpectAxes(
      RT_ENV_PROBE,
      {{0.5f, 0.5f}, {0.75f, 0.5f}, {0.25f, 0.5f}, {0.5f, 0.25f}, {0.5f, 0.75f}, {1.0f, 0.5f}});
  // A 4 x 4 probe: straight ahead is the corner shared by texels (1,1)..(2,2): (2, 2).
  EXPECT_EQ(EnvTexelIndex(EnvDirectionToUV(RT_ENV_PROBE, V(0, 0, -1)), 4, 4), 2 * 4 + 2);
  EXPECT_EQ(EnvTexelIndex(EnvDirectionToUV(RT_ENV_PROBE, V(0, 1, 0)), 4, 4), 1 * 4 + 2);
}

// Direction -> uv -> direction returns the direction, and the solid angle per unit map
// area integrates to the whole sphere (4 pi) over the map.
TEST(EnvironmentMap, RoundTripAndSolidAngle) {
  std::mt19937 rng(7);
  std::normal_distribution<float> g;
  for (int mapping : {RT_ENV_LATLONG, RT_ENV_PROBE}) {
    for (int i = 0; i < 2000; ++i) {
      float3 d = Normalize(V(g(rng), g(rng), g(rng)));
      float jacobian;
      float3 back = EnvUVToDirection(mapping, EnvDirectionToUV(mapping, d), &jacobian);
      ASSERT_NEAR(back.x, d.x, 2e-5f) << mapping;
      ASSERT_NEAR(back.y, d.y, 2e-5f) << mapping;
      ASSERT_NEAR(back.z, d.z, 2e-5f) << mapping;
    }
    const int n = 1000;
    double total = 0;
    for (int y = 0; y < n; ++y)
      for (int x = 0; x < n; ++x) {
        float jacobian;
        EnvUVToDirection(mapping, make_float2((x + 0.5f) / n, (y + 0.5f) / n), &jacobian);
        total += jacobian;
      }
    EXPECT_NEAR(total / (double(n) * n), 4 * M_PI, 2e-3 * 4 * M_PI) << mapping;
  }
}

TEST(EnvironmentMap, SinCos2PiMatchesTheLibrary) {
  for (int i = -4000; i <= 4000; ++i) {
    float t = i / 1000.0f + 0.000123f;
    float s, c;
    SinCos2Pi(t, &s, &c);
    EXPECT_NEAR(s, std::sin(2 * M_PI * double(t)), 4e-7) << t;
    EXPECT_NEAR(c, std::cos(2 * M_PI * double(t)), 4e-7) << t;
  }
}

// ---- Scenes in code ----

ImageF Map(int w, int h, float value) {
  ImageF m;
  m.width = w;
  m.height = h;
  m.channels = 3;
  m.max_value = 0;
  m.pixels.assign(static_cast<size_t>(w) * h * 3, value);
  return m;
}

Light Environment(int mapping, int sampler) {
  Light l{};
  l.type = RT_LIGHT_ENVIRONMENT;
  RT_ENV_MAPPING(&l) = mapping;
  RT_ENV_SAMPLING(&l) = sampler;
  return l;
}

// A floor of kd (0.5 grey) at y = 0, facing +y (the environment's up), seen from above by
// a w x w camera looking straight down at a 2 x 2 patch of it.
SceneDesc Floor(int w, Material m) {
  SceneDesc s;
  CameraDesc c;
  c.image_name = "x.png";
  c.position = {0, 5, 0};
  c.gaze = {0, -1, 0};
  c.up = {0, 0, -1};
  c.left = c.bottom = -0.2;
  c.right = c.top = 0.2;
  c.width = c.height = w;
  s.cameras.push_back(c);
  s.materials.push_back(m);
  MeshDesc quad;
  quad.positions = {{-10, 0, -10}, {-10, 0, 10}, {10, 0, 10}, {10, 0, -10}};
  quad.triangles = {{0, 1, 2}, {0, 2, 3}};
  s.meshes.push_back(quad);
  ObjectDesc floor;
  floor.mesh = 0;
  s.objects.push_back(floor);
  return s;
}

Material Diffuse(float kd) {
  Material m{};
  m.diffuse = V(kd, kd, kd);
  m.phong_exponent = 1;
  m.refraction_index = 1;
  return m;
}

RenderResult RenderCpu(const SceneDesc& s, int spp, uint32_t seed = 0) {
  RenderOptions opt;
  opt.spp = spp;
  opt.seed = seed;
  FlatScene flat = prepare_scene(s, opt);
  prepare_camera(flat, s, 0, opt);
  return test::render_cpu(flat, 2);
}

// The mean of channel 0 over every sample of every pixel, and its standard error.
struct Estimate {
  double mean, se;
};
Estimate Measure(const RenderResult& r) {
  double sum = 0, sum_sq = 0, n = 0;
  for (const PixelAccum& a : r.accum) {
    sum += a.sum.x;
    sum_sq += a.sum_sq.x;
    n += a.sum_sq.w;
  }
  double mean = sum / n;
  return {mean, std::sqrt(std::max(0.0, sum_sq / n - mean * mean) / n)};
}

// A constant environment L over an unoccluded floor: the course's diffuse term kd E cos
// (no 1/pi, as for its point lights) gives kd * pi * L whatever the sampler; the cosine
// sampler has no variance at all. A normalized BRDF (kd / pi) gives the physical kd * L.
TEST(EnvironmentLight, ConstantEnvironmentOverADiffuseFloor) {
  const float kd = 0.5f, L = 100.0f;
  const double expected = kd * M_PI * L;
  for (int sampler : {RT_ENV_SAMPLE_IMPORTANCE, RT_ENV_SAMPLE_UNIFORM}) {
    SceneDesc s = Floor(4, Diffuse(kd));
    s.environment_map = Map(32, 16, L);
    s.lights.push_back(Environment(RT_ENV_LATLONG, sampler));
    Estimate e = Measure(RenderCpu(s, 4096));
    // 4.4 standard errors: a false alarm once in 10^5 runs.
    EXPECT_NEAR(e.mean, expected, 4.4 * e.se + 1e-4 * expected) << "sampler " << sampler;
    EXPECT_LT(e.se, 0.01 * expected) << "sampler " << sampler;
  }
  // Every single cosine-weighted sample is exact, up to rounding.
  SceneDesc s = Floor(4, Diffuse(kd));
  s.environment_map = Map(32, 16, L);
  s.lights.push_back(Environment(RT_ENV_LATLONG, RT_ENV_SAMPLE_COSINE));
  for (float v : RenderCpu(s, 1).rgb()) EXPECT_NEAR(v, expected, 1e-5 * expected);
  s.materials[0].brdf = RT_BRDF_MODIFIED_BLINN_PHONG;
  s.materials[0].brdf_flags = RT_BRDF_NORMALIZED;
  for (float v : RenderCpu(s, 1).rgb()) EXPECT_NEAR(v, kd * L, 1e-5 * kd * L);
}

// Camera rays and mirror-reflected rays that leave the scene see the map's texel of their
// direction, exactly.
TEST(EnvironmentLight, EscapingRaysSeeTheMap) {
  SceneDesc s = Floor(1, Diffuse(0.5f));
  s.objects.clear();  // Nothing: the camera looks straight down, at the bottom row.
  s.environment_map = Map(8, 4, 0.0f);
  for (int x = 0; x < 8; ++x) {
    s.environment_map.pixels[(3 * 8 + x) * 3] = 7.0f;       // Bottom row: down.
    s.environment_map.pixels[(0 * 8 + x) * 3 + 1] = 11.0f;  // Top row: up.
  }
  s.lights.push_back(Environment(RT_ENV_LATLONG, RT_ENV_SAMPLE_IMPORTANCE));
  RenderResult r = RenderCpu(s, 1);
  EXPECT_EQ(r.accum[0].sum.x, 7.0f);
  EXPECT_EQ(r.accum[0].sum.y, 0.0f);
  // A mirror floor: the reflected ray goes up and sees the top row.
  SceneDesc m = Floor(1, Diffuse(0.0f));
  m.materials[0].type = RT_MATERIAL_MIRROR;
  m.materials[0].mirror = V(1, 1, 1);
  m.environment_map = s.environment_map;
  m.lights.push_back(Environment(RT_ENV_LATLONG, RT_ENV_SAMPLE_IMPORTANCE));
  RenderResult rm = RenderCpu(m, 1);
  EXPECT_EQ(rm.accum[0].sum.x, 0.0f);
  EXPECT_EQ(rm.accum[0].sum.y, 11.0f);
}

// One bright texel of radiance L lights the floor as a directional light of radiance
// L * (the texel's solid angle) from the texel's centre: the same image, within the
// variation of the cosine and of sin(theta) across the texel (below 0.5 % here).
TEST(EnvironmentLight, OneBrightTexelMatchesADirectionalLight) {
  const int w = 64, h = 32, tx = 40, ty = 9;
  const float L = 5000.0f;
  SceneDesc env = Floor(8, Diffuse(0.5f));
  env.environment_map = Map(w, h, 0.0f);
  for (int c = 0; c < 3; ++c) env.environment_map.pixels[(ty * w + tx) * 3 + c] = L;
  env.lights.push_back(Environment(RT_ENV_LATLONG, RT_ENV_SAMPLE_IMPORTANCE));
  float jacobian;
  float3 towards =
      EnvUVToDirection(RT_ENV_LATLONG, make_float2((tx + 0.5f) / w, (ty + 0.5f) / h), &jacobian);
  double solid_angle = 2 * M_PI / w * (std::cos(M_PI * ty / h) - std::cos(M_PI * (ty + 1) / h));
  SceneDesc dir = Floor(8, Diffuse(0.5f));
  Light d{};
  d.type = RT_LIGHT_DIRECTIONAL;
  d.normal = -towards;
  float e = static_cast<float>(L * solid_angle);
  d.emission = V(e, e, e);
  dir.lights.push_back(d);
  RenderResult a = RenderCpu(env, 64), b = RenderCpu(dir, 1);
  std::vector<float> ra = a.rgb(), rb = b.rgb();
  ASSERT_GT(rb[0], 1.0f);
  for (size_t i = 0; i < ra.size(); ++i) EXPECT_NEAR(ra[i], rb[i], 5e-3 * rb[i]) << i;
  // A sphere between the floor and the texel shadows both alike at the floor's centre.
  ObjectDesc ball;
  ball.kind = ObjectDesc::kSphere;
  ball.transform = Mat4::translation({towards.x * 3, towards.y * 3, towards.z * 3}) *
                   Mat4::scaling({0.5, 0.5, 0.5});
  env.objects.push_back(ball);
  dir.objects.push_back(ball);
  EXPECT_EQ(RenderCpu(env, 16).rgb()[(4 * 8 + 4) * 3], 0.0f);
  EXPECT_EQ(RenderCpu(dir, 1).rgb()[(4 * 8 + 4) * 3], 0.0f);
}

// The importance sampler draws texel (x, y) with probability f(x, y) / sum f, where f is
// luminance times the solid angle per unit map area (chi-square at 1e-3), and reports the
// density EnvironmentPdf gives for the direction it drew.
TEST(EnvironmentLight, ImportanceSamplingFollowsItsDensity) {
  for (int mapping : {RT_ENV_LATLONG, RT_ENV_PROBE}) {
    const int w = 12, h = 8;
    SceneDesc s = Floor(1, Diffuse(0.5f));
    s.environment_map = Map(w, h, 0.0f);
    std::mt19937 rng(3);
    std::uniform_real_distribution<float> uni(0.0f, 10.0f);
    for (float& p : s.environment_map.pixels) p = uni(rng);
    for (int c = 0; c < 3; ++c) s.environment_map.pixels[(2 * w + 5) * 3 + c] = 0.0f;  // Black.
    s.lights.push_back(Environment(mapping, RT_ENV_SAMPLE_IMPORTANCE));
    RenderOptions opt;
    FlatScene flat = prepare_scene(s, opt);
    prepare_camera(flat, s, 0, opt);
    SceneData sd = flat.view();
    const Light* light = &flat.lights[flat.header.environment];
    std::vector<double> f = environment_importance(s.environment_map, mapping);
    double total = 0;
    for (double v : f) total += v;
    const int n = 200000;
    std::vector<double> count(f.size(), 0);
    LightSampleContext ctx = MakeLightSampleContext(V(0, 0, 0), V(0, 1, 0), V(0, 1, 0));
    std::uniform_real_distribution<float> u01(0.0f, 1.0f);
    int pdf_mismatches = 0, valid = 0;
    for (int i = 0; i < n; ++i) {
      LightSample ls = SampleEnvironmentLight(&sd, light, &ctx, make_float2(u01(rng), u01(rng)));
      // A probe's texels on the rim of its disc reach outside it, where there is no direction.
      if (mapping == RT_ENV_LATLONG) {
        ASSERT_TRUE(ls.valid);
      }
      if (!ls.valid) continue;
      ++valid;
      int texel = EnvTexelIndex(EnvDirectionToUV(mapping, ls.wi), w, h);
      count[texel] += 1;
      float3 radiance = EnvTexel(&sd, texel);
      double pdf = radiance.x / ls.irradiance.x;
      if (std::fabs(pdf - EnvironmentPdf(&sd, light, ls.wi)) > 1e-3 * pdf) ++pdf_mismatches;
    }
    EXPECT_GT(valid, n * 9 / 10);
    // Mapping the direction back may land across a texel edge by rounding, rarely.
    EXPECT_LT(pdf_mismatches, n / 1000) << mapping;
    EXPECT_LT(count[2 * w + 5], 1e-4 * n) << "a black texel was drawn";
    // One bin per texel wholly inside the map's domain, and one bin for the rest (a probe's
    // rim texels, its invalid draws and its black corners).
    double chi2 = 0, rest_count = n, rest_p = 1;
    int bins = 0;
    for (int y = 0; y < h; ++y)
      for (int x = 0; x < w; ++x) {
        size_t i = static_cast<size_t>(y) * w + x;
        bool inside = true;
        for (int corner = 0; corner < 4 && mapping == RT_ENV_PROBE; ++corner) {
          double a = 2.0 * (x + (corner & 1)) / w - 1, b = 2.0 * (y + (corner >> 1)) / h - 1;
          inside = inside && a * a + b * b <= 1;
        }
        if (f[i] <= 0 || !inside) continue;
        double p = f[i] / total, expected = n * p;
        chi2 += (count[i] - expected) * (count[i] - expected) / expected;
        rest_count -= count[i];
        rest_p -= p;
        ++bins;
      }
    if (rest_p * n > 5) {
      chi2 += (rest_count - n * rest_p) * (rest_count - n * rest_p) / (n * rest_p);
      ++bins;
    }
    // The 1 - 1e-3 quantile of chi-square with k degrees of freedom (Wilson-Hilferty).
    double k = bins - 1, z = 3.0902;
    double limit = k * std::pow(1 - 2 / (9 * k) + z * std::sqrt(2 / (9 * k)), 3);
    EXPECT_LT(chi2, limit) << "mapping " << mapping << ", " << bins << " bins";
  }
}

// Every sampler on both devices: the same bits in every pixel at equal seeds.
TEST(EnvironmentLight, OpenClMatchesCpuBitForBit) {
  std::string why;
  RenderDevice* cl = test::shared_device(Device::kOpenCl, &why);
  if (!cl) GTEST_SKIP() << "no OpenCL device: " << why;
  for (int mapping : {RT_ENV_LATLONG, RT_ENV_PROBE})
    for (int sampler : {RT_ENV_SAMPLE_IMPORTANCE, RT_ENV_SAMPLE_UNIFORM, RT_ENV_SAMPLE_COSINE}) {
      SceneDesc s = Floor(16, Diffuse(0.5f));
      s.cameras[0].left = s.cameras[0].bottom = -2;
      s.cameras[0].right = s.cameras[0].top = 2;
      s.environment_map = Map(24, 12, 0.0f);
      std::mt19937 rng(11);
      std::uniform_real_distribution<float> uni(0.0f, 50.0f);
      for (float& p : s.environment_map.pixels) p = uni(rng);
      ObjectDesc ball;
      ball.kind = ObjectDesc::kSphere;
      ball.transform = Mat4::translation({0.3, 0.6, 0}) * Mat4::scaling({0.5, 0.5, 0.5});
      s.objects.push_back(ball);
      s.lights.push_back(Environment(mapping, sampler));
      RenderOptions opt;
      opt.spp = 4;
      opt.seed = 5;
      FlatScene flat = prepare_scene(s, opt);
      prepare_camera(flat, s, 0, opt);
      RenderResult a = test::render_on(*cl, flat), b = test::render_cpu(flat, 2);
      ASSERT_EQ(a.accum.size(), b.accum.size());
      float brightest = 0;
      for (const PixelAccum& p : b.accum) brightest = std::max(brightest, p.sum.x);
      EXPECT_GT(brightest, 0.0f) << "a black image proves nothing";
      size_t same = 0;
      for (size_t i = 0; i < a.accum.size(); ++i)
        same += std::memcmp(&a.accum[i].sum, &b.accum[i].sum, sizeof(float4)) == 0;
      EXPECT_EQ(same, a.accum.size()) << "mapping " << mapping << ", sampler " << sampler;
    }
}

}  // namespace
}  // namespace rt
