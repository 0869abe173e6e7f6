// The scene file as a document: missing, empty or malformed files, the <Scene> root, numbers
// that are not finite or not floats, wrong counts of numbers, and accepted oddities of form
// (unknown elements, CRLF line endings, one-line XML, comments).
#include <gtest/gtest.h>

#include <filesystem>
#include <string>

#include "util/errors.h"
#include "scene/scene.h"
#include "support/loader_fixture.h"

namespace rt {
namespace {

using namespace test;
namespace fs = std::filesystem;

TEST_F(LoaderErrors, MalformedXmlNamesTheLine) {
  std::string xml =
      edited(kTinyScene, {{"<ImageName>simple.png</ImageName>", "<ImageName>simple.png"}});
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
  std::string xml = kTinyScene;
  size_t b = xml.find("    <Cameras>"), e = xml.find("</Cameras>\n") + 11;
  xml.erase(b, e - b);
  ASSERT_EQ(xml.find("Camera"), std::string::npos);
  expect_error(write("scene.xml", xml), {"no <Camera>"});
  // An empty <Cameras> is no better.
  expect_error(write("scene2.xml", edited(xml, {{"<Lights>", "<Cameras></Cameras><Lights>"}})),
               {"no <Camera>"});
}

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

TEST_F(LoaderErrors, MaxRecursionDepth) {
  expect_error({{"<Cameras>", "<MaxRecursionDepth>-1</MaxRecursionDepth><Cameras>"}},
               {"MaxRecursionDepth", "'-1'"});
  expect_error({{"<Cameras>", "<MaxRecursionDepth>2.5</MaxRecursionDepth><Cameras>"}},
               {"MaxRecursionDepth", "'2.5'"});
  expect_error({{"<Cameras>", "<MaxRecursionDepth>six</MaxRecursionDepth><Cameras>"}},
               {"MaxRecursionDepth", "'six'"});
}

TEST_F(LoaderAccepts, TemplateLoads) {
  SceneDesc s = load_scene(scene({}));
  ASSERT_EQ(s.cameras.size(), 1u);
  EXPECT_EQ(s.cameras[0].width, 16);
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

TEST_F(LoaderAccepts, CrlfLineEndings) {
  std::string path = write(
      "scene.xml",
      replaced_all(edited(kTinyScene, {{"<ImageName>simple.png", "<ImageName>\nsimple.png\n"}}),
                   "\n", "\r\n"));
  SceneDesc s = load_scene(path);
  ASSERT_EQ(s.cameras.size(), 1u);
  EXPECT_EQ(s.cameras[0].image_name, "simple.png");
  EXPECT_EQ(s.objects.size(), 3u);
  EXPECT_EQ(s.meshes.at(0).triangles.size(), 2u);
}

TEST_F(LoaderAccepts, OneLineXml) {
  SceneDesc s = load_scene(write("scene.xml", replaced_all(kTinyScene, "\n", " ")));
  EXPECT_EQ(s.cameras.size(), 1u);
  EXPECT_EQ(s.objects.size(), 3u);
  EXPECT_DOUBLE_EQ(s.cameras[0].top, 0.5);
}

TEST_F(LoaderAccepts, Comments) {
  SceneDesc s =
      load_scene(scene({{"<Scene>", "<!-- top --><Scene><!-- inside -->"},
                        {"<Gaze>0 0 -1</Gaze>", "<Gaze><!-- ahead -->0 0 <!-- z -->-1</Gaze>"},
                        {"<Radius>0.3</Radius>", "<Radius>0.3</Radius> <!-- r -->"}}));
  EXPECT_EQ(s.cameras.at(0).gaze.z, -1);
  EXPECT_EQ(s.objects.size(), 3u);
}

}  // namespace
}  // namespace rt
