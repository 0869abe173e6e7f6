// SphericalDirectionalLight in scene files: the loader's reading of its map, mapping and
// sampler, one clear line for each kind of bad input, and the course's hw5 scenes, whose
// maps are not available here (../shared/scenes/SOURCES.md): they fail for the missing map
// alone, and render with a generated stand-in map.
#include <gtest/gtest.h>
#include <unistd.h>

#include <cstring>
#include <filesystem>
#include <fstream>
#include <string>
#include <vector>

#include "cl/light/environment_map.h"
#include "integrator/render.h"
#include "io/image_output.h"
#include "prepare/flat_scene.h"
#include "scene/scene.h"
#include "support/device_harness.h"
#include "util/errors.h"

namespace fs = std::filesystem;

namespace rt {
namespace {

const std::string kScenes = RT_SHARED_SCENES_DIR;

// A fresh folder per test, removed at the end.
struct TempDir {
  fs::path path;
  TempDir() {
    path = fs::path(testing::TempDir()) /
           ("envlight_" + std::to_string(getpid()) + "_" +
            testing::UnitTest::GetInstance()->current_test_info()->name());
    fs::create_directories(path / "textures");
  }
  ~TempDir() { fs::remove_all(path); }
};

// A w x h map whose texel (x, y) holds (x + 1, y + 1, 1): every texel tells where it is.
void WriteMap(const std::string& path, int w, int h) {
  std::vector<float> rgb;
  for (int y = 0; y < h; ++y)
    for (int x = 0; x < w; ++x) rgb.insert(rgb.end(), {x + 1.0f, y + 1.0f, 1.0f});
  write_image(path, w, h, rgb);
}

std::string Scene(const std::string& light, const std::string& image = "textures/env.exr") {
  return R"(<Scene>
  <Cameras><Camera id="1"><Position>0 0 0</Position><Gaze>0 0 -1</Gaze><Up>0 1 0</Up>
    <NearPlane>-1 1 -1 1</NearPlane><NearDistance>1</NearDistance>
    <ImageResolution>4 4</ImageResolution><ImageName>out.exr</ImageName></Camera></Cameras>
  <Textures><Images><Image id="1">)" +
         image + R"(</Image></Images></Textures>
  <Lights>)" +
         light +
         R"(</Lights>
  <Materials><Material id="1"><DiffuseReflectance>1 1 1</DiffuseReflectance></Material></Materials>
  <VertexData>0 0 -6</VertexData>
  <Objects><Sphere id="1"><Material>1</Material><Center>1</Center><Radius>1</Radius></Sphere></Objects>
</Scene>)";
}

std::string Write(const TempDir& dir, const std::string& xml) {
  std::string path = (dir.path / "scene.xml").string();
  std::ofstream(path) << xml;
  return path;
}

// The load's error: one line naming the file, the element and `value`.
std::string LoadError(const std::string& path) {
  try {
    load_scene(path);
  } catch (const InputError& e) {
    return e.what();
  }
  return "(loaded without an error)";
}

void ExpectOneLine(const std::string& message, const std::string& file,
                   const std::vector<std::string>& parts) {
  EXPECT_EQ(message.find('\n'), std::string::npos) << message;
  EXPECT_NE(message.find(file), std::string::npos) << message;
  for (const std::string& p : parts) EXPECT_NE(message.find(p), std::string::npos) << message;
}

TEST(EnvironmentLightScene, ReadsMapMappingAndSampler) {
  TempDir dir;
  WriteMap((dir.path / "textures/env.exr").string(), 8, 4);
  SceneDesc s = load_scene(Write(dir, Scene(R"(<SphericalDirectionalLight id="1" type="probe">
      <ImageId>1</ImageId><Sampler>cosine</Sampler></SphericalDirectionalLight>)")));
  ASSERT_EQ(s.lights.size(), 1u);
  EXPECT_EQ(s.lights[0].type, RT_LIGHT_ENVIRONMENT);
  EXPECT_EQ(RT_ENV_MAPPING(&s.lights[0]), RT_ENV_PROBE);
  EXPECT_EQ(RT_ENV_SAMPLING(&s.lights[0]), RT_ENV_SAMPLE_COSINE);
  EXPECT_EQ(s.environment_map.width, 8);
  EXPECT_EQ(s.environment_map.at(3, 2, 0), 4.0f);
  SceneDesc d = load_scene(Write(dir, Scene("<SphericalDirectionalLight id=\"1\"><ImageId>1"
                                            "</ImageId></SphericalDirectionalLight>")));
  EXPECT_EQ(RT_ENV_MAPPING(&d.lights[0]),
            RT_ENV_LATLONG);  // The specification's mapping by default.
  EXPECT_EQ(RT_ENV_SAMPLING(&d.lights[0]), RT_ENV_SAMPLE_IMPORTANCE);
  RenderOptions opt;
  FlatScene flat = prepare_scene(d, opt);
  prepare_camera(flat, d, 0, opt);
  EXPECT_NE(flat.header.features & RT_FEATURE_ENVIRONMENT_LIGHT, 0);
  EXPECT_EQ(flat.header.environment, 0);
  EXPECT_EQ(flat.env_marginal_cdf.size(), 5u);
  EXPECT_EQ(flat.env_conditional_cdf.size(), 4u * 9u);
  EXPECT_EQ(flat.env_marginal_cdf.back(), 1.0f);
}

TEST(EnvironmentLightScene, BadInputIsOneClearLine) {
  TempDir dir;
  WriteMap((dir.path / "textures/env.exr").string(), 8, 4);
  std::ofstream(dir.path / "textures/broken.exr") << "not an EXR file";
  const std::string light = "SphericalDirectionalLight";
  struct Case {
    std::string xml;
    std::vector<std::string> parts;
  } cases[] = {
      {Scene("<" + light + " id=\"1\"><ImageId>1</ImageId></" + light + ">", "textures/none.exr"),
       {light, "ImageId", "textures/none.exr"}},
      {Scene("<" + light + " id=\"1\"><ImageId>1</ImageId></" + light + ">", "textures/broken.exr"),
       {light, "ImageId", "textures/broken.exr", "cannot read EXR"}},
      {Scene("<" + light + " id=\"1\" type=\"cube\"><ImageId>1</ImageId></" + light + ">"),
       {light, "'cube'", "latlong", "probe"}},
      {Scene("<" + light + " id=\"1\"><ImageId>1</ImageId><Sampler>random</Sampler></" + light +
             ">"),
       {light, "Sampler", "'random'"}},
      {Scene("<" + light + " id=\"1\"><ImageId>7</ImageId></" + light + ">"),
       {light, "ImageId", "'7'"}},
      {Scene("<" + light + " id=\"1\"></" + light + ">"), {light, "ImageId"}},
      {Scene("<" + light + " id=\"1\"><ImageId>1</ImageId></" + light + "><" + light +
             " id=\"2\"><ImageId>1</ImageId></" + light + ">"),
       {light, "id=2", "second environment light"}},
  };
  for (const Case& c : cases) {
    std::string path = Write(dir, c.xml);
    ExpectOneLine(LoadError(path), path, c.parts);
  }
  // A map with a negative or NaN texel would give a NaN image: refused, naming the texel.
  std::vector<float> rgb(2 * 2 * 3, 1.0f);
  rgb[(1 * 2 + 0) * 3 + 1] = -2.0f;
  write_image((dir.path / "textures/negative.exr").string(), 2, 2, rgb);
  std::string path =
      Write(dir, Scene("<" + light + " id=\"1\"><ImageId>1</ImageId></" + light + ">",
                       "textures/negative.exr"));
  ExpectOneLine(LoadError(path), path, {light, "texel (0, 1)", "-2"});
}

// The hw5 scenes with environment maps load up to the map, and fail naming it.
TEST(EnvironmentLightScene, CourseScenesFailOnlyForTheMissingMap) {
  struct Case {
    const char* scene;
    const char* map;
  } cases[] = {{"/hw5/glass_sphere_env.xml", "textures/grace-new.exr"},
               {"/hw5/mirror_sphere_env.xml", "textures/grace-new.exr"},
               {"/hw5/sphere_env_light.xml", "textures/pisa_latlong.exr"}};
  for (const Case& c : cases) {
    std::string path = kScenes + c.scene;
    if (!fs::exists(path)) GTEST_SKIP() << path << " is not here (../shared/scenes)";
    if (fs::exists(fs::path(path).parent_path() / c.map)) continue;  // Complete after all.
    ExpectOneLine(LoadError(path), path,
                  {"SphericalDirectionalLight", "ImageId", c.map, "cannot read EXR"});
  }
}

// mirror_sphere_env with a generated map in place of grace-new.exr: the camera sees the map
// around the sphere, texel for texel, and the mirror sphere reflects it; both devices agree.
TEST(EnvironmentLightScene, CourseSceneRendersWithAStandInMap) {
  std::string original = kScenes + "/hw5/mirror_sphere_env.xml";
  if (!fs::exists(original)) GTEST_SKIP() << original << " is not here (../shared/scenes)";
  TempDir dir;
  fs::copy_file(original, dir.path / "scene.xml");
  const int w = 64, h = 32;
  WriteMap((dir.path / "textures/grace-new.exr").string(), w, h);
  SceneDesc s = load_scene((dir.path / "scene.xml").string());
  RenderOptions opt;
  FlatScene flat = prepare_scene(s, opt);
  prepare_camera(flat, s, 0, opt);
  flat.header.camera.width = 100;  // Fewer pixels over the same film.
  flat.header.camera.height = 50;
  RenderResult r = test::render_cpu(flat, 2);
  const Camera& cam = flat.header.camera;
  // The top-left pixel misses the sphere: it shows the texel of its ray's direction.
  float x = cam.left + (cam.right - cam.left) * 0.5f / cam.width;
  float y = cam.top - (cam.top - cam.bottom) * 0.5f / cam.height;
  float3 d = Normalize(cam.u * x + cam.v * y - cam.w * cam.near_distance);
  int texel = EnvTexelIndex(EnvDirectionToUV(RT_ENV_LATLONG, d), w, h);
  EXPECT_EQ(r.accum[0].sum.x, texel % w + 1.0f);
  EXPECT_EQ(r.accum[0].sum.y, texel / w + 1.0f);
  // The centre pixel sees the sphere reflect what lies behind the camera (+z): the
  // map's left and right edges, columns 0 and w - 1, around its middle rows.
  const PixelAccum& c = r.accum[(cam.height / 2) * cam.width + cam.width / 2];
  EXPECT_TRUE(c.sum.x == 1.0f || c.sum.x == float(w)) << c.sum.x;
  EXPECT_NEAR(c.sum.y, h / 2 + 0.5f, 1.0f);
  std::string why;
  if (RenderDevice* cl = test::shared_device(Device::kOpenCl, &why)) {
    RenderResult rc = test::render_on(*cl, flat);
    size_t same = 0;
    for (size_t i = 0; i < r.accum.size(); ++i)
      same += std::memcmp(&rc.accum[i].sum, &r.accum[i].sum, sizeof(float4)) == 0;
    EXPECT_EQ(same, r.accum.size()) << "OpenCL and the CPU differ";
  }
}

}  // namespace
}  // namespace rt
