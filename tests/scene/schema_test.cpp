// The structure checks of src/scene/scene_schema.cpp: unsupported features are errors, unknown
// ones warnings (one per kind), repeats and repeated ids errors naming both lines, and
// --strict; and the course's own files, which must keep loading as before.
#include <gtest/gtest.h>
#include <tinyxml2.h>

#include <filesystem>
#include <set>
#include <string>

#include "util/errors.h"
#include "scene/scene.h"
#include "scene/scene_schema.h"
#include "support/test_scene.h"

namespace rt {
namespace {

// A camera, a light, a material, a transformation and a sphere: the smallest scene with
// a definition of each kind the tests repeat.
const std::string kScene = R"(<Scene>
  <Cameras><Camera id="1"><Position>0 0 0</Position><Gaze>0 0 -1</Gaze><Up>0 1 0</Up>
    <NearPlane>-1 1 -1 1</NearPlane><NearDistance>1</NearDistance>
    <ImageResolution>4 4</ImageResolution><ImageName>a.png</ImageName></Camera></Cameras>
  <Lights><PointLight id="1"><Position>0 0 0</Position><Intensity>1 1 1</Intensity></PointLight></Lights>
  <Materials><Material id="1"><DiffuseReflectance>1 1 1</DiffuseReflectance></Material></Materials>
  <Transformations><Translation id="1">0 0 -1</Translation></Transformations>
  <VertexData>0 0 -2</VertexData>
  <Objects><Sphere id="1"><Material>1</Material><Center>1</Center><Radius>0.5</Radius></Sphere></Objects>
</Scene>
)";

std::string with(const std::string& from, const std::string& to) {
  return test::replaced(kScene, from, to);
}

SceneDesc load(const std::string& xml, bool strict = false) {
  LoadOptions options;
  options.strict = strict;
  return load_scene_text(xml, "s.xml", options);
}

// The message of the InputError `xml` must raise (one line, starting with "s.xml: ").
std::string error_of(const std::string& xml, bool strict = false) {
  LoadOptions options;
  options.strict = strict;
  return test::expect_load_text_error(xml, "s.xml", {}, options);
}

TEST(SceneSchema, UnsupportedElementsAndAttributeValuesAreErrors) {
  // Object lights are read, but not moving ones.
  EXPECT_NE(
      error_of(with("</Objects>",
                    "<LightMesh id=\"2\"><MotionBlur>1 0 0</MotionBlur></LightMesh></Objects>"))
          .find("LightMesh id=2 > MotionBlur: not supported"),
      std::string::npos);
  // Both handednesses are read; empty elements change nothing.
  SceneDesc s = load(with("<Camera id=\"1\">", "<Camera id=\"1\" handedness=\"right\">"));
  EXPECT_TRUE(s.warnings.empty());
  s = load(with("<VertexData>", "<Textures/><TexCoordData>\n</TexCoordData><VertexData>"));
  EXPECT_TRUE(s.warnings.empty());
}

TEST(SceneSchema, UnknownKindsWarnOnceWithACount) {
  SceneDesc s = load(with("<Radius>", "<Glow a=\"1\"/><Glow/><Radius b=\"2\">"));
  ASSERT_EQ(s.warnings.size(), 2u);
  EXPECT_NE(s.warnings[0].find("Sphere id=1 > Glow: unknown element (line 9), ignored (2 times)"),
            std::string::npos)
      << s.warnings[0];
  EXPECT_NE(s.warnings[1].find("unknown attribute b=\"2\""), std::string::npos) << s.warnings[1];
  EXPECT_NE(error_of(with("<Radius>", "<Glow/><Radius>"), true).find("--strict"),
            std::string::npos);
  s = load(with("<Objects>", "stray words<Objects>"));
  ASSERT_EQ(s.warnings.size(), 1u);
  EXPECT_NE(s.warnings[0].find("text 'stray words' between elements"), std::string::npos);
}

TEST(SceneSchema, RepeatsAndRepeatedIdsAreErrorsNamingBothLines) {
  EXPECT_NE(error_of(with("<Radius>0.5</Radius>", "<Radius>0.5</Radius>\n<Radius>2</Radius>"))
                .find("Sphere id=1 > Radius: repeated at lines 9 and 10"),
            std::string::npos);
  EXPECT_NE(
      error_of(with("</Lights>", "</Lights>\n<Lights></Lights>")).find("repeated at lines 5 and 6"),
      std::string::npos);
  EXPECT_NE(error_of(with("</Transformations>",
                          "\n<Translation id=\"1\">1 0 0</Translation></Transformations>"))
                .find("Translation id=1: id '1' is defined twice, at lines 7 and 8"),
            std::string::npos);
  // Kinds are separate name spaces: Scaling 1 is not Translation 1.
  EXPECT_TRUE(
      load(with("</Transformations>", "<Scaling id=\"1\">1 1 1</Scaling></Transformations>"))
          .warnings.empty());
  // Point lights and spheres may share ids (course scenes do): both kept, with a warning.
  SceneDesc s = load(with("</Lights>",
                          "<PointLight id=\"1\"><Position>1 0 0</Position>"
                          "<Intensity>1 1 1</Intensity></PointLight></Lights>"));
  EXPECT_EQ(s.point_lights.size(), 2u);
  ASSERT_EQ(s.warnings.size(), 1u);
  EXPECT_NE(s.warnings[0].find("id '1' is used at lines 5 and 5; both are kept"), std::string::npos)
      << s.warnings[0];
}

// Every XML file of the course: no repeated element, no repeated id but in the files the
// README names, no unknown element or attribute. (Unsupported features may be refused; the
// hw4 files are, for their textures, before their repeated light ids are reached.)
TEST(SceneSchema, CourseFilesRelyOnlyOnTheDocumentedRepeats) {
  const std::filesystem::path root = RT_SHARED_SCENES_DIR;
  if (!std::filesystem::exists(root)) GTEST_SKIP() << root << " is missing";
  const std::set<std::string> documented = {"hw1/two_spheres.xml", "hw4/sphere_perlin.xml",
                                            "hw4/sphere_perlin_bump.xml",
                                            "hw4/sphere_perlin_scale.xml"};
  std::set<std::string> repeated_ids;
  int files = 0;
  for (const auto& e : std::filesystem::recursive_directory_iterator(root)) {
    if (e.path().extension() != ".xml") continue;
    ++files;
    const std::string name = std::filesystem::relative(e.path(), root).string();
    tinyxml2::XMLDocument doc;
    ASSERT_EQ(doc.LoadFile(e.path().c_str()), tinyxml2::XML_SUCCESS) << name;
    try {
      for (const std::string& w : check_scene_structure(doc, name)) {
        EXPECT_NE(w.find("both are kept"), std::string::npos) << w;
        EXPECT_EQ(documented.count(name), 1u) << w;
        repeated_ids.insert(name);
      }
    } catch (const InputError& err) {
      EXPECT_NE(std::string(err.what()).find("not supported"), std::string::npos) << err.what();
    }
  }
  EXPECT_GT(files, 400);
  EXPECT_EQ(repeated_ids.count("hw1/two_spheres.xml"), 1u);
}

}  // namespace
}  // namespace rt
