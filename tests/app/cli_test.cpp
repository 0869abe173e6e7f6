// Runs the built raytracer on bad input and checks what a user sees: one error line on
// stderr, the documented exit status (1 for bad input, 2 for bad usage), no PNG or
// temporary file left behind, and no hang.
#include <gtest/gtest.h>
#include <sys/wait.h>
#include <unistd.h>

#include <chrono>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <iterator>
#include <string>
#include <vector>

#include "io/png_io.h"
#include "support/cli_harness.h"

namespace {

namespace fs = std::filesystem;

using namespace rt::test;
const char* const kScene = kTinyScene;

class CliBadInput : public CliFixture {};

TEST_F(CliBadInput, MalformedSceneOneLineNoPng) {
  std::string scene = write("bad.xml", replaced(kScene, "</ImageName>", ""));
  Outcome r = render(scene);
  EXPECT_EQ(r.code, 1);
  expect_one_error_line(r);
  EXPECT_NE(r.err.find(scene), std::string::npos) << r.err;
  EXPECT_NE(r.err.find("malformed"), std::string::npos) << r.err;
  EXPECT_TRUE(output_files().empty());
  EXPECT_TRUE(r.out.empty()) << r.out;
}

TEST_F(CliBadInput, BadValueOneLineNamesElementAndValue) {
  std::string scene = write("bad.xml", replaced(kScene, "<Gaze>0 0 -1", "<Gaze>0 0 0"));
  Outcome r = render(scene);
  EXPECT_EQ(r.code, 1);
  expect_one_error_line(r);
  EXPECT_NE(r.err.find(scene + ": Cameras > Camera id=1 > Gaze: '0 0 0'"), std::string::npos)
      << r.err;
  EXPECT_TRUE(output_files().empty());
}

TEST_F(CliBadInput, MissingSceneFile) {
  std::string scene = (dir_ / "absent.xml").string();
  Outcome r = render(scene);
  EXPECT_EQ(r.code, 1);
  expect_one_error_line(r);
  EXPECT_NE(r.err.find(scene), std::string::npos) << r.err;
  EXPECT_TRUE(output_files().empty());
}

TEST_F(CliBadInput, MissingOutputDirectory) {
  std::string scene = write("s.xml", kScene);
  std::string missing = (dir_ / "no_such_dir").string();
  Outcome r = run(quote(scene) + " --device cpu --quiet --output-dir " + quote(missing));
  EXPECT_EQ(r.code, 1);
  expect_one_error_line(r);
  EXPECT_NE(r.err.find(missing), std::string::npos) << r.err;
  EXPECT_FALSE(fs::exists(missing));
}

TEST_F(CliBadInput, UnwritableOutputLeavesNoTempFile) {
  std::string scene = write("s.xml", kScene);
  fs::create_directory(dir_ / "out" / "simple.png");  // rename() onto a directory fails
  Outcome r = render(scene);
  EXPECT_EQ(r.code, 1);
  expect_one_error_line(r);
  EXPECT_NE(r.err.find("simple.png"), std::string::npos) << r.err;
  EXPECT_EQ(output_files(), std::vector<std::string>{"simple.png"});
  EXPECT_TRUE(fs::is_directory(dir_ / "out" / "simple.png"));
  EXPECT_TRUE(fs::is_empty(dir_ / "out" / "simple.png"));
}

TEST_F(CliBadInput, ImageNameInMissingSubdirectory) {
  std::string scene =
      write("s.xml", replaced(kScene, "<ImageName>simple.png", "<ImageName>sub/x.png"));
  Outcome r = render(scene);
  EXPECT_EQ(r.code, 1);
  expect_one_error_line(r);
  EXPECT_NE(r.err.find("x.png"), std::string::npos) << r.err;
  EXPECT_TRUE(output_files().empty());
}

TEST_F(CliBadInput, UnknownOptionIsUsageError) {
  std::string scene = write("s.xml", kScene);
  Outcome r = render(scene, "--frobnicate");
  EXPECT_EQ(r.code, 2);
  EXPECT_NE(r.err.find("--frobnicate"), std::string::npos) << r.err;
  EXPECT_TRUE(r.out.empty()) << r.out;
  EXPECT_TRUE(output_files().empty());
}

TEST_F(CliBadInput, NonNumericSppIsUsageError) {
  std::string scene = write("s.xml", kScene);
  Outcome r = render(scene, "--spp abc");
  EXPECT_EQ(r.code, 2);
  EXPECT_NE(r.err.find("--spp"), std::string::npos) << r.err;
  EXPECT_NE(r.err.find("'abc'"), std::string::npos) << r.err;
  EXPECT_TRUE(output_files().empty());
  EXPECT_EQ(render(scene, "--spp").code, 2);  // missing value
  EXPECT_EQ(render(scene, "--spp 0").code, 2);
}

TEST_F(CliBadInput, MissingOpenClDevice) {
  std::string scene = write("s.xml", kScene);
  Outcome r =
      run(quote(scene) + " --device cl --cl-device no-such-device-xyzzy --quiet --output-dir " +
          quote(out_));
  EXPECT_EQ(r.code, 1);
  expect_one_error_line(r);
  EXPECT_NE(r.err.find("OpenCL"), std::string::npos) << r.err;
  EXPECT_TRUE(output_files().empty());
  // No platform at all: the Khronos ICD loader finds no vendors here. (Another loader may
  // ignore the variable and render; then there is nothing to check.)
  r = run(quote(scene) + " --device cl --quiet --output-dir " + quote(out_),
          "env OCL_ICD_VENDORS=" + quote((dir_ / "no_vendors").string()) + " OCL_ICD_FILENAMES=");
  if (r.code != 0) {
    EXPECT_EQ(r.code, 1);
    expect_one_error_line(r);
    EXPECT_NE(r.err.find("OpenCL"), std::string::npos) << r.err;
    EXPECT_TRUE(output_files().empty());
  }
}

// The PNG must be 8-bit RGB: IHDR bytes 24 and 25 hold the bit depth and colour type.
TEST_F(CliBadInput, GoodSceneRendersPng) {
  std::string scene = write("s.xml", kScene);
  Outcome r = render(scene);
  ASSERT_EQ(r.code, 0) << r.err;
  fs::path png = dir_ / "out" / "simple.png";
  ASSERT_TRUE(fs::is_regular_file(png));
  EXPECT_EQ(output_files(), std::vector<std::string>{"simple.png"});
  std::string bytes = slurp(png);
  ASSERT_GT(bytes.size(), 33u);
  EXPECT_EQ(bytes.substr(12, 4), "IHDR");
  EXPECT_EQ(static_cast<int>(bytes[24]), 8);  // bit depth
  EXPECT_EQ(static_cast<int>(bytes[25]), 2);  // colour type 2: RGB, no alpha
  rt::Image8 img = rt::read_png(png.string());
  EXPECT_EQ(img.width, 16);
  EXPECT_EQ(img.height, 8);
  // The lit quad covers the centre; the corners see the black background.
  auto at = [&](int x, int y) { return img.rgb[(y * img.width + x) * 3]; };
  EXPECT_GT(at(7, 4), 0);
  EXPECT_EQ(at(0, 0), 0);
}

TEST_F(CliBadInput, QuietSuccessIsSilent) {
  std::string scene = write("s.xml", kScene);
  Outcome r = render(scene);
  EXPECT_EQ(r.code, 0);
  EXPECT_EQ(r.out, "");
  EXPECT_EQ(r.err, "");
  // Without --quiet, stderr is not a terminal here, so there is no progress line either.
  r = run(quote(scene) + " --device cpu --output-dir " + quote(out_));
  EXPECT_EQ(r.code, 0);
  EXPECT_EQ(r.out, "");
  EXPECT_EQ(r.err, "");
}

TEST_F(CliBadInput, HelpAndVersion) {
  Outcome r = run("--help");
  EXPECT_EQ(r.code, 0);
  EXPECT_NE(r.out.find("--device"), std::string::npos) << r.out;
  EXPECT_EQ(r.err, "");
  r = run("--version");
  EXPECT_EQ(r.code, 0);
  EXPECT_EQ(r.out.rfind("raytracer ", 0), 0u) << r.out;
  ASSERT_GT(r.out.size(), 10u);
  EXPECT_TRUE(std::isdigit(static_cast<unsigned char>(r.out[10]))) << r.out;
  EXPECT_EQ(r.err, "");
  EXPECT_EQ(run("").code, 2);  // no scene file
}

TEST_F(CliBadInput, HugePlyFaceCountDoesNotHang) {
  write("m.ply",
        "ply\nformat binary_little_endian 1.0\nelement vertex 3\nproperty float x\n"
        "property float y\nproperty float z\nelement face 2147483647\n"
        "property list uchar int vertex_indices\nend_header\n" +
            std::string(3 * 12, '\0') + std::string("\x03\0\0\0\0\1\0\0\0\2\0\0\0", 13));
  std::string scene = write("s.xml", tiny_scene_with_ply_mesh("m.ply"));
  Outcome r = render(scene);
  EXPECT_EQ(r.code, 1);  // 124 would mean `timeout` had to kill it
  EXPECT_LT(r.seconds, 5);
  expect_one_error_line(r);
  EXPECT_NE(r.err.find("m.ply"), std::string::npos) << r.err;
  EXPECT_NE(r.err.find("2147483647"), std::string::npos) << r.err;
  EXPECT_TRUE(output_files().empty());
}

}  // namespace
