// Object lights (hw6 LightMesh, LightSphere; cl/light/mesh_light.h, sphere_light.h,
// emission.h): loading and bad input, their light samples against closed forms (irradiance
// and subtended solid angle on the axis of a square and of a sphere), the densities they
// report against a brute-force integral over directions (an ellipsoid), front-face-only
// emission, and the OpenCL kernel against the CPU reference bit for bit.
#include <gtest/gtest.h>

#include <cmath>
#include <cstring>
#include <string>
#include <vector>

#include "cl/integrator/integrator.h"
#include "cl/light/emission.h"
#include "cl/light/light.h"
#include "cl/util/hash.h"
#include "prepare/flat_scene.h"
#include "support/device_harness.h"
#include "support/test_scene.h"
#include "util/errors.h"

namespace rt {
namespace {

// A scene around OBJECTS (one white diffuse material "1", a black one "2"), one camera
// at CAMERA_POS looking at the origin, 8 x 8 pixels.
std::string Scene(const std::string& objects, const std::string& camera_pos = "0 0 5",
                  const std::string& transforms = "") {
  return R"(<Scene><Cameras><Camera id="1" type="lookAt"><Position>)" + camera_pos +
         R"(</Position><GazePoint>0 0 0</GazePoint><Up>0 1 0</Up><FovY>10</FovY>
    <NearDistance>1</NearDistance><ImageResolution>8 8</ImageResolution>
    <ImageName>out.exr</ImageName></Camera></Cameras>
  <Materials><Material id="1"><DiffuseReflectance>1 1 1</DiffuseReflectance></Material>
    <Material id="2"><DiffuseReflectance>0 0 0</DiffuseReflectance></Material></Materials>
  <Transformations>)" +
         transforms + R"(</Transformations>
  <VertexData>-1 -1 0  1 -1 0  1 1 0  -1 1 0  0 0 0</VertexData>
  <Objects>)" +
         objects + "</Objects></Scene>";
}

// A square of side 2 in the plane z = 0 emitting towards +z (counter-clockwise seen from
// +z), and a sphere of radius `radius` at the origin.
std::string Square(const std::string& radiance = "2 2 2") {
  return "<LightMesh id=\"1\"><Material>2</Material><Radiance>" + radiance +
         "</Radiance><Faces>1 2 3 1 3 4</Faces></LightMesh>";
}
std::string Ball(double radius, const std::string& extra = "") {
  return "<LightSphere id=\"1\"><Material>2</Material><Center>5</Center><Radius>" +
         std::to_string(radius) + "</Radius><Radiance>3 3 3</Radiance>" + extra + "</LightSphere>";
}

struct Flat {
  SceneDesc scene;
  FlatScene flat;
  SceneData sd;
};

Flat Load(const std::string& xml) {
  Flat f;
  f.scene = load_scene_text(xml, "object_light_test.xml");
  RenderOptions opt;
  opt.camera_frame = false;  // The tests evaluate lights at world-space points.
  f.flat = prepare_scene(f.scene, opt);
  prepare_camera(f.flat, f.scene, 0, opt);
  f.sd = f.flat.view();
  return f;
}

const Light& FirstObjectLight(const Flat& f) {
  for (const Light& l : f.flat.lights)
    if (l.type == RT_LIGHT_MESH || l.type == RT_LIGHT_SPHERE) return l;
  throw std::runtime_error("no object light");
}

float2 Uniform2(uint i) {
  return make_float2(UintToUnitFloat(Hash4(i, 1u, 7u, 0u)), UintToUnitFloat(Hash4(i, 2u, 7u, 0u)));
}

// Means of the irradiance on a surface at p with unit normal n, and of 1/pdf
// (whose expectation is the solid angle the light subtends where it is sampled), with their
// standard errors.
struct Estimate {
  double e = 0, e_se = 0, omega = 0, omega_se = 0;
  int invalid = 0;
};

Estimate Sample(const Flat& f, float3 p, float3 n, int count) {
  const Light& light = FirstObjectLight(f);
  LightSampleContext ctx = MakeLightSampleContext(p, n, n);
  double s = 0, s2 = 0, w = 0, w2 = 0;
  Estimate est;
  for (int i = 0; i < count; ++i) {
    float2 u = Uniform2(static_cast<uint>(i));
    LightSample ls = light.type == RT_LIGHT_MESH ? SampleMeshLight(&f.sd, &light, &ctx, u)
                                                 : SampleSphereLight(&f.sd, &light, &ctx, u);
    if (!ls.valid) {
      ++est.invalid;
      continue;
    }
    double e = ls.irradiance.x * std::max(0.0f, Dot(n, ls.wi));
    double inv = 1.0 / ls.pdf;
    s += e, s2 += e * e, w += inv, w2 += inv * inv;
  }
  est.e = s / count;
  est.e_se = std::sqrt(std::max(0.0, s2 / count - est.e * est.e) / count);
  est.omega = w / count;
  est.omega_se = std::sqrt(std::max(0.0, w2 / count - est.omega * est.omega) / count);
  return est;
}

// Within 4.5 standard errors (and a float floor): a false failure has odds below 1e-5.
#define EXPECT_ESTIMATE(value, se, exact) \
  EXPECT_NEAR(value, exact, 4.5 * (se) + 1e-5 * std::fabs(exact)) << "se " << (se)

TEST(ObjectLightLoader, MeshAndSphereAreGeometryAndLights) {
  Flat f = Load(Scene(Square() + Ball(0.5, "<Transformations>t1</Transformations>"), "0 0 5",
                      "<Translation id=\"1\">0 0 -3</Translation>"));
  ASSERT_EQ(f.scene.objects.size(), 2u);
  EXPECT_TRUE(f.scene.objects[0].emits);
  EXPECT_EQ(f.scene.objects[0].radiance.x, 2.0);
  EXPECT_EQ(f.flat.header.num_lights, 2);
  EXPECT_TRUE(f.flat.header.features & RT_FEATURE_MESH_LIGHTS);
  EXPECT_TRUE(f.flat.header.features & RT_FEATURE_SPHERE_LIGHTS);
  const Light& mesh = FirstObjectLight(f);
  EXPECT_EQ(mesh.type, RT_LIGHT_MESH);
  EXPECT_FLOAT_EQ(RT_LIGHT_SURFACE_AREA(&mesh), 4.0f);
  EXPECT_EQ(RT_MESH_COUNT(&mesh), 2);
  EXPECT_EQ(f.flat.light_cdf[RT_MESH_CDF(&mesh) + 1], 1.0f);
  EXPECT_FLOAT_EQ(f.flat.light_cdf[RT_MESH_CDF(&mesh)], 0.5f);
  // Each instance names its light back.
  for (size_t i = 0; i < f.flat.instances.size(); ++i) {
    int l = f.flat.instance_lights[i];
    ASSERT_GE(l, 0);
    EXPECT_EQ(RT_LIGHT_INSTANCE(&f.flat.lights[l]), static_cast<int>(i));
  }
  // |det| of the sphere's transform: radius^3.
  EXPECT_FLOAT_EQ(RT_SPHERE_VOLUME_SCALE(&f.flat.lights[1]), 0.125f);
}

TEST(ObjectLightLoader, BadInputIsOneClearLine) {
  struct Case {
    std::string objects, fragment;
  } cases[] = {
      {Square("1 -2 1"), "Radiance: '1 -2 1' is negative"},
      {"<LightMesh id=\"1\"><Material>2</Material><Radiance>1 1 1</Radiance></LightMesh>", "Faces"},
      {"<LightSphere id=\"1\"><Material>2</Material><Center>5</Center><Radius>1</Radius>"
       "</LightSphere>",
       "Radiance"},
      {"<LightSphere id=\"1\"><Material>2</Material><Center>5</Center><Radius>0</Radius>"
       "<Radiance>1 1 1</Radiance></LightSphere>",
       "Radius: '0' must be positive"},
      {"<LightMesh id=\"1\"><Material>2</Material><Radiance>1 1 1</Radiance>"
       "<Faces>1 2 9</Faces></LightMesh>",
       "out of range"},
      {Square().insert(Square().find("</LightMesh>"), "<MotionBlur>1 0 0</MotionBlur>"),
       "MotionBlur"},
  };
  for (const Case& c : cases)
    test::expect_load_text_error(Scene(c.objects), "object_light_test.xml", {c.fragment});
}

// A uniformly emitting square of side 2a seen from distance h on its axis: irradiance
// E = 4 L X / sqrt(1 + X^2) atan(X / sqrt(1 + X^2)), X = a / h (four corner rectangles of
// the classic form factor), and solid angle 4 asin(a^2 / (a^2 + h^2)).
TEST(MeshLight, SquareOnItsAxisMatchesClosedForms) {
  Flat f = Load(Scene(Square()));
  for (double h : {0.25, 1.0, 4.0}) {
    Estimate est =
        Sample(f, make_float3(0, 0, static_cast<float>(h)), make_float3(0, 0, -1), 40000);
    double x = 1.0 / h, r = std::sqrt(1 + x * x);
    EXPECT_EQ(est.invalid, 0);
    EXPECT_ESTIMATE(est.e, est.e_se, 4 * 2.0 * x / r * std::atan(x / r));
    EXPECT_ESTIMATE(est.omega, est.omega_se, 4 * std::asin(1.0 / (1 + h * h)));
  }
}

// Only the front face emits: behind the square every sample is invalid, and a ray that
// hits it from behind finds no radiance; from the front it finds L.
TEST(MeshLight, EmitsFromItsFrontFaceOnly) {
  Flat f = Load(Scene(Square()));
  Estimate behind = Sample(f, make_float3(0.1f, 0.2f, -1), make_float3(0, 0, 1), 1000);
  EXPECT_EQ(behind.invalid, 1000);
  for (float z : {5.0f, -5.0f}) {
    Ray ray = MakeRay(make_float3(0.1f, 0.2f, z), make_float3(0, 0, z > 0 ? -1.0f : 1.0f),
                      RT_INFINITY, 0);
    Hit hit;
    ASSERT_TRUE(IntersectClosest(&f.sd, ray, 0, &hit));
    SurfacePoint s = ComputeSurface(&f.sd, ray, hit);
    EXPECT_EQ(HitLightIndex(&f.sd, hit), 0);
    EXPECT_EQ(EmittedRadiance(&f.sd, &s).x, z > 0 ? 2.0f : 0.0f) << "seen from z = " << z;
    // The density of a hit is the one sampling would give the same point.
    if (z > 0) {
      EXPECT_FLOAT_EQ(EmitterPdf(&f.sd, ray.origin, &s), 25.0f / 4.0f);
    }
  }
}

// A sphere of radius r at distance d, seen from a point facing its centre: E = pi L r^2 /
// d^2 and solid angle 2 pi (1 - sqrt(1 - r^2 / d^2)); every sample carries the same 1/pdf.
TEST(SphereLight, SphereOnItsAxisMatchesClosedForms) {
  for (double r : {0.5, 0.01}) {
    Flat f = Load(Scene(Ball(r)));
    for (double d : {0.6, 2.0, 30.0}) {
      if (d <= r) continue;
      Estimate est =
          Sample(f, make_float3(0, 0, static_cast<float>(d)), make_float3(0, 0, -1), 20000);
      double s2 = r * r / (d * d);
      EXPECT_EQ(est.invalid, 0);
      EXPECT_ESTIMATE(est.e, est.e_se, M_PI * 3.0 * s2);
      double omega = 2 * M_PI * (1 - std::sqrt(1 - s2));
      EXPECT_NEAR(est.omega, omega, 2e-4 * omega) << "r " << r << " d " << d;
    }
  }
}

// The ellipsoid (a sphere through a non-uniform scale), against uniform directions from
// the shading point intersected with it analytically: the density of the sampler
// integrates to one over the directions that hit it (E[4 pi pdf(w)] = 1), and the mean of
// its samples' 1/pdf is the solid angle it subtends (4 pi times the share of hits).
TEST(SphereLight, EllipsoidDensityAgainstBruteForce) {
  Flat f = Load(Scene(Ball(0.5, "<Transformations>s1</Transformations>"), "0 0 5",
                      "<Scaling id=\"1\">3 1 0.5</Scaling>"));
  const Light& light = FirstObjectLight(f);
  const Instance& inst = f.flat.instances[RT_LIGHT_INSTANCE(&light)];
  float3 p = make_float3(0.7f, 1.1f, 1.3f);
  double sum = 0, sum2 = 0, hits = 0, e_sum = 0, e_sum2 = 0;
  const int n = 400000;
  for (int i = 0; i < n; ++i) {
    float2 u = Uniform2(static_cast<uint>(i) + 1000000u);
    double z = 1 - 2.0 * u.x, rr = std::sqrt(std::max(0.0, 1 - z * z)), phi = 2 * M_PI * u.y;
    float3 w = make_float3(static_cast<float>(rr * std::cos(phi)),
                           static_cast<float>(rr * std::sin(phi)), static_cast<float>(z));
    // Object space: the unit sphere; the nearer root of |o + t d|^2 = 1.
    float3 o = TransformPoint(inst.world_to_object, p),
           d = TransformVector(inst.world_to_object, w);
    double a = Dot(d, d), b = Dot(o, d), c = Dot(o, o) - 1.0, disc = b * b - a * c;
    double v = 0, e = 0;
    if (disc > 0 && -b - std::sqrt(disc) > 0) {
      double t = (-b - std::sqrt(disc)) / a;
      float3 q = p + w * static_cast<float>(t);
      v = SphereLightPdf(&f.sd, &light, p, q) * 4 * M_PI;
      e = 3.0 * std::max(0.0, -double(w.z)) * 4 * M_PI;  // L cos / uniform pdf.
      ++hits;
    }
    sum += v, sum2 += v * v, e_sum += e, e_sum2 += e * e;
  }
  double mean = sum / n, se = std::sqrt((sum2 / n - mean * mean) / n);
  ASSERT_GT(hits, 1000);
  EXPECT_NEAR(mean, 1.0, 4.5 * se + 1e-3) << "se " << se;
  double share = hits / n, omega = 4 * M_PI * share;
  double omega_se = 4 * M_PI * std::sqrt(share * (1 - share) / n);
  Estimate est = Sample(f, p, make_float3(0, 0, -1), 100000);
  EXPECT_EQ(est.invalid, 0);
  EXPECT_NEAR(est.omega, omega, 4.5 * std::hypot(omega_se, est.omega_se) + 1e-4 * omega);
  // --ellipsoid-lights exact: the irradiance on a surface facing -z, against brute force.
  f.flat.header.flags |= RT_FLAG_EXACT_ELLIPSOID_LIGHTS;
  double e = e_sum / n, e_se = std::sqrt((e_sum2 / n - e * e) / n);
  Estimate exact = Sample(f, p, make_float3(0, 0, -1), 100000);
  EXPECT_NEAR(exact.e, e, 4.5 * std::hypot(e_se, exact.e_se)) << "se " << e_se;
  // The course's convention: radiance times the object-space cone's solid angle, here
  // (with the point above the ellipsoid's flat axis) well below the exact irradiance.
  f.flat.header.flags &= ~RT_FLAG_EXACT_ELLIPSOID_LIGHTS;
  float3 pc = TransformPoint(inst.world_to_object, p);
  double omega_obj = 2 * M_PI * (1 - std::sqrt(1 - 1 / Dot(pc, pc)));
  LightSampleContext ctx = MakeLightSampleContext(p, make_float3(0, 0, -1), make_float3(0, 0, -1));
  LightSample ls = SampleSphereLight(&f.sd, &light, &ctx, make_float2(0.3f, 0.6f));
  EXPECT_NEAR(ls.irradiance.x, 3.0 * omega_obj, 1e-5 * 3.0 * omega_obj);
  EXPECT_LT(Sample(f, p, make_float3(0, 0, -1), 100000).e, 0.9 * exact.e);
}

// The OpenCL kernel against the CPU reference on the course's object-light scenes, at
// a reduced size: every pixel's sums bit for bit.
TEST(ObjectLightDevices, KernelMatchesCpuBitForBit) {
  std::string why;
  RenderDevice* cl = test::shared_device(Device::kOpenCl, &why);
  if (!cl) GTEST_SKIP() << "no OpenCL device: " << why;
  const std::string dir = std::string(RT_SHARED_SCENES_DIR) + "/hw6/directLighting/";
  for (const char* name :
       {"diffuse_area", "glossy_area_small", "glossy_area_sphere", "glossy_area_ellipsoid"}) {
    std::string path = dir + "cornellbox_jaroslav_" + name + ".xml";
    SceneDesc scene;
    try {
      scene = load_scene(path);
    } catch (const InputError& e) {
      GTEST_SKIP() << "course scene missing: " << e.what();
    }
    RenderOptions opt;
    opt.spp = 4;
    FlatScene flat = prepare_scene(scene, opt);
    prepare_camera(flat, scene, 0, opt);
    flat.header.camera.width = flat.header.camera.height = 48;
    RenderResult a = test::render_on(*cl, flat), b = test::render_cpu(flat);
    ASSERT_EQ(a.accum.size(), b.accum.size());
    size_t same = 0;
    for (size_t i = 0; i < a.accum.size(); ++i)
      same += std::memcmp(&a.accum[i], &b.accum[i], sizeof(PixelAccum)) == 0;
    EXPECT_EQ(same, a.accum.size()) << name;
    float peak = 0;
    for (float v : b.rgb()) peak = std::max(peak, v);
    EXPECT_GT(peak, 0.0f) << name << ": black image";
  }
}

}  // namespace
}  // namespace rt
