// The path tracer (cl/integrator/path.h) against closed forms, on the CPU reference:
// furnaces whose radiance is a geometric series in the albedo, truncated where the bounce
// limit says, with and without importance sampling and Russian roulette. Statistical
// checks accept |mean - expected| <= 4.5 standard errors (a false alarm has probability
// below 1e-5 per check, normal approximation over >= 20000 samples) plus 2e-4 relative for
// the float sums of the film (their rounding over 40000 samples stays below it); estimators
// without variance are checked to that rounding alone.
#include <gtest/gtest.h>

#include <array>
#include <cmath>
#include <string>
#include <vector>

#include "cl/material/brdf.h"
#include "util/errors.h"
#include "prepare/flat_scene.h"
#include "support/device_harness.h"
#include "support/pixel_estimate.h"
#include "support/test_scene.h"

namespace {

using rt::test::ExpectMean;
using rt::test::Lambert;
using rt::test::PixelStats;
using rt::test::RenderOnePixel;

// The shared point camera (tests/support/test_scene.h), rendering with the path tracer.
rt::CameraDesc PointCamera(rt::Vec3d eye, int samples, int path_flags) {
  rt::CameraDesc c = rt::test::PointCamera(eye, samples);
  c.path_tracing = true;
  c.path_flags = path_flags;
  return c;
}

rt::ObjectDesc Sphere(double radius) {
  rt::ObjectDesc o;
  o.kind = rt::ObjectDesc::kSphere;
  o.transform = rt::Mat4::scaling({radius, radius, radius});
  return o;
}

// The light furnace: a point light of intensity I at the centre of a closed sphere of
// radius R and albedo a, seen from the centre. Every wall point receives I / R^2 directly
// and, from a wall of uniform radiance L, pi L: each bounce adds a times the last, so with
// next-event estimation at each vertex of D scatterings (the last one included, as the
// course does) the radiance is L1 (1 + a + ... + a^D), L1 = (a / pi) I / R^2.
constexpr double kAlbedo = 0.5, kIntensity = 100, kRadius = 2;
constexpr double kL1 = kAlbedo / M_PI * kIntensity / (kRadius * kRadius);

rt::SceneDesc LightFurnace(int depth, int samples, int path_flags) {
  rt::SceneDesc s;
  s.max_depth = depth;
  s.cameras.push_back(PointCamera({0, 0, 0}, samples, path_flags));
  s.materials.push_back(Lambert(kAlbedo));
  s.objects.push_back(Sphere(kRadius));
  PointLight light{};
  light.position = rt::Vec3d{0, 0, 0};
  light.intensity = make_float3(kIntensity, kIntensity, kIntensity);
  s.point_lights.push_back(light);
  return s;
}

double Geometric(double a, int terms) { return (1 - std::pow(a, terms)) / (1 - a); }

TEST(PathTracing, LightFurnaceIsTheTruncatedSeries) {
  const int nee = RT_FLAG_NEXT_EVENT, importance = RT_FLAG_IMPORTANCE_SAMPLING;
  for (int depth : {0, 1, 3, 6}) {
    double expected = kL1 * Geometric(kAlbedo, depth + 1);
    // Cosine-weighted bounces weigh exactly a each: the estimate has no variance.
    ExpectMean(RenderOnePixel(LightFurnace(depth, 16, nee | importance)), expected,
               "importance, depth " + std::to_string(depth));
    ExpectMean(RenderOnePixel(LightFurnace(depth, 20000, nee)), expected,
               "uniform, depth " + std::to_string(depth));
  }
}

TEST(PathTracing, UnbiasedRouletteMatchesTheUntruncatedSeries) {
  const int flags = RT_FLAG_NEXT_EVENT | RT_FLAG_RUSSIAN_ROULETTE;
  rt::RenderOptions unbiased;
  unbiased.unbiased_roulette = true;
  double infinite = kL1 / (1 - kAlbedo);
  for (int importance : {0, RT_FLAG_IMPORTANCE_SAMPLING}) {
    std::string what = importance ? "importance" : "uniform";
    PixelStats rr = RenderOnePixel(LightFurnace(3, 40000, flags | importance), unbiased);
    ExpectMean(rr, infinite, "roulette, " + what);
    // The same mean as without roulette at a depth whose truncation is below 1e-9.
    PixelStats deep = RenderOnePixel(LightFurnace(30, 20000, RT_FLAG_NEXT_EVENT | importance));
    ExpectMean(deep, infinite, "depth 30, " + what);
    rt::test::ExpectSameMean(rr, deep, what);
  }
}

rt::MeshDesc Square(double half, double z, bool facing_down) {
  rt::MeshDesc m;
  m.positions = {{-half, -half, z}, {half, -half, z}, {half, half, z}, {-half, half, z}};
  m.triangles = facing_down ? std::vector<std::array<int, 3>>{{0, 2, 1}, {0, 3, 2}}
                            : std::vector<std::array<int, 3>>{{0, 1, 2}, {0, 2, 3}};
  return m;
}

// A floor of albedo a under a black square ceiling light (LightMesh) of half-size s at
// height h, radiance Le, seen from above at the point below the light's centre. The floor
// point receives E = 4 pi Le F(s, s, h), F the differential form factor to an s x s
// rectangle over its corner, and reflects (a / pi) E; nothing else bounces back.
constexpr double kLe = 30, kHalf = 1, kHeight = 1;

double CeilingRadiance() {
  double x = kHalf / kHeight, y = kHalf / kHeight;
  double f = (x / std::sqrt(1 + x * x) * std::atan(y / std::sqrt(1 + x * x)) +
              y / std::sqrt(1 + y * y) * std::atan(x / std::sqrt(1 + y * y))) /
             (2 * M_PI);
  return kAlbedo / M_PI * 4 * M_PI * kLe * f;
}

rt::SceneDesc CeilingLight(int samples, int path_flags) {
  rt::SceneDesc s;
  s.max_depth = 3;
  s.cameras.push_back(PointCamera({0, 0, 0.5}, samples, path_flags));
  s.materials.push_back(Lambert(kAlbedo));
  s.materials.push_back(Lambert(0));
  s.meshes.push_back(Square(50, 0, false));
  s.meshes.push_back(Square(kHalf, kHeight, true));
  rt::ObjectDesc floor, light;
  floor.mesh = 0;
  light.mesh = 1;
  light.material = 1;
  light.emits = true;
  light.radiance = {kLe, kLe, kLe};
  s.objects = {floor, light};
  return s;
}

// Paths that find the light by a bounce and light samples estimate the same radiance.
TEST(PathTracing, NextEventEstimationAgreesWithBounces) {
  for (int importance : {0, RT_FLAG_IMPORTANCE_SAMPLING}) {
    std::string what = importance ? "importance" : "uniform";
    ExpectMean(RenderOnePixel(CeilingLight(40000, importance)), CeilingRadiance(),
               "bounces, " + what);
    ExpectMean(RenderOnePixel(CeilingLight(40000, importance | RT_FLAG_NEXT_EVENT)),
               CeilingRadiance(), "light samples, " + what);
  }
}

// The course's roulette (path.h, RouletteSurvives): at the light (the second hit, q = the
// floor's BRDF value a / pi) a path that dies keeps the emission and a surviving one
// divides it by q, so the light counts (2 - a / pi) times; the unbiased roulette counts it
// once.
TEST(PathTracing, CourseRouletteCountsADyingPathsLight) {
  const int flags = RT_FLAG_RUSSIAN_ROULETTE | RT_FLAG_IMPORTANCE_SAMPLING;
  PixelStats course = RenderOnePixel(CeilingLight(40000, flags));
  ExpectMean(course, CeilingRadiance() * (2 - kAlbedo / M_PI), "course roulette");
  rt::RenderOptions unbiased;
  unbiased.unbiased_roulette = true;
  ExpectMean(RenderOnePixel(CeilingLight(40000, flags), unbiased), CeilingRadiance(),
             "unbiased roulette");
}

// The sky furnace: a convex sphere of albedo a under a uniform background B (seen by rays
// that escape, --background-on-secondary-miss) reflects a B after one bounce, whatever the
// bounce limit beyond it; this exercises the BSDF sampling without light sampling.
TEST(PathTracing, SkyFurnaceReflectsAlbedoTimesSky) {
  const double sky = 80;
  for (int importance : {0, RT_FLAG_IMPORTANCE_SAMPLING}) {
    rt::SceneDesc s;
    s.max_depth = 2;
    s.background = {sky, sky, sky};
    s.cameras.push_back(PointCamera({0, 0, 5}, importance ? 16 : 20000, importance));
    s.materials.push_back(Lambert(kAlbedo));
    s.objects.push_back(Sphere(1));
    rt::RenderOptions opt;
    opt.background_on_secondary_miss = true;
    ExpectMean(RenderOnePixel(s, opt), kAlbedo * sky, importance ? "importance" : "uniform");
  }
}

// Without next-event estimation a point light cannot be found by a path (it is not part of
// the geometry), so the light furnace is black; the sky furnace does not need it.
TEST(PathTracing, PointLightsNeedNextEventEstimation) {
  EXPECT_EQ(RenderOnePixel(LightFurnace(3, 16, RT_FLAG_IMPORTANCE_SAMPLING)).mean, 0.0);
}

const char* kCamera = R"(<Scene><Cameras><Camera id="1">
  <Position>0 0 5</Position><Gaze>0 0 -1</Gaze><Up>0 1 0</Up>
  <NearPlane>-1 1 -1 1</NearPlane><NearDistance>1</NearDistance>
  <ImageResolution>4 4</ImageResolution><ImageName>x.png</ImageName>
  RENDERER
</Camera></Cameras>
<Materials><Material id="1"><DiffuseReflectance>1 1 1</DiffuseReflectance></Material></Materials>
<VertexData>0 0 0 1 0 0 0 1 0</VertexData>
<Objects><Mesh id="1"><Material>1</Material><Faces>1 2 3</Faces></Mesh></Objects></Scene>)";

rt::SceneDesc LoadWithRenderer(const std::string& renderer) {
  std::string xml = kCamera;
  xml.replace(xml.find("RENDERER"), 8, renderer);
  return rt::load_scene_text(xml, "s.xml");
}

TEST(PathTracing, RendererElementsAreRead) {
  rt::SceneDesc plain = LoadWithRenderer("");
  EXPECT_FALSE(plain.cameras[0].path_tracing);
  rt::SceneDesc uniform =
      LoadWithRenderer("<Renderer>PathTracing</Renderer><RendererParams></RendererParams>");
  EXPECT_TRUE(uniform.cameras[0].path_tracing);
  EXPECT_EQ(uniform.cameras[0].path_flags, 0);
  rt::SceneDesc all = LoadWithRenderer(
      "<Renderer> PathTracing </Renderer><RendererParams>NextEventEstimation "
      "ImportanceSampling\n RussianRoulette</RendererParams>");
  EXPECT_EQ(all.cameras[0].path_flags,
            RT_FLAG_NEXT_EVENT | RT_FLAG_IMPORTANCE_SAMPLING | RT_FLAG_RUSSIAN_ROULETTE);
  auto features = [](const rt::SceneDesc& s) {
    rt::FlatScene flat = rt::prepare_scene(s, rt::RenderOptions());
    rt::prepare_camera(flat, s, 0, rt::RenderOptions());
    return flat.header.features;
  };
  EXPECT_TRUE(features(all) & RT_FEATURE_PATH_TRACING);
  EXPECT_FALSE(features(plain) & RT_FEATURE_PATH_TRACING);
}

// One line naming the file, the element and the word.
TEST(PathTracing, BadRendererInputIsOneClearLine) {
  const std::pair<const char*, const char*> cases[] = {
      {"<Renderer>PathTracing</Renderer><RendererParams>NextEventEstimation Importance"
       "</RendererParams>",
       "Camera id=1 > RendererParams: 'Importance' is not a path-tracing option"},
      {"<Renderer>PhotonMapping</Renderer>",
       "Camera id=1 > Renderer: 'PhotonMapping' is not supported"},
      {"<RendererParams>RussianRoulette</RendererParams>",
       "Camera id=1 > RendererParams: 'RussianRoulette' needs <Renderer>PathTracing"},
  };
  for (const auto& c : cases) {
    try {
      LoadWithRenderer(c.first);
      ADD_FAILURE() << "accepted: " << c.first;
    } catch (const rt::InputError& e) {
      std::string what = e.what();
      EXPECT_EQ(what.rfind("s.xml: ", 0), 0u) << what;
      EXPECT_NE(what.find(c.second), std::string::npos) << what;
      EXPECT_EQ(what.find('\n'), std::string::npos) << what;
    }
  }
}

}  // namespace
