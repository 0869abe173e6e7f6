// Bad-input tests for the scene loader: every rejected scene must end in one rt::InputError
// line naming the file, the element and the offending value; accepted oddities (unknown
// elements, degenerate triangles, CRLF, older dialects) must load with the right values.
#include <gtest/gtest.h>
#include <unistd.h>

#include <cmath>
#include <filesystem>
#include <fstream>
#include <initializer_list>
#include <string>
#include <utility>
#include <vector>

#include "errors.h"
#include "scene.h"

namespace rt {
namespace {

namespace fs = std::filesystem;

// Eight vertices, one mesh, one triangle and one sphere, like hw1/simple.xml but with a
// non-square resolution so aspect-ratio mistakes show.
const char* kBase = R"(<Scene>
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
            <ImageResolution>40 20</ImageResolution>
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

using Edits = std::vector<std::pair<std::string, std::string>>;

// Applies text replacements; each `from` must occur exactly once so a template change
// cannot silently turn a test into a no-op.
std::string edit(std::string xml, const Edits& edits) {
  for (const auto& [from, to] : edits) {
    size_t at = xml.find(from);
    EXPECT_NE(at, std::string::npos) << "template lacks: " << from;
    if (at == std::string::npos) continue;
    EXPECT_EQ(xml.find(from, at + 1), std::string::npos) << "template has twice: " << from;
    xml.replace(at, from.size(), to);
  }
  return xml;
}

std::string replace_all(std::string s, const std::string& from, const std::string& to) {
  for (size_t at = 0; (at = s.find(from, at)) != std::string::npos; at += to.size())
    s.replace(at, from.size(), to);
  return s;
}

class LoaderTest : public ::testing::Test {
 protected:
  void SetUp() override {
    const auto* info = ::testing::UnitTest::GetInstance()->current_test_info();
    dir_ = fs::temp_directory_path() / ("rt_loader_" + std::to_string(getpid()) + "_" +
                                        info->test_suite_name() + "_" + info->name());
    fs::remove_all(dir_);
    fs::create_directories(dir_);
  }
  void TearDown() override { fs::remove_all(dir_); }

  std::string write(const std::string& name, const std::string& text) {
    fs::path p = dir_ / name;
    fs::create_directories(p.parent_path());
    std::ofstream(p, std::ios::binary) << text;
    return p.string();
  }
  std::string scene(const Edits& edits) { return write("scene.xml", edit(kBase, edits)); }

  // Loads `path`, expecting an InputError whose one-line message contains every `part`.
  std::string expect_error(const std::string& path, std::initializer_list<std::string> parts) {
    try {
      SceneDesc s = load_scene(path);
      ADD_FAILURE() << "loaded without error (" << s.cameras.size() << " cameras)";
      return "";
    } catch (const InputError& e) {
      std::string msg = e.what();
      EXPECT_EQ(msg.find('\n'), std::string::npos) << "not one line: " << msg;
      EXPECT_EQ(msg.rfind(path + ": ", 0), 0u) << "does not start with the file: " << msg;
      for (const auto& part : parts)
        EXPECT_NE(msg.find(part), std::string::npos) << "'" << part << "' missing in: " << msg;
      return msg;
    }
  }
  // The same for a scene made from the template.
  std::string expect_error(const Edits& edits, std::initializer_list<std::string> parts) {
    return expect_error(scene(edits), parts);
  }

  fs::path dir_;
};

using LoaderErrors = LoaderTest;
using LoaderAccepts = LoaderTest;
using LoaderTransforms = LoaderTest;

// ---- Files and XML structure ----

TEST_F(LoaderErrors, MalformedXmlNamesTheLine) {
  std::string xml = edit(kBase, {{"<ImageName>simple.png</ImageName>", "<ImageName>simple.png"}});
  // tinyxml2 reports the line where the unclosed element starts (1-based).
  size_t at = xml.find("<ImageName>");
  int line = 1;
  for (size_t i = 0; i < at; ++i) line += xml[i] == '\n';
  std::string path = write("scene.xml", xml);
  expect_error(path, {"XML", "malformed", "line " + std::to_string(line) + " ", "<ImageName>"});
  // A broken attribute, at the end of a one-line file.
  expect_error(write("attr.xml", "<Scene><Cameras x=\"1></Scene>"), {"line 1 ", "<Cameras>"});
  expect_error(write("cut.xml", "<Scene>\n<Cameras>\n"), {"malformed", "line 2"});
}

TEST_F(LoaderErrors, MissingFile) {
  std::string path = (dir_ / "no_such_scene.xml").string();
  expect_error(path, {"cannot open"});
}

TEST_F(LoaderErrors, EmptyFileAndDirectory) {
  expect_error(write("empty.xml", ""), {"empty"});
  expect_error(write("blank.xml", "  \n\n  "), {"empty"});
  fs::create_directories(dir_ / "adir.xml");
  expect_error((dir_ / "adir.xml").string(), {"directory"});
}

TEST_F(LoaderErrors, NoSceneRoot) {
  expect_error(write("scene.xml", "<World><Cameras/></World>\n"), {"no <Scene>"});
}

TEST_F(LoaderErrors, NoCamera) {
  std::string xml = kBase;
  size_t b = xml.find("    <Cameras>"), e = xml.find("</Cameras>\n") + 11;
  xml.erase(b, e - b);
  ASSERT_EQ(xml.find("Camera"), std::string::npos);
  expect_error(write("scene.xml", xml), {"no <Camera>"});
  // An empty <Cameras> is no better.
  expect_error(write("scene2.xml", edit(xml, {{"<Lights>", "<Cameras></Cameras><Lights>"}})),
               {"no <Camera>"});
}

TEST_F(LoaderErrors, MissingRequiredCameraElement) {
  for (const char* line :
       {"<Position>0 0 0</Position>\n            <Gaze>", "<Gaze>0 0 -1</Gaze>", "<Up>0 1 0</Up>",
        "<NearPlane>-1 1 -0.5 0.5</NearPlane>", "<NearDistance>1</NearDistance>",
        "<ImageResolution>40 20</ImageResolution>", "<ImageName>simple.png</ImageName>"}) {
    std::string l = line;
    std::string name = l.substr(1, l.find('>') - 1);
    SCOPED_TRACE(name);
    // The Position line is written with the start of the Gaze line to keep it unique.
    std::string keep = l.find("\n") != std::string::npos ? "<Gaze>" : "";
    expect_error({{l, keep}}, {"Camera id=1", "missing <" + name + ">"});
  }
}

// ---- Numbers ----

TEST_F(LoaderErrors, NonFiniteOrNonNumericInVector) {
  for (const char* bad : {"nan", "NaN", "inf", "-Infinity", "abc", "1e999", "0x", "1,5"}) {
    SCOPED_TRACE(bad);
    expect_error({{"<Gaze>0 0 -1</Gaze>", std::string("<Gaze>0 ") + bad + " -1</Gaze>"}},
                 {"Camera id=1 > Gaze", std::string("'") + bad + "'"});
  }
  expect_error({{"<Intensity>1000 1000 1000</Intensity>", "<Intensity>1000 nan 1000</Intensity>"}},
               {"PointLight id=1 > Intensity", "'nan'"});
  expect_error({{"-0.5 -0.5 -2", "-0.5 inf -2"}}, {"VertexData", "'inf'"});
}

TEST_F(LoaderErrors, BeyondFloatRange) {
  // Finite in double, inf once the devices convert to float.
  expect_error({{"-0.5 -0.5 -2", "-0.5 1e39 -2"}}, {"VertexData", "'1e39'", "float"});
  expect_error({{"<Radius>0.3</Radius>", "<Radius>-4e38</Radius>"}},
               {"Sphere id=1 > Radius", "'-4e38'"});
}

TEST_F(LoaderErrors, SingularComposedTransform) {
  // Each factor is fine; radius^3 underflows to a zero determinant.
  expect_error({{"<Radius>0.3</Radius>", "<Radius>1e-120</Radius>"}}, {"Sphere id=1", "singular"});
}

TEST_F(LoaderErrors, WrongCountOfNumbers) {
  expect_error({{"<Gaze>0 0 -1</Gaze>", "<Gaze>0 -1</Gaze>"}},
               {"Camera id=1 > Gaze", "expected 3 numbers, got 2", "'0 -1'"});
  expect_error({{"<Gaze>0 0 -1</Gaze>", "<Gaze>0 0 -1 4</Gaze>"}},
               {"Camera id=1 > Gaze", "got 4", "'0 0 -1 4'"});
  expect_error({{"<Gaze>0 0 -1</Gaze>", "<Gaze></Gaze>"}}, {"Camera id=1 > Gaze", "got 0"});
  expect_error({{"<NearPlane>-1 1 -0.5 0.5</NearPlane>", "<NearPlane>-1 1 -0.5</NearPlane>"}},
               {"Camera id=1 > NearPlane", "got 3"});
  expect_error({{"-0.875 1 -2", "-0.875 1"}}, {"VertexData", "not a multiple of 3"});
  expect_error({{"1 3 4", "1 3"}}, {"Mesh id=1 > Faces", "not a multiple of 3"});
  // A value split over lines is still quoted on one line.
  expect_error({{"<Gaze>0 0 -1</Gaze>", "<Gaze>0\n  -1</Gaze>"}}, {"'0 -1'"});
}

// ---- Camera geometry ----

TEST_F(LoaderErrors, ZeroGaze) {
  expect_error({{"<Gaze>0 0 -1</Gaze>", "<Gaze>0 0 0</Gaze>"}},
               {"Camera id=1 > Gaze", "'0 0 0'", "zero"});
}

TEST_F(LoaderErrors, ZeroUp) {
  expect_error({{"<Up>0 1 0</Up>", "<Up>0 0 0</Up>"}}, {"Camera id=1 > Up", "'0 0 0'", "zero"});
}

TEST_F(LoaderErrors, UpParallelToGaze) {
  expect_error({{"<Up>0 1 0</Up>", "<Up>0 0 2</Up>"}}, {"Camera id=1 > Up", "'0 0 2'", "parallel"});
}

TEST_F(LoaderErrors, LookAtGazePointAtPosition) {
  expect_error({{"<Camera id=\"1\">", "<Camera id=\"1\" type=\"lookAt\">"},
                {"<Gaze>0 0 -1</Gaze>", "<GazePoint>0 0 0</GazePoint><FovY>45</FovY>"}},
               {"Camera id=1 > GazePoint", "'0 0 0'", "Position"});
}

TEST_F(LoaderErrors, GazePointWithoutLookAt) {
  expect_error({{"<Gaze>0 0 -1</Gaze>", "<GazePoint>0 0 -1</GazePoint><FovY>45</FovY>"}},
               {"Camera id=1", "missing <Gaze>", "lookAt"});
}

TEST_F(LoaderErrors, BadResolutionNearDistanceAndSamples) {
  expect_error(
      {{"<ImageResolution>40 20</ImageResolution>", "<ImageResolution>40 0</ImageResolution>"}},
      {"Camera id=1 > ImageResolution", "'40 0'"});
  expect_error(
      {{"<ImageResolution>40 20</ImageResolution>", "<ImageResolution>40.5 20</ImageResolution>"}},
      {"Camera id=1 > ImageResolution", "'40.5 20'"});
  expect_error({{"<NearDistance>1</NearDistance>", "<NearDistance>-1</NearDistance>"}},
               {"Camera id=1 > NearDistance", "'-1'"});
  expect_error({{"<ImageName>simple.png</ImageName>", "<ImageName>   </ImageName>"}},
               {"Camera id=1 > ImageName", "empty"});
}

TEST_F(LoaderErrors, NonSquareNumSamples) {
  expect_error({{"<ImageName>", "<NumSamples>8</NumSamples><ImageName>"}},
               {"Camera id=1 > NumSamples", "'8'", "not a perfect square"});
  expect_error({{"<ImageName>", "<NumSamples>0</NumSamples><ImageName>"}},
               {"Camera id=1 > NumSamples", "'0'"});
  expect_error({{"<ImageName>", "<NumSamples>4.5</NumSamples><ImageName>"}},
               {"Camera id=1 > NumSamples", "'4.5'"});
}

// ---- Lights ----

const char* kAreaLight = R"(<AreaLight id="1">
            <Position>0 1 -2</Position>
            <Normal>0 -1 0</Normal>
            <Size>2</Size>
            <Radiance>10 10 10</Radiance>
        </AreaLight>
    </Lights>)";

TEST_F(LoaderErrors, ZeroAreaLightNormal) {
  expect_error({{"</Lights>", replace_all(kAreaLight, "0 -1 0", "0 0 0")}},
               {"AreaLight id=1 > Normal", "'0 0 0'", "zero"});
}

TEST_F(LoaderErrors, NegativeAreaLightSize) {
  expect_error({{"</Lights>", replace_all(kAreaLight, "<Size>2", "<Size>-2")}},
               {"AreaLight id=1 > Size", "'-2'"});
}

TEST_F(LoaderErrors, NegativeLightValues) {
  expect_error({{"<Intensity>1000 1000 1000</Intensity>", "<Intensity>1000 -1 1000</Intensity>"}},
               {"PointLight id=1 > Intensity", "'1000 -1 1000'", "negative"});
  expect_error({{"</Lights>", replace_all(kAreaLight, "10 10 10", "10 10 -0.5")}},
               {"AreaLight id=1 > Radiance", "'10 10 -0.5'", "negative"});
  expect_error(
      {{"<AmbientLight>25 25 25</AmbientLight>", "<AmbientLight>-25 25 25</AmbientLight>"}},
      {"AmbientLight", "'-25 25 25'", "negative"});
}

// ---- References ----

TEST_F(LoaderErrors, MaterialIdThatDoesNotExist) {
  expect_error({{"<Material>1</Material>\n            <Faces>", "<Material>7</Material><Faces>"}},
               {"Mesh id=1 > Material", "'7'"});
  // Whitespace around the id is trimmed, both in the message and the lookup.
  expect_error(
      {{"<Material>1</Material>\n            <Center>", "<Material>\n  7  </Material><Center>"}},
      {"Sphere id=1 > Material", "'7'"});
  expect_error(
      {{"<Material>1</Material>\n            <Indices>", "<Material></Material><Indices>"}},
      {"Triangle id=1 > Material", "''"});
}

TEST_F(LoaderErrors, FaceIndexOutOfRange) {
  expect_error({{"1 3 4", "1 3 0"}}, {"Mesh id=1 > Faces", "vertex index 0", "[1, 8]"});
  expect_error({{"1 3 4", "1 9 4"}}, {"Mesh id=1 > Faces", "vertex index 9", "[1, 8]"});
  expect_error({{"1 3 4", "1 -3 4"}}, {"Mesh id=1 > Faces", "vertex index -3"});
  expect_error({{"5 6 7", "5 6 9"}}, {"Triangle id=1 > Indices", "vertex index 9"});
  // Huge values must not overflow an integer conversion into a bogus number.
  expect_error({{"1 3 4", "1 3 1e30"}}, {"Mesh id=1 > Faces", "1e+30"});
}

TEST_F(LoaderErrors, SphereCenterOutOfRange) {
  expect_error({{"<Center>8</Center>", "<Center>9</Center>"}},
               {"Sphere id=1 > Center", "vertex index 9", "[1, 8]"});
  expect_error({{"<Center>8</Center>", "<Center>0</Center>"}},
               {"Sphere id=1 > Center", "vertex index 0"});
  expect_error({{"<Center>8</Center>", "<Center>-3e38</Center>"}},
               {"Sphere id=1 > Center", "vertex index -3e+38"});
}

TEST_F(LoaderErrors, NonIntegerIndex) {
  expect_error({{"1 3 4", "1 3.5 4"}}, {"Mesh id=1 > Faces", "'3.5'", "not a whole number"});
  expect_error({{"1 3 4", "1 x 4"}}, {"Mesh id=1 > Faces", "'x'"});
  expect_error({{"<Center>8</Center>", "<Center>2.5</Center>"}}, {"Sphere id=1 > Center", "'2.5'"});
  expect_error({{"<Faces>", "<Faces vertexOffset=\"one\">"}},
               {"Mesh id=1 > Faces", "vertexOffset", "'one'"});
}

TEST_F(LoaderErrors, UnknownTransformationReference) {
  expect_error({{"<Objects>",
                 "<Transformations><Translation id=\"1\">1 0 0</Translation>"
                 "</Transformations><Objects>"},
                {"<Material>1</Material>\n            <Faces>",
                 "<Material>1</Material><Transformations>t1 t9</Transformations><Faces>"}},
               {"Mesh id=1 > Transformations", "'t9'"});
}

TEST_F(LoaderErrors, SingularTransform) {
  expect_error({{"<Objects>",
                 "<Transformations><Scaling id=\"1\">0 1 1</Scaling>"
                 "</Transformations><Objects>"}},
               {"Scaling id=1", "'0 1 1'", "singular"});
  expect_error({{"<Objects>",
                 "<Transformations><Rotation id=\"1\">45 0 0 0</Rotation>"
                 "</Transformations><Objects>"}},
               {"Rotation id=1", "'45 0 0 0'", "axis"});
  expect_error(
      {{"<Objects>",
        "<Transformations><Composite id=\"1\">0 0 0 0  0 1 0 0  0 0 1 0  "
        "0 0 0 1</Composite></Transformations><Objects>"},
       {"<Radius>0.3</Radius>", "<Radius>0.3</Radius><Transformations>c1</Transformations>"}},
      {"Sphere id=1 > Transformations", "'c1'", "singular"});
  expect_error({{"<Objects>",
                 "<Transformations><Composite id=\"1\">1 0 0 0  0 1 0 0  0 0 1 0  "
                 "0 0 1 0</Composite></Transformations><Objects>"}},
               {"Composite id=1", "'0 0 1 0'"});
}

TEST_F(LoaderErrors, BaseMeshIdThatDoesNotExist) {
  expect_error({{"</Objects>", "<MeshInstance id=\"2\" baseMeshId=\"5\"/></Objects>"}},
               {"MeshInstance id=2", "'5'"});
  // A Triangle or Sphere id is no mesh.
  expect_error({{"</Objects>", "<MeshInstance id=\"2\" baseMeshId=\"\"/></Objects>"}},
               {"MeshInstance id=2", "''"});
  expect_error({{"</Objects>", "<MeshInstance id=\"2\"/></Objects>"}},
               {"MeshInstance id=2", "baseMeshId"});
  expect_error({{"</Objects>",
                 "<MeshInstance id=\"2\" baseMeshId=\"1\" resetTransform=\"yes\"/>"
                 "</Objects>"}},
               {"MeshInstance id=2", "resetTransform", "'yes'"});
}

TEST_F(LoaderErrors, NegativeRadius) {
  expect_error({{"<Radius>0.3</Radius>", "<Radius>-0.3</Radius>"}},
               {"Sphere id=1 > Radius", "'-0.3'"});
  expect_error({{"<Radius>0.3</Radius>", "<Radius>0</Radius>"}}, {"Sphere id=1 > Radius", "'0'"});
}

TEST_F(LoaderErrors, MaxRecursionDepth) {
  expect_error({{"<Cameras>", "<MaxRecursionDepth>-1</MaxRecursionDepth><Cameras>"}},
               {"MaxRecursionDepth", "'-1'"});
  expect_error({{"<Cameras>", "<MaxRecursionDepth>2.5</MaxRecursionDepth><Cameras>"}},
               {"MaxRecursionDepth", "'2.5'"});
  expect_error({{"<Cameras>", "<MaxRecursionDepth>six</MaxRecursionDepth><Cameras>"}},
               {"MaxRecursionDepth", "'six'"});
}

// ---- PLY files ----

const char* kPlyHeader =
    "ply\nformat ascii 1.0\nelement vertex 4\nproperty float x\n"
    "property float y\nproperty float z\nelement face 1\n"
    "property list uchar int vertex_indices\nend_header\n";

std::string ply_mesh(const std::string& file) {
  return "<Mesh id=\"1\">\n            <Material>1</Material>\n            <Faces plyFile=\"" +
         file + "\"/>\n        </Mesh>";
}

const char* kMeshBlock = R"(<Mesh id="1">
            <Material>1</Material>
            <Faces>
                3 1 2
                1 3 4
            </Faces>
        </Mesh>)";

TEST_F(LoaderErrors, MissingPlyFileRelativeToXml) {
  std::string path = write("sub/scene.xml", edit(kBase, {{kMeshBlock, ply_mesh("meshes/m.ply")}}));
  std::string resolved = (dir_ / "sub" / "meshes" / "m.ply").string();
  expect_error(path, {"Mesh id=1 > Faces", "'meshes/m.ply'", resolved});
  // Next to the XML, not next to the working directory, is where it is looked for.
  write("sub/meshes/m.ply", std::string(kPlyHeader) + "0 0 -2\n1 0 -2\n1 1 -2\n0 1 -2\n3 0 1 2\n");
  EXPECT_EQ(load_scene(path).meshes.at(0).triangles.size(), 1u);
}

TEST_F(LoaderErrors, TruncatedPly) {
  write("m.ply", std::string(kPlyHeader) + "0 0 -2\n1 0 -2\n");
  std::string path = write("scene.xml", edit(kBase, {{kMeshBlock, ply_mesh("m.ply")}}));
  expect_error(path, {"Mesh id=1 > Faces", (dir_ / "m.ply").string(), "vertex"});
  // A binary body cut short.
  std::string bin =
      replace_all(kPlyHeader, "ascii", "binary_little_endian") + std::string(20, '\0');
  write("b.ply", bin);
  path = write("scene2.xml", edit(kBase, {{kMeshBlock, ply_mesh("b.ply")}}));
  expect_error(path, {"Mesh id=1 > Faces", (dir_ / "b.ply").string()});
}

TEST_F(LoaderErrors, PlyIndexOutOfRange) {
  write("m.ply", std::string(kPlyHeader) + "0 0 -2\n1 0 -2\n1 1 -2\n0 1 -2\n3 0 1 4\n");
  std::string path = write("scene.xml", edit(kBase, {{kMeshBlock, ply_mesh("m.ply")}}));
  expect_error(path, {"Mesh id=1 > Faces", "m.ply", "index 4", "out of range"});
}

TEST_F(LoaderErrors, PlyHugeFaceCountFailsFast) {
  std::string h = replace_all(kPlyHeader, "element face 1", "element face 2000000000");
  write("m.ply", h + "0 0 -2\n1 0 -2\n1 1 -2\n0 1 -2\n3 0 1 2\n");
  std::string path = write("scene.xml", edit(kBase, {{kMeshBlock, ply_mesh("m.ply")}}));
  expect_error(path, {"Mesh id=1 > Faces", "2000000000"});
}

// ---- Accepted input ----

TEST_F(LoaderAccepts, TemplateLoads) {
  SceneDesc s = load_scene(scene({}));
  ASSERT_EQ(s.cameras.size(), 1u);
  EXPECT_EQ(s.cameras[0].width, 40);
  EXPECT_EQ(s.objects.size(), 3u);
  EXPECT_TRUE(s.warnings.empty());
  EXPECT_EQ(s.degenerate_triangles, 0);
}

TEST_F(LoaderAccepts, UnknownElementWarnsAndLoads) {
  std::string path = scene({{"<Cameras>", "<Fog density=\"1\">0.5</Fog>\n    <Cameras>"},
                            {"</Objects>", "<Cone id=\"4\"/></Objects>"}});
  SceneDesc s = load_scene(path);
  EXPECT_EQ(s.cameras.size(), 1u);
  EXPECT_EQ(s.objects.size(), 3u);
  ASSERT_EQ(s.warnings.size(), 2u);
  EXPECT_NE(s.warnings[0].find(path), std::string::npos) << s.warnings[0];
  EXPECT_NE(s.warnings[0].find("Fog"), std::string::npos) << s.warnings[0];
  EXPECT_NE(s.warnings[1].find("Cone id=4"), std::string::npos) << s.warnings[1];
}

TEST_F(LoaderAccepts, DegenerateTrianglesSkippedAndCounted) {
  // 1 1 2 repeats a vertex; 1 2 and (-0.5, -1.5, -2) are collinear with 1 and 2.
  SceneDesc s = load_scene(
      scene({{"-0.875 1 -2", "-0.5 -1.5 -2"}, {"1 3 4", "1 3 4\n 1 1 2\n 1 2 8\n 2 2 2"}}));
  EXPECT_EQ(s.degenerate_triangles, 3);
  ASSERT_EQ(s.meshes.size(), 2u);
  EXPECT_EQ(s.meshes[0].triangles.size(), 2u);
  ASSERT_EQ(s.warnings.size(), 1u);
  EXPECT_NE(s.warnings[0].find("3 degenerate"), std::string::npos) << s.warnings[0];
}

TEST_F(LoaderAccepts, CrlfLineEndings) {
  std::string path =
      write("scene.xml",
            replace_all(edit(kBase, {{"<ImageName>simple.png", "<ImageName>\nsimple.png\n"}}), "\n",
                        "\r\n"));
  SceneDesc s = load_scene(path);
  ASSERT_EQ(s.cameras.size(), 1u);
  EXPECT_EQ(s.cameras[0].image_name, "simple.png");
  EXPECT_EQ(s.objects.size(), 3u);
  EXPECT_EQ(s.meshes.at(0).triangles.size(), 2u);
}

TEST_F(LoaderAccepts, OneLineXml) {
  SceneDesc s = load_scene(write("scene.xml", replace_all(kBase, "\n", " ")));
  EXPECT_EQ(s.cameras.size(), 1u);
  EXPECT_EQ(s.objects.size(), 3u);
  EXPECT_DOUBLE_EQ(s.cameras[0].top, 0.5);
}

TEST_F(LoaderAccepts, PaddedImageNameTrimmed) {
  SceneDesc s = load_scene(scene({{"<ImageName>simple.png", "<ImageName>  x.png  "}}));
  EXPECT_EQ(s.cameras.at(0).image_name, "x.png");
}

TEST_F(LoaderAccepts, FiveNumberNearPlane) {
  SceneDesc s = load_scene(scene({{"-1 1 -0.5 0.5</NearPlane>", "-1 1 -0.5 0.5 1</NearPlane>"}}));
  const CameraDesc& c = s.cameras.at(0);
  EXPECT_EQ(c.left, -1);
  EXPECT_EQ(c.right, 1);
  EXPECT_EQ(c.bottom, -0.5);
  EXPECT_EQ(c.top, 0.5);
}

TEST_F(LoaderAccepts, Comments) {
  SceneDesc s =
      load_scene(scene({{"<Scene>", "<!-- top --><Scene><!-- inside -->"},
                        {"<Gaze>0 0 -1</Gaze>", "<Gaze><!-- ahead -->0 0 <!-- z -->-1</Gaze>"},
                        {"<Radius>0.3</Radius>", "<Radius>0.3</Radius> <!-- r -->"}}));
  EXPECT_EQ(s.cameras.at(0).gaze.z, -1);
  EXPECT_EQ(s.objects.size(), 3u);
}

TEST_F(LoaderAccepts, MaterialIdWithWhitespace) {
  SceneDesc s = load_scene(scene(
      {{"<Center>8</Center>", "<Center> 8\n</Center>"},
       {"<Material>1</Material>\n            <Center>", "<Material>\n   1 </Material><Center>"}}));
  EXPECT_EQ(s.objects.at(2).material, 0);
}

TEST_F(LoaderAccepts, LookAtCamera) {
  SceneDesc s =
      load_scene(scene({{"<Camera id=\"1\">", "<Camera id=\"1\" type=\"lookAt\">"},
                        {"<Gaze>0 0 -1</Gaze>", "<GazePoint>0 0 -5</GazePoint>"},
                        {"<NearPlane>-1 1 -0.5 0.5</NearPlane>", "<FovY>60</FovY>"},
                        {"<NearDistance>1</NearDistance>", "<NearDistance>2</NearDistance>"}}));
  const CameraDesc& c = s.cameras.at(0);
  double top = 2 * std::tan(30 * M_PI / 180);
  EXPECT_NEAR(c.top, top, 1e-12);
  EXPECT_NEAR(c.bottom, -top, 1e-12);
  EXPECT_NEAR(c.right, top * 40 / 20, 1e-12);
  EXPECT_NEAR(c.left, -top * 2, 1e-12);
  EXPECT_EQ(c.gaze.z, -5);
}

TEST_F(LoaderAccepts, CameraOutsideCameras) {
  // Files of 2017 have no <Cameras> wrapper.
  std::string xml = edit(kBase, {{"    <Cameras>\n", ""}, {"    </Cameras>\n", ""}});
  SceneDesc s = load_scene(write("scene.xml", xml));
  ASSERT_EQ(s.cameras.size(), 1u);
  EXPECT_EQ(s.cameras[0].image_name, "simple.png");
  EXPECT_TRUE(s.warnings.empty()) << s.warnings[0];
  expect_error(write("bad.xml", edit(xml, {{"<Up>0 1 0</Up>", "<Up>0 0 0</Up>"}})),
               {": Camera id=1 > Up: '0 0 0'"});
}

TEST_F(LoaderAccepts, MotionBlur) {
  SceneDesc s = load_scene(
      scene({{"<Radius>0.3</Radius>", "<Radius>0.3</Radius><MotionBlur>0 0.5 -1</MotionBlur>"}}));
  EXPECT_EQ(s.objects.at(2).motion.y, 0.5);
  EXPECT_EQ(s.objects.at(2).motion.z, -1);
  EXPECT_EQ(s.objects.at(0).motion.z, 0);
}

TEST_F(LoaderAccepts, VertexOffsetOnFaces) {
  SceneDesc s = load_scene(scene({{"<Faces>", "<Faces vertexOffset=\"4\">"}, {"1 3 4", "2 1 3"}}));
  const MeshDesc& m = s.meshes.at(0);
  ASSERT_EQ(m.triangles.size(), 2u);
  // "3 1 2" + 4 -> vertices 7, 5, 6.
  Vec3d p = m.positions.at(m.triangles[0][0]);
  EXPECT_EQ(p.x, 0.875);
  EXPECT_EQ(p.y, 1);
}

TEST_F(LoaderAccepts, PlyQuadsTriangulated) {
  std::string h = replace_all(kPlyHeader, "element face 1", "element face 2");
  write("m.ply", h + "0 0 -2\n1 0 -2\n1 1 -2\n0 1 -2\n4 0 1 2 3\n3 0 2 3\n");
  SceneDesc s = load_scene(write("scene.xml", edit(kBase, {{kMeshBlock, ply_mesh("m.ply")}})));
  EXPECT_EQ(s.meshes.at(0).triangles.size(), 3u);
  EXPECT_EQ(s.meshes.at(0).positions.size(), 4u);
}

TEST_F(LoaderAccepts, OlderMaterialDialect) {
  const char* mats = R"(<Material id="2"><DiffuseReflectance>1 1 1</DiffuseReflectance></Material>
        <Material id="3"><MirrorReflectance>1 1 1</MirrorReflectance></Material>
        <Material id="4"><Transparency>0.5 0.5 0.5</Transparency><RefractionIndex>1.5</RefractionIndex></Material>
    </Materials>)";
  SceneDesc old = load_scene(scene({{"</Materials>", mats}}));
  ASSERT_EQ(old.materials.size(), 4u);
  EXPECT_EQ(old.materials[0].type, RT_MATERIAL_PLAIN);
  EXPECT_EQ(old.materials[1].type, RT_MATERIAL_PLAIN);
  EXPECT_EQ(old.materials[2].type, RT_MATERIAL_MIRROR);
  EXPECT_EQ(old.materials[3].type, RT_MATERIAL_DIELECTRIC);
  // Without <Transparency> anywhere the file is of the newer kind: no type, no mirror.
  SceneDesc newer = load_scene(write(
      "newer.xml",
      edit(kBase,
           {{"</Materials>", replace_all(mats, "<Transparency>0.5 0.5 0.5</Transparency>", "")}})));
  EXPECT_EQ(newer.materials.at(2).type, RT_MATERIAL_PLAIN);
  EXPECT_EQ(newer.materials.at(3).type, RT_MATERIAL_PLAIN);
}

TEST_F(LoaderAccepts, EdgeVectorAreaLight) {
  SceneDesc s = load_scene(scene({{"</Lights>", R"(<AreaLight id="1">
            <Position>1 2 3</Position>
            <EdgeVector1>2 0 0</EdgeVector1>
            <EdgeVector2>0 0 3</EdgeVector2>
            <Intensity>5 6 7</Intensity>
        </AreaLight></Lights>)"}}));
  ASSERT_EQ(s.area_lights.size(), 1u);
  const AreaLight& a = s.area_lights[0];
  EXPECT_FLOAT_EQ(a.area, 6);
  EXPECT_FLOAT_EQ(a.corner.x, 1);
  EXPECT_FLOAT_EQ(a.corner.z, 3);
  EXPECT_FLOAT_EQ(a.edge2.z, 3);
  EXPECT_FLOAT_EQ(std::fabs(a.normal.y), 1);
  EXPECT_FLOAT_EQ(a.radiance.y, 6);
}

TEST_F(LoaderAccepts, SquareAreaLight) {
  SceneDesc s = load_scene(scene({{"</Lights>", kAreaLight}}));
  ASSERT_EQ(s.area_lights.size(), 1u);
  const AreaLight& a = s.area_lights[0];
  EXPECT_FLOAT_EQ(a.area, 4);
  // Centred on Position: corner + (edge1 + edge2) / 2 == Position.
  EXPECT_NEAR(a.corner.y + (a.edge1.y + a.edge2.y) / 2, 1, 1e-6);
  EXPECT_NEAR(a.corner.z + (a.edge1.z + a.edge2.z) / 2, -2, 1e-6);
}

// ---- Transformations ----

const char* kTransforms = R"(<Transformations>
        <Translation id="1">1 0 0</Translation>
        <Translation id="2">0 2 0</Translation>
        <Scaling id="1">2 2 2</Scaling>
        <Rotation id="1">90 0 0 1</Rotation>
        <Composite id="1">1 0 0 5  0 1 0 6  0 0 1 7  0 0 0 1</Composite>
    </Transformations>
    <Objects>)";

void expect_point(const Mat4& m, Vec3d p, Vec3d want) {
  Vec3d q = m.point(p);
  EXPECT_NEAR(q.x, want.x, 1e-12);
  EXPECT_NEAR(q.y, want.y, 1e-12);
  EXPECT_NEAR(q.z, want.z, 1e-12);
}

TEST_F(LoaderTransforms, CompositeMatrixIsRowMajor) {
  SceneDesc s = load_scene(
      scene({{"<Objects>", kTransforms},
             {"<Radius>0.3</Radius>", "<Radius>1</Radius><Transformations>c1</Transformations>"},
             {"<Center>8</Center>", "<Center>1</Center>"}}));
  // Centre vertex 1 is (-0.5, 0.5, -2).
  expect_point(s.objects.at(2).transform, {0, 0, 0}, {4.5, 6.5, 5});
}

TEST_F(LoaderTransforms, ListedOrderIsApplicationOrder) {
  // "t1 r1": translate by +x, then rotate 90 degrees about z: the origin ends at (0, 1, 0).
  std::string path = scene(
      {{"<Objects>", kTransforms},
       {"-0.875 1 -2", "0 0 0"},
       {"<Radius>0.3</Radius>", "<Radius>0.5</Radius><Transformations>t1 r1</Transformations>"}});
  SceneDesc s = load_scene(path);
  expect_point(s.objects.at(2).transform, {0, 0, 0}, {0, 1, 0});
  expect_point(s.objects.at(2).transform, {1, 0, 0}, {0, 1.5, 0});  // radius 0.5 scales first
  s = load_scene(write(
      "r.xml", edit(kBase, {{"<Objects>", kTransforms},
                            {"-0.875 1 -2", "0 0 0"},
                            {"<Radius>0.3</Radius>",
                             "<Radius>0.5</Radius><Transformations>r1 t1</Transformations>"}})));
  expect_point(s.objects.at(2).transform, {0, 0, 0}, {1, 0, 0});
}

TEST_F(LoaderTransforms, MeshInstanceChain) {
  std::string path =
      scene({{"<Objects>", kTransforms},
             {"<Material>1</Material>\n            <Faces>",
              "<Material>1</Material><Transformations>t1</Transformations><Faces>"},
             {"</Objects>", R"(<MeshInstance id="2" baseMeshId="1" resetTransform="false">
            <Transformations>t2</Transformations></MeshInstance>
        <MeshInstance id="3" baseMeshId="2"><Transformations>r1</Transformations></MeshInstance>
        <MeshInstance id="4" baseMeshId="3" resetTransform="true">
            <Transformations>s1</Transformations></MeshInstance>
        <MeshInstance id="5" baseMeshId="4" resetTransform="false"></MeshInstance>
    </Objects>)"}});
  SceneDesc s = load_scene(path);
  ASSERT_EQ(s.objects.size(), 7u);
  for (size_t i = 3; i < 7; ++i) EXPECT_EQ(s.objects[i].mesh, s.objects[0].mesh) << i;
  expect_point(s.objects[0].transform, {0, 0, 0}, {1, 0, 0});  // t1
  expect_point(s.objects[3].transform, {0, 0, 0}, {1, 2, 0});  // t2 after t1
  expect_point(s.objects[4].transform, {0, 0, 0},
               {-2, 1, 0});                                    // r1 after t2 t1 (default: no reset)
  expect_point(s.objects[5].transform, {1, 0, 0}, {2, 0, 0});  // reset: s1 alone
  expect_point(s.objects[6].transform, {1, 0, 0}, {2, 0, 0});  // identity after s1
}

TEST_F(LoaderTransforms, InstanceIdsReusingMeshIds) {
  // Older files number instances from 1 as well; baseMeshId="1" still means Mesh 1.
  std::string path =
      scene({{"<Objects>", kTransforms},
             {"<Material>1</Material>\n            <Faces>",
              "<Material>1</Material><Transformations>t1</Transformations><Faces>"},
             {"</Objects>", R"(<Mesh id="2"><Material>1</Material><Faces>5 6 7</Faces></Mesh>
        <MeshInstance id="1" baseMeshId="2"><Transformations>t2</Transformations></MeshInstance>
        <MeshInstance id="2" baseMeshId="1"></MeshInstance>
    </Objects>)"}});
  SceneDesc s = load_scene(path);
  ASSERT_EQ(s.objects.size(), 6u);
  EXPECT_EQ(s.objects[4].mesh, s.objects[3].mesh);
  EXPECT_EQ(s.objects[5].mesh, s.objects[0].mesh);
  expect_point(s.objects[5].transform, {0, 0, 0}, {1, 0, 0});
  EXPECT_EQ(s.objects[4].material, 0);
}

}  // namespace
}  // namespace rt
