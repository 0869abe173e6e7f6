// The path tracer under an environment light (cl/integrator/path.h): with next-event
// estimation the environment is sampled at every vertex, so a path that leaves the scene
// after a non-specular bounce must not add it again, and one that leaves after a delta
// lobe (or the camera ray) must. Counting it twice or not at all moves every figure below
// by a whole term, far outside the statistical tolerance (support/pixel_estimate.h).
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstring>
#include <string>

#include "cl/features.h"
#include "cl/light/environment_map.h"
#include "support/device_harness.h"
#include "support/pixel_estimate.h"
#include "support/test_scene.h"

namespace {

using rt::test::ExpectMean;
using rt::test::ExpectSameMean;
using rt::test::RenderOnePixel;

constexpr float kSky = 2.0f;  // The environment's constant radiance L.

// A constant environment light of radiance kSky, sampled by `sampler`.
void AddSky(rt::SceneDesc* s, int sampler) {
  s->environment_map.width = 8;
  s->environment_map.height = 4;
  s->environment_map.channels = 3;
  s->environment_map.max_value = 0;
  s->environment_map.pixels.assign(8 * 4 * 3, kSky);
  Light l{};
  l.type = RT_LIGHT_ENVIRONMENT;
  RT_ENV_MAPPING(&l) = RT_ENV_LATLONG;
  RT_ENV_SAMPLING(&l) = sampler;
  s->lights.push_back(l);
}

rt::MeshDesc Quad(rt::Vec3d a, rt::Vec3d b, rt::Vec3d c, rt::Vec3d d) {
  rt::MeshDesc m;
  m.positions = {a, b, c, d};
  m.triangles = {{0, 1, 2}, {0, 2, 3}};
  return m;
}

// A camera at height 0.5 looking straight down (-z) at the floor's centre, path tracing.
rt::SceneDesc Looking(int depth, int samples, int path_flags) {
  rt::SceneDesc s;
  s.max_depth = depth;
  rt::CameraDesc c = rt::test::PointCamera({0, 0, 0.5}, samples);
  c.path_tracing = true;
  c.path_flags = path_flags;
  s.cameras.push_back(c);
  return s;
}

// A floor z = 0 (facing +z) of the given material: every direction above it is the sky.
void AddFloor(rt::SceneDesc* s, const Material& m) {
  s->materials.push_back(m);
  s->meshes.push_back(Quad({-50, -50, 0}, {50, -50, 0}, {50, 50, 0}, {-50, 50, 0}));
  rt::ObjectDesc o;
  o.mesh = static_cast<int>(s->meshes.size()) - 1;
  o.material = static_cast<int>(s->materials.size()) - 1;
  s->objects.push_back(o);
}

// The course's diffuse material (no BRDF element: f = kd, no 1/pi).
Material CourseDiffuse(float kd) {
  Material m{};
  m.diffuse = make_float3(kd, kd, kd);
  m.phong_exponent = 1;
  m.refraction_index = 1;
  return m;
}

const int kNee = RT_FLAG_NEXT_EVENT, kImportance = RT_FLAG_IMPORTANCE_SAMPLING;

std::string Name(int flags, int sampler) {
  return std::string(flags & kNee ? "NEE" : "bounces") +
         (flags & kImportance ? ", cosine" : ", uniform") + ", environment sampler " +
         std::to_string(sampler);
}

// A floor of kd under a constant sky L reflects, in the course's convention (f = kd),
// kd pi L; a normalized Lambertian (f = kd / pi) reflects kd L. Paths that find the sky by
// a bounce and light samples of the sky agree, whatever the samplers; the depth allows
// more bounces than the floor can use, so a path that escaped after its light sample and
// were counted again would show 2 kd pi L.
TEST(PathEnvironment, ConstantSkyOverAFloor) {
  const float kd = 0.25f;
  for (int sampler : {RT_ENV_SAMPLE_IMPORTANCE, RT_ENV_SAMPLE_UNIFORM, RT_ENV_SAMPLE_COSINE})
    for (int flags : {0, kImportance, kNee, kNee | kImportance}) {
      rt::SceneDesc s = Looking(3, 20000, flags);
      AddFloor(&s, CourseDiffuse(kd));
      AddSky(&s, sampler);
      ExpectMean(RenderOnePixel(s), kd * M_PI * kSky, "course diffuse, " + Name(flags, sampler));
      s.materials[0] = rt::test::Lambert(kd);
      ExpectMean(RenderOnePixel(s), kd * kSky, "normalized, " + Name(flags, sampler));
    }
}

// A course mirror (MirrorReflectance km beside a diffuse kd) under the sky: the mirrored
// ray leaves by a delta lobe, which light samples cannot reach, so it counts the sky with
// next-event estimation too, and the diffuse part adds kd pi L once: km L + kd pi L.
TEST(PathEnvironment, MirrorCountsTheSkyItReflects) {
  const float kd = 0.25f, km = 0.5f;
  Material mirror = CourseDiffuse(kd);
  mirror.type = RT_MATERIAL_MIRROR;
  mirror.mirror = make_float3(km, km, km);
  for (int flags : {0, kImportance, kNee, kNee | kImportance}) {
    rt::SceneDesc s = Looking(3, 20000, flags);
    AddFloor(&s, mirror);
    AddSky(&s, RT_ENV_SAMPLE_IMPORTANCE);
    ExpectMean(RenderOnePixel(s), (km + kd * M_PI) * kSky, Name(flags, 0));
  }
}

// The white furnace: an open box (floor and four walls, no lid) of albedo 1 under a
// constant sky L has radiance L everywhere once every bounce counts (the outgoing radiance
// of each surface equals the uniform incoming radiance). The camera looks down at the
// floor, whose paths bounce between the walls before they escape; at depth 60 the share
// of paths still inside is below 1e-6. A path that adds the sky twice, or drops it after a
// bounce, misses L by a share of the light of one bounce or more.
rt::SceneDesc OpenBox(double albedo, int depth, int samples, int flags) {
  rt::SceneDesc s = Looking(depth, samples, flags);
  s.cameras[0].position = {0.1, 0.2, 0.3};
  s.materials.push_back(rt::test::Lambert(albedo));
  const double w = 0.5, h = 0.6;
  s.meshes = {Quad({-w, -w, 0}, {w, -w, 0}, {w, w, 0}, {-w, w, 0}),
              Quad({-w, -w, 0}, {-w, w, 0}, {-w, w, h}, {-w, -w, h}),
              Quad({w, -w, 0}, {w, -w, h}, {w, w, h}, {w, w, 0}),
              Quad({-w, -w, 0}, {-w, -w, h}, {w, -w, h}, {w, -w, 0}),
              Quad({-w, w, 0}, {w, w, 0}, {w, w, h}, {-w, w, h})};
  for (int i = 0; i < 5; ++i) {
    rt::ObjectDesc o;
    o.mesh = i;
    s.objects.push_back(o);
  }
  AddSky(&s, RT_ENV_SAMPLE_IMPORTANCE);
  return s;
}

TEST(PathEnvironment, OpenBoxWhiteFurnace) {
  for (int flags : {0, kImportance, kNee, kNee | kImportance}) {
    // Cosine-weighted bounces of a white Lambertian weigh exactly 1: only which bounce
    // escapes varies, so fewer samples suffice.
    int samples = flags & kImportance ? 4000 : 20000;
    ExpectMean(RenderOnePixel(OpenBox(1.0, 60, samples, flags)), kSky, Name(flags, 0));
  }
}

// Below albedo 1 the open box has no closed form, but paths that find the sky by bounces
// and by light samples must still agree. A light sample at a path's last vertex reaches
// one bounce further than its last bounce (the course's convention, docs/path_tracing.md),
// so next-event estimation at depth D estimates what bounces alone give at depth D + 1.
TEST(PathEnvironment, OpenBoxAgreesWithAndWithoutLightSamples) {
  for (int depth : {0, 3})
    for (int importance : {0, kImportance}) {
      std::string what = "depth " + std::to_string(depth) + (importance ? ", cosine" : ", uniform");
      ExpectSameMean(RenderOnePixel(OpenBox(0.6, depth + 1, 20000, importance)),
                     RenderOnePixel(OpenBox(0.6, depth, 20000, importance | kNee)), what);
    }
}

// The kernel against the CPU reference at equal seeds: the open box under the sky, path
// traced with and without light samples, seen by a 12 x 12 camera; every pixel's sums and
// the ray count bit for bit.
TEST(PathEnvironment, OpenClMatchesCpuBitForBit) {
  std::string why;
  rt::RenderDevice* cl = rt::test::shared_device(rt::Device::kOpenCl, &why);
  if (!cl) GTEST_SKIP() << "no OpenCL device: " << why;
  for (int flags : {kImportance, kNee, kNee | kImportance}) {
    rt::SceneDesc s = OpenBox(0.6, 4, 8, flags);
    rt::CameraDesc& c = s.cameras[0];
    c.width = c.height = 12;
    c.left = c.bottom = -0.6;
    c.right = c.top = 0.6;
    rt::RenderOptions opt;
    opt.seed = 3;
    rt::FlatScene flat = rt::prepare_scene(s, opt);
    rt::prepare_camera(flat, s, 0, opt);
    rt::RenderResult a = rt::test::render_on(*cl, flat), b = rt::test::render_cpu(flat);
    ASSERT_EQ(a.accum.size(), b.accum.size());
    size_t same = 0;
    float brightest = 0;
    for (size_t i = 0; i < a.accum.size(); ++i) {
      same += std::memcmp(&a.accum[i].sum, &b.accum[i].sum, sizeof(float4)) == 0;
      brightest = std::max(brightest, b.accum[i].sum.x);
    }
    EXPECT_GT(brightest, 0.0f) << "a black image proves nothing";
    EXPECT_EQ(same, a.accum.size()) << Name(flags, 0);
    EXPECT_EQ(a.rays, b.rays) << Name(flags, 0);
  }
}

}  // namespace
