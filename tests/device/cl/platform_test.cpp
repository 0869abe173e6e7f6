// Finding the OpenCL device (src/device/cl/cl_platform.cpp): the device's name, selectors
// that match nothing, and the raytracer binary on a machine without any OpenCL platform,
// where `--device cl` fails in one line and `--device auto` falls back to the CPU reference.
#include <gtest/gtest.h>
#include <stdlib.h>
#include <sys/wait.h>

#include <algorithm>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <string>

#include "support/cl_harness.h"
#include "support/test_scene.h"

namespace fs = std::filesystem;

namespace {

using namespace rt::test;

TEST(OpenCl, DeviceNameIsNotEmpty) {
  REQUIRE_DEVICE(r);
  EXPECT_FALSE(r->name().empty());
}

TEST(OpenCl, BadSelectorsReturnNullWithAReason) {
  std::string why;
  EXPECT_EQ(open_cl("no-such-device-name-xyz", &why), nullptr);
  EXPECT_FALSE(why.empty());
  EXPECT_EQ(why.find('\n'), std::string::npos);
  why.clear();
  EXPECT_EQ(open_cl("999", &why), nullptr);
  EXPECT_FALSE(why.empty());
}

// Runs a shell command; returns its exit status (or -1).
int run(const std::string& cmd) {
  int status = std::system(cmd.c_str());
  if (status == -1 || !WIFEXITED(status)) return -1;
  return WEXITSTATUS(status);
}

TEST(OpenCl, NoPlatformPath) {
  fs::path dir = make_temp_dir("noicd");
  fs::path vendors = dir / "vendors", out = dir / "out";
  fs::create_directories(vendors);
  fs::create_directories(out);
  // The tiny test scene (its image is simple.png): this test needs no course scene.
  std::string scene = (dir / "tiny.xml").string();
  std::ofstream(scene) << rt::test::kTinyScene;
  std::string base = "OCL_ICD_VENDORS='" + vendors.string() + "' '" RT_RAYTRACER_EXE "' '" + scene +
                     "' --output-dir '" + out.string() + "' ";
  fs::path err = dir / "err.txt";

  int rc = run(base + "--device cl >/dev/null 2>'" + err.string() + "'");
  std::string e = slurp(err);
  EXPECT_NE(rc, 0);
  EXPECT_NE(e.find("OpenCL"), std::string::npos) << e;
  EXPECT_EQ(std::count(e.begin(), e.end(), '\n'), 1) << e;
  EXPECT_FALSE(fs::exists(out / "simple.png"));

  rc = run(base + "--device auto >/dev/null 2>'" + err.string() + "'");
  e = slurp(err);
  EXPECT_EQ(rc, 0) << e;
  EXPECT_NE(e.find("CPU reference"), std::string::npos) << e;
  EXPECT_TRUE(fs::exists(out / "simple.png"));

  rc = run("OCL_ICD_VENDORS='" + vendors.string() + "' '" RT_RAYTRACER_EXE "' --list-devices >'" +
           err.string() + "' 2>&1");
  EXPECT_NE(rc, 0);
  EXPECT_NE(slurp(err).find("no OpenCL platform"), std::string::npos) << slurp(err);

  std::error_code ec;
  fs::remove_all(dir, ec);
}

}  // namespace
