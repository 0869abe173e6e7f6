#include "support/test_scene.h"

#include <unistd.h>

#include <fstream>
#include <iterator>

#include "util/errors.h"
#include "scene/scene.h"

namespace rt::test {

namespace fs = std::filesystem;

const char* const kTinyScene = R"(<Scene>
    <BackgroundColor>0 0 0</BackgroundColor>
    <ShadowRayEpsilon>1e-3</ShadowRayEpsilon>
    <IntersectionTestEpsilon>1e-6</IntersectionTestEpsilon>
    <Cameras>
        <Camera id="1">
            <Position>0 0 0</Position>
            <Gaze>0 0 -1</Gaze>
            <Up>0 1 0</Up>
            <NearPlane>-1 1 -0.5 0.5</NearPlane>
            <NearDistance>1</NearDistance>
            <ImageResolution>16 8</ImageResolution>
            <ImageName>simple.png</ImageName>
        </Camera>
    </Cameras>
    <Lights>
        <AmbientLight>25 25 25</AmbientLight>
        <PointLight id="1">
            <Position>0 0 0</Position>
            <Intensity>1000 1000 1000</Intensity>
        </PointLight>
    </Lights>
    <Materials>
        <Material id="1">
            <AmbientReflectance>1 1 1</AmbientReflectance>
            <DiffuseReflectance>1 1 1</DiffuseReflectance>
            <SpecularReflectance>1 1 1</SpecularReflectance>
            <PhongExponent>1</PhongExponent>
        </Material>
    </Materials>
    <VertexData>
        -0.5 0.5 -2
        -0.5 -0.5 -2
        0.5 -0.5 -2
        0.5 0.5 -2
        0.75 0.75 -2
        1 0.75 -2
        0.875 1 -2
        -0.875 1 -2
    </VertexData>
    <Objects>
        <Mesh id="1">
            <Material>1</Material>
            <Faces>
                3 1 2
                1 3 4
            </Faces>
        </Mesh>
        <Triangle id="1">
            <Material>1</Material>
            <Indices>
                5 6 7
            </Indices>
        </Triangle>
        <Sphere id="1">
            <Material>1</Material>
            <Center>8</Center>
            <Radius>0.3</Radius>
        </Sphere>
    </Objects>
</Scene>
)";

std::string replaced(std::string s, const std::string& from, const std::string& to) {
  const size_t at = s.find(from);
  EXPECT_NE(at, std::string::npos) << "the scene lacks: " << from;
  if (at == std::string::npos) return s;
  EXPECT_EQ(s.find(from, at + 1), std::string::npos) << "the scene has twice: " << from;
  return s.replace(at, from.size(), to);
}

std::string tiny_scene_with_ply_mesh(const std::string& ply) {
  return replaced(kTinyScene,
                  "<Faces>\n                3 1 2\n                1 3 4\n            </Faces>",
                  "<Faces plyFile=\"" + ply + "\"/>");
}

std::string replaced_all(std::string s, const std::string& from, const std::string& to) {
  for (size_t at = 0; (at = s.find(from, at)) != std::string::npos; at += to.size())
    s.replace(at, from.size(), to);
  return s;
}

std::string edited(std::string s, const Edits& edits) {
  for (const auto& [from, to] : edits) s = replaced(std::move(s), from, to);
  return s;
}

std::string slurp(const fs::path& p) {
  std::ifstream in(p, std::ios::binary);
  return {std::istreambuf_iterator<char>(in), {}};
}

namespace {

// Runs `load`, expecting an InputError of one line that starts with "name: " (or "name:LINE: "
// for malformed XML) and contains
// every one of `parts`; returns its message.
template <class Load>
std::string expect_error_of(const Load& load, const std::string& name,
                            std::initializer_list<std::string> parts) {
  try {
    SceneDesc s = load();
    ADD_FAILURE() << "loaded without error (" << s.cameras.size() << " cameras)";
    return "";
  } catch (const InputError& e) {
    std::string msg = e.what();
    EXPECT_EQ(msg.find('\n'), std::string::npos) << "not one line: " << msg;
    EXPECT_EQ(msg.rfind(name + ":", 0), 0u) << "does not start with the file: " << msg;
    for (const auto& part : parts)
      EXPECT_NE(msg.find(part), std::string::npos) << "'" << part << "' missing in: " << msg;
    return msg;
  }
}

}  // namespace

std::string expect_load_error(const std::string& path, std::initializer_list<std::string> parts) {
  return expect_error_of([&] { return load_scene(path); }, path, parts);
}

std::string expect_load_text_error(const std::string& xml, const std::string& name,
                                   std::initializer_list<std::string> parts,
                                   const LoadOptions& options) {
  return expect_error_of([&] { return load_scene_text(xml, name, options); }, name, parts);
}

void TempDirTest::SetUp() {
  const auto* info = ::testing::UnitTest::GetInstance()->current_test_info();
  std::string name = std::string(info->test_suite_name()) + "_" + info->name();
  for (char& c : name)
    if (c == '/') c = '_';  // Parameterised tests name themselves "Prefix/Suite.Name/0".
  dir_ = fs::temp_directory_path() / ("rt_test_" + std::to_string(getpid()) + "_" + name);
  fs::remove_all(dir_);
  fs::create_directories(dir_);
}

void TempDirTest::TearDown() {
  std::error_code ec;  // Never throw from TearDown.
  fs::remove_all(dir_, ec);
}

std::string TempDirTest::write(const std::string& name, const std::string& text) {
  const fs::path p = dir_ / name;
  fs::create_directories(p.parent_path());
  std::ofstream(p, std::ios::binary) << text;
  return p.string();
}

CameraDesc PointCamera(Vec3d eye, int samples) {
  CameraDesc c;
  c.image_name = "x.png";
  c.position = eye;
  c.gaze = {0, 0, -1};
  c.up = {0, 1, 0};
  c.left = c.bottom = -1e-7;
  c.right = c.top = 1e-7;
  c.near_distance = 1;
  c.width = c.height = 1;
  c.samples = samples;
  return c;
}

}  // namespace rt::test
