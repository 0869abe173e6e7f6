// The hw5 scenes through the executable: cube_point_hdr, whose inputs are complete but
// which has no reference image, renders to its EXR and the tone-mapped PNG beside it; a
// scene whose environment map is missing fails in one line naming the map, writing nothing.
#include <gtest/gtest.h>

#include <algorithm>
#include <filesystem>
#include <string>

#include "image/read_hdr.h"
#include "support/cli_harness.h"

namespace rt::test {
namespace {

const std::string kScenes = RT_SHARED_SCENES_DIR;

using Hw5Scenes = CliFixture;

TEST_F(Hw5Scenes, CubePointHdrWritesExrAndPng) {
  std::string scene = kScenes + "/hw5/cube_point_hdr.xml";
  if (!std::filesystem::exists(scene)) GTEST_SKIP() << scene << " is not here (../shared/scenes)";
  Outcome r = render(scene, "--resolution-scale 0.25");
  ASSERT_EQ(r.code, 0) << r.err;
  std::vector<std::string> files = output_files();
  std::sort(files.begin(), files.end());
  ASSERT_EQ(files, (std::vector<std::string>{"cube_point_hdr.exr", "cube_point_hdr.png"}));
  ImageF exr = read_exr(out_ + "/cube_point_hdr.exr");
  EXPECT_EQ(exr.width, 200);
  float brightest = *std::max_element(exr.pixels.begin(), exr.pixels.end());
  EXPECT_GT(brightest, 255.0f);  // High dynamic range: beyond the PNG's white.
  EXPECT_GT(slurp(std::filesystem::path(out_) / "cube_point_hdr.png").size(), 100u);
}

TEST_F(Hw5Scenes, MissingEnvironmentMapIsOneLine) {
  std::string scene = kScenes + "/hw5/mirror_sphere_env.xml";
  if (!std::filesystem::exists(scene)) GTEST_SKIP() << scene << " is not here (../shared/scenes)";
  if (std::filesystem::exists(kScenes + "/hw5/textures/grace-new.exr"))
    GTEST_SKIP() << "the map is here: nothing is missing";
  Outcome r = render(scene);
  EXPECT_EQ(r.code, 1);
  expect_one_error_line(r);
  EXPECT_NE(r.err.find("SphericalDirectionalLight id=1 > ImageId"), std::string::npos) << r.err;
  EXPECT_NE(r.err.find("textures/grace-new.exr"), std::string::npos) << r.err;
  EXPECT_TRUE(output_files().empty());
}

}  // namespace
}  // namespace rt::test
