// Building the kernel (src/device/cl/cl_program.cpp): specialized programs for several
// feature sets and the generic one, which must render the same image, programs kept in
// memory, and the compiled-kernel cache on disk, including a corrupt cache file.
#include <gtest/gtest.h>
#include <stdlib.h>

#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <string>

#include "cl/features.h"
#include "support/cl_harness.h"
#include "support/device_harness.h"

namespace fs = std::filesystem;

namespace {

using namespace rt::test;

// Specialized kernels for several feature sets and the generic one all build, and a bit
// the scene does not need never changes the image.
TEST(OpenCl, KernelBuildsSpecializedAndGeneric) {
  REQUIRE_DEVICE(r);
  SKIP_WITHOUT_SCENE("/hw1/simple.xml");
  Loaded l = load("/hw1/simple.xml", 1, 24);
  rt::DeviceLoadInfo t;
  rt::RenderResult base = render_on_cl(l.flat, false, &t);
  EXPECT_NE(t.build_options.find("-DRT_KERNEL_FEATURES=" + std::to_string(l.flat.header.features)),
            std::string::npos)
      << t.build_options;
  // The kernel reads the arrays at the node width the host built them with.
  EXPECT_NE(t.build_options.find("-DRT_BVH_WIDTH=" + std::to_string(RT_BVH_WIDTH)),
            std::string::npos)
      << t.build_options;
  EXPECT_EQ(t.build_options.find("fast-relaxed"), std::string::npos);
  EXPECT_EQ(t.build_options.find("mad-enable"), std::string::npos);
  std::printf("[ specialized 0x%x ] compile %.0f ms\n", l.flat.header.features, t.compile_ms);

  for (int extra : {RT_FEATURE_MIRROR | RT_FEATURE_DIELECTRIC | RT_FEATURE_MULTISAMPLE,
                    RT_FEATURE_SMOOTH | RT_FEATURE_AREA_LIGHTS | RT_FEATURE_MOTION_BLUR |
                        RT_FEATURE_DEPTH_OF_FIELD | RT_FEATURE_CONDUCTOR | RT_FEATURE_ROUGHNESS}) {
    rt::FlatScene f = l.flat;
    f.header.features |= extra;
    rt::DeviceLoadInfo te;
    rt::RenderResult res = render_on_cl(f, false, &te);
    std::printf("[ specialized 0x%x ] compile %.0f ms\n", f.header.features, te.compile_ms);
    EXPECT_TRUE(identical(res, base)) << "features 0x" << std::hex << f.header.features;
  }
  rt::DeviceLoadInfo tg;
  rt::RenderResult generic = render_on_cl(l.flat, true, &tg);
  std::printf("[ generic ] compile %.0f ms\n", tg.compile_ms);
  EXPECT_NE(tg.build_options.find("-DRT_KERNEL_FEATURES=" + std::to_string(RT_FEATURE_ALL)),
            std::string::npos)
      << tg.build_options;
  EXPECT_TRUE(identical(generic, base));
  // The second use of a program comes from memory.
  rt::DeviceLoadInfo again;
  render_on_cl(l.flat, true, &again);
  EXPECT_TRUE(again.cache_hit);
}

class ScopedEnv {
 public:
  ScopedEnv(const char* name, const std::string& value) : name_(name) {
    const char* old = std::getenv(name);
    had_ = old != nullptr;
    if (had_) old_ = old;
    setenv(name, value.c_str(), 1);
  }
  ~ScopedEnv() {
    if (had_)
      setenv(name_, old_.c_str(), 1);
    else
      unsetenv(name_);
  }

 private:
  const char* name_;
  bool had_;
  std::string old_;
};

TEST(OpenCl, CompiledKernelCache) {
  REQUIRE_DEVICE(r);
  fs::path dir = make_temp_dir("cache");
  ScopedEnv env("XDG_CACHE_HOME", dir.string());
  SKIP_WITHOUT_SCENE("/hw1/simple.xml");
  Loaded l = load("/hw1/simple.xml", 0, 32);
  std::string why;
  rt::RenderResult first, second;
  {
    auto a = open_cl("", &why);
    ASSERT_NE(a, nullptr) << why;
    rt::DeviceLoadInfo t;
    first = rt::test::render_on(*a, l.flat, {}, &t);
    EXPECT_FALSE(t.cache_hit);
    std::printf("[ cache ] cold compile %.0f ms\n", t.compile_ms);
  }
  size_t files = 0;
  for (auto& e : fs::directory_iterator(dir / "raytracer" / "kernels")) {
    EXPECT_EQ(e.path().extension(), ".bin") << e.path();
    ++files;
  }
  EXPECT_EQ(files, 1u);
  {
    auto b = open_cl("", &why);
    ASSERT_NE(b, nullptr) << why;
    rt::DeviceLoadInfo t;
    second = rt::test::render_on(*b, l.flat, {}, &t);
    EXPECT_TRUE(t.cache_hit);
    std::printf("[ cache ] cached load %.0f ms\n", t.compile_ms);
  }
  EXPECT_TRUE(identical(first, second));
  // A corrupt cache file falls back to a build from source.
  for (auto& e : fs::directory_iterator(dir / "raytracer" / "kernels"))
    std::ofstream(e.path(), std::ios::binary | std::ios::trunc) << "not a binary";
  {
    auto c = open_cl("", &why);
    ASSERT_NE(c, nullptr) << why;
    rt::DeviceLoadInfo t;
    rt::RenderResult third = rt::test::render_on(*c, l.flat, {}, &t);
    EXPECT_FALSE(t.cache_hit);
    EXPECT_TRUE(identical(first, third));
  }
  std::error_code ec;
  fs::remove_all(dir, ec);
}

}  // namespace
