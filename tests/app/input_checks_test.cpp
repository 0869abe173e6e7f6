// Checks made before any render, through the executable: outputs that conflict or cannot be
// written, unsupported and unknown elements (and --strict), duplicate definitions, and error
// messages that quote no more of a foreign file than a short printable excerpt.
#include <unistd.h>

#include <algorithm>

#include <filesystem>
#include <fstream>
#include <string>
#include <utility>
#include <vector>

#include "support/cli_harness.h"

namespace {

namespace fs = std::filesystem;
using namespace rt::test;
const char* const kScene = kTinyScene;

// Line number (1-based) of the n-th occurrence (0-based) of `what` in `text`.
int line_of(const std::string& text, const std::string& what, int n = 0) {
  size_t at = text.find(what);
  for (int i = 0; i < n && at != std::string::npos; ++i) at = text.find(what, at + 1);
  EXPECT_NE(at, std::string::npos) << what;
  return 1 + static_cast<int>(std::count(text.begin(), text.begin() + at, '\n'));
}

// The template's camera, again, with another id (and the same ImageName).
std::string second_camera(const std::string& scene, const std::string& image) {
  const size_t b = scene.find("        <Camera id=\"1\">"), e = scene.find("</Camera>") + 10;
  std::string cam = replaced(scene.substr(b, e - b), "id=\"1\"", "id=\"2\"");
  cam = replaced(cam, "simple.png", image);
  return replaced(scene, "    </Cameras>", cam + "    </Cameras>");
}

using CliInputChecks = CliFixture;

TEST_F(CliInputChecks, TwoCamerasWithOneImageNameRefusedBeforeRendering) {
  std::string scene = write("s.xml", second_camera(kScene, "simple.png"));
  Outcome r = render(scene);
  EXPECT_EQ(r.code, 1);
  expect_one_error_line(r);
  EXPECT_NE(r.err.find("Camera id=2 > ImageName: 'simple.png'"), std::string::npos) << r.err;
  EXPECT_NE(r.err.find("camera 0 (Cameras > Camera id=1"), std::string::npos) << r.err;
  EXPECT_TRUE(output_files().empty());
  // Only one of them rendered: no conflict.
  EXPECT_EQ(render(scene, "--camera 1").code, 0);
  EXPECT_EQ(output_files(), std::vector<std::string>{"simple.png"});
}

TEST_F(CliInputChecks, MomentsFilesMayCollideToo) {
  // a.png and a.moments.exr differ, but a.png's moments file is a.moments.exr.
  std::string scene =
      write("s.xml", replaced(second_camera(kScene, "a.moments.exr"), "simple.png", "a.png"));
  EXPECT_EQ(render(scene).code, 0);
  fs::remove_all(dir_ / "out");
  fs::create_directory(dir_ / "out");
  Outcome r = render(scene, "--moments");
  EXPECT_EQ(r.code, 1);
  expect_one_error_line(r);
  EXPECT_NE(r.err.find("a.moments.exr"), std::string::npos) << r.err;
  EXPECT_TRUE(output_files().empty());
}

// The inputs carry an image's extension (the loader reads both by their content), so that
// the ImageName passes the loader's check of writable extensions.
TEST_F(CliInputChecks, OutputThatIsTheSceneFileRefused) {
  const std::string text = replaced(kScene, "simple.png", "s.png");
  const std::string scene = (dir_ / "out" / "s.png").string();
  std::ofstream(scene) << text;
  Outcome r = render(scene);
  EXPECT_EQ(r.code, 1);
  expect_one_error_line(r);
  EXPECT_NE(r.err.find("would overwrite the input file"), std::string::npos) << r.err;
  EXPECT_EQ(slurp(scene), text);
  EXPECT_EQ(output_files(), std::vector<std::string>{"s.png"});
}

TEST_F(CliInputChecks, OutputThatIsThePlyFileRefused) {
  const std::string ply =
      "ply\nformat ascii 1.0\nelement vertex 3\nproperty float x\nproperty float y\n"
      "property float z\nelement face 1\nproperty list uchar int vertex_indices\nend_header\n"
      "0 0 -2\n1 0 -2\n1 1 -2\n3 0 1 2\n";
  std::ofstream(dir_ / "out" / "m.png") << ply;
  std::string scene = write(
      "s.xml",
      replaced(
          replaced(kScene,
                   "<Faces>\n                3 1 2\n                1 3 4\n            </Faces>",
                   "<Faces plyFile=\"out/m.png\"/>"),
          "simple.png", "m.png"));
  Outcome r = render(scene);
  EXPECT_EQ(r.code, 1);
  expect_one_error_line(r);
  EXPECT_NE(r.err.find("m.png"), std::string::npos) << r.err;
  EXPECT_NE(r.err.find("would overwrite the input file"), std::string::npos) << r.err;
  EXPECT_EQ(slurp(dir_ / "out" / "m.png"), ply);
}

TEST_F(CliInputChecks, NameTooLongForTheFileSystemRefusedBeforeRendering) {
  const long name_max = pathconf(out_.c_str(), _PC_NAME_MAX);
  ASSERT_GT(name_max, 0);
  const std::string name(name_max + 1 - 4, 'x');
  // Camera 0 is fine and comes first: checked only at its write, it would be rendered.
  std::string scene = write("s.xml", second_camera(kScene, name + ".png"));
  Outcome r = render(scene);
  EXPECT_EQ(r.code, 1);
  expect_one_error_line(r);
  EXPECT_NE(r.err.find("Camera id=2 > ImageName"), std::string::npos) << r.err;
  EXPECT_NE(r.err.find("allows " + std::to_string(name_max)), std::string::npos) << r.err;
  EXPECT_TRUE(output_files().empty());
}

TEST_F(CliInputChecks, UnsupportedFeaturesAreErrors) {
  const std::pair<const char*, const char*> cases[] = {
      {"</Objects>", "<LightMesh id=\"9\"><MotionBlur>1 0 0</MotionBlur></LightMesh></Objects>"},
      {"<ImageName>", "<Renderer>PhotonMapping</Renderer><ImageName>"},
  };
  const char* names[] = {"MotionBlur", "Renderer"};
  for (int i = 0; i < 2; ++i) {
    std::string scene = write("s.xml", replaced(kScene, cases[i].first, cases[i].second));
    Outcome r = render(scene);
    EXPECT_EQ(r.code, 1) << names[i];
    expect_one_error_line(r);
    EXPECT_NE(r.err.find(scene), std::string::npos) << r.err;
    EXPECT_NE(r.err.find(names[i]), std::string::npos) << r.err;
    EXPECT_NE(r.err.find("not supported"), std::string::npos) << r.err;
    EXPECT_TRUE(output_files().empty()) << names[i];
  }
  // A missing binary vertex file: one line naming it, nothing written.
  std::string missing = write(
      "s.xml",
      replaced(replaced(kScene, "<VertexData>", "<VertexData binaryFile=\"vertices.bin\"/><!--"),
               "</VertexData>", "-->"));
  Outcome m = render(missing);
  EXPECT_EQ(m.code, 1);
  expect_one_error_line(m);
  EXPECT_NE(m.err.find("VertexData: binaryFile '" + (dir_ / "vertices.bin").string() + "'"),
            std::string::npos)
      << m.err;
  EXPECT_TRUE(output_files().empty());
  // An empty <Textures/> (older course files) changes nothing and is accepted silently.
  std::string scene =
      write("s.xml", replaced(kScene, "<Objects>", "<Textures>\n</Textures><Objects>"));
  Outcome r = render(scene);
  EXPECT_EQ(r.code, 0) << r.err;
  EXPECT_EQ(r.err, "");
}

TEST_F(CliInputChecks, UnknownElementsWarnOncePerKindAndStrictRefuses) {
  std::string scene = write(
      "s.xml", replaced(kScene, "<Objects>", "<Fog>1</Fog><Fog>2</Fog><Fog>3</Fog><Objects>"));
  Outcome r = run(quote(scene) + " --device cpu --output-dir " + quote(out_));
  EXPECT_EQ(r.code, 0) << r.err;
  EXPECT_EQ(std::count(r.err.begin(), r.err.end(), '\n'), 1) << r.err;
  EXPECT_NE(r.err.find("warning: " + scene + ": Fog"), std::string::npos) << r.err;
  EXPECT_NE(r.err.find("(3 times)"), std::string::npos) << r.err;
  EXPECT_EQ(output_files(), std::vector<std::string>{"simple.png"});
  fs::remove(dir_ / "out" / "simple.png");
  r = render(scene, "--strict");
  EXPECT_EQ(r.code, 1);
  expect_one_error_line(r);
  EXPECT_NE(r.err.find("Fog"), std::string::npos) << r.err;
  EXPECT_NE(r.err.find("--strict"), std::string::npos) << r.err;
  EXPECT_TRUE(output_files().empty());
}

TEST_F(CliInputChecks, SecondSceneAndStrayTextWarned) {
  std::string scene = write("s.xml", std::string("stray\n") + kScene + "<Scene></Scene>\n");
  Outcome r = run(quote(scene) + " --device cpu --output-dir " + quote(out_));
  EXPECT_EQ(r.code, 0) << r.err;
  EXPECT_NE(r.err.find("text outside <Scene>"), std::string::npos) << r.err;
  EXPECT_NE(r.err.find("a second <Scene>"), std::string::npos) << r.err;
  EXPECT_EQ(render(scene, "--strict").code, 1);
}

TEST_F(CliInputChecks, RepeatedSingleElementIsAnErrorNamingBothLines) {
  const std::string text =
      replaced(kScene, "<ImageResolution>16 8</ImageResolution>",
               "<ImageResolution>16 8</ImageResolution>\n<ImageResolution>32 16</ImageResolution>");
  Outcome r = render(write("s.xml", text));
  EXPECT_EQ(r.code, 1);
  expect_one_error_line(r);
  const std::string lines = "lines " + std::to_string(line_of(text, "<ImageResolution>")) +
                            " and " + std::to_string(line_of(text, "<ImageResolution>", 1));
  EXPECT_NE(r.err.find("Camera id=1 > ImageResolution: repeated at " + lines), std::string::npos)
      << r.err;
  EXPECT_TRUE(output_files().empty());
}

TEST_F(CliInputChecks, RepeatedIdOfAMaterialIsAnErrorOfASphereAWarning) {
  const std::string m =
      "<Material id=\"1\">\n<DiffuseReflectance>0 0 1</DiffuseReflectance>\n</Material>";
  const std::string text = replaced(kScene, "    </Materials>", m + "\n    </Materials>");
  Outcome r = render(write("s.xml", text));
  EXPECT_EQ(r.code, 1);
  expect_one_error_line(r);
  EXPECT_NE(r.err.find("Material id=1: id '1' is defined twice, at lines " +
                       std::to_string(line_of(text, "<Material id=\"1\">")) + " and " +
                       std::to_string(line_of(text, "<Material id=\"1\">", 1))),
            std::string::npos)
      << r.err;
  EXPECT_TRUE(output_files().empty());
  // hw1/two_spheres.xml gives both spheres id 1: both are kept, with a warning.
  std::string spheres = replaced(kScene, "    </Objects>",
                                 "<Sphere id=\"1\"><Material>1</Material><Center>1</Center>"
                                 "<Radius>0.1</Radius></Sphere>\n    </Objects>");
  r = run(quote(write("t.xml", spheres)) + " --device cpu --output-dir " + quote(out_));
  EXPECT_EQ(r.code, 0) << r.err;
  EXPECT_NE(r.err.find("id '1' is used at lines"), std::string::npos) << r.err;
}

TEST_F(CliInputChecks, ForeignPlyFileIsNotQuoted) {
  write("secret.txt", "root:SECRET-HASH:0:0:root:/root:/bin/bash\nmore\n");
  std::string scene = write("s.xml", tiny_scene_with_ply_mesh("secret.txt"));
  Outcome r = render(scene);
  EXPECT_EQ(r.code, 1);
  expect_one_error_line(r);
  EXPECT_NE(r.err.find("not a PLY file"), std::string::npos) << r.err;
  EXPECT_EQ(r.err.find("SECRET"), std::string::npos) << r.err;
  EXPECT_EQ(r.err.find("root:"), std::string::npos) << r.err;
}

}  // namespace
