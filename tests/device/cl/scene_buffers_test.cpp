// OpenCL host tests: struct layouts on the device, kernel builds, agreement with the CPU
// reference, the compiled-kernel cache and the no-device path of the raytracer binary.
// Tests that need a device are skipped when none is usable.
#define CL_HPP_ENABLE_EXCEPTIONS
#include <gtest/gtest.h>
#include <stdlib.h>
#include <sys/wait.h>
#include <CL/opencl.hpp>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <string>
#include <vector>

#include "bvh/bvh_lanes.h"
#include "cl/features.h"
#include "cl/bvh/simd.h"
#include "device/cl/cl_scene_buffers.h"
#include "device/cl/cl_device.h"
#include "device/cl/cl_program.h"
#include "device/cpu/cpu_device.h"
#include "scene/scene.h"
#include "support/device_harness.h"
#include "support/test_scene.h"

namespace fs = std::filesystem;

namespace {

const std::string kScenes = RT_SHARED_SCENES_DIR;

// One device for the whole binary (building programs is the slow part); no disk cache so
// each run exercises the compiler.
rt::RenderDevice* shared_cl(std::string* why, bool generic = false) {
  return rt::test::shared_device(rt::Device::kOpenCl, why, generic, /*kernel_cache=*/false);
}

#define REQUIRE_DEVICE(r)                 \
  std::string why_;                       \
  rt::RenderDevice* r = shared_cl(&why_); \
  if (!r) GTEST_SKIP() << "no OpenCL device: " << why_

fs::path make_temp_dir(const std::string& tag) {
  std::string templ = (fs::temp_directory_path() / ("rt_cl_test_" + tag + "_XXXXXX")).string();
  std::vector<char> buf(templ.begin(), templ.end());
  buf.push_back('\0');
  if (!mkdtemp(buf.data())) throw std::runtime_error("mkdtemp failed");
  return fs::path(buf.data());
}

struct Loaded {
  rt::SceneDesc scene;
  rt::FlatScene flat;
};

// The course's scenes live beside the clone (../shared); a clone elsewhere skips the tests
// that render them instead of failing on a missing file.
#define SKIP_WITHOUT_SCENE(rel)     \
  if (!fs::exists(kScenes + (rel))) \
  GTEST_SKIP() << kScenes + (rel) << " is not here (the course's scenes, ../shared)"

Loaded load(const std::string& rel, int spp, int size, int bvh_width = 0) {
  Loaded l;
  l.scene = rt::load_scene(kScenes + rel);
  rt::RenderOptions opt;
  opt.spp = spp;
  opt.bvh.width = bvh_width;
  l.flat = rt::flatten_scene(l.scene, opt);
  rt::set_camera(l.flat, l.scene, 0, opt);
  // Fewer pixels over the same film: the pixel coordinates follow width and height.
  l.flat.header.camera.width = size;
  l.flat.header.camera.height = size;
  return l;
}

rt::RenderResult render_on_cpu(const rt::FlatScene& flat) { return rt::test::render_cpu(flat); }

// Renders on the shared device with the specialized or the generic kernel.
rt::RenderResult render_on_cl(const rt::FlatScene& flat, bool generic,
                              rt::DeviceLoadInfo* info = nullptr) {
  std::string why;
  rt::RenderDevice* device = shared_cl(&why, generic);
  if (!device) throw std::runtime_error("no OpenCL device: " + why);
  return rt::test::render_on(*device, flat, {}, info);
}

// A new device with the disk cache on, as the executable opens it.
std::unique_ptr<rt::RenderDevice> open_cl(const std::string& selector, std::string* why) {
  rt::DeviceOptions options;
  options.cl_selector = selector;
  return rt::create_cl_device(options, why);
}

bool same_bits(const float4& a, const float4& b) { return std::memcmp(&a, &b, sizeof a) == 0; }

// Compares two renders: prints the share of bit-identical per-pixel sums and the largest
// difference of the reconstructed colour, and checks it against the tolerance.
void expect_agree(const std::string& label, const rt::RenderResult& cl,
                  const rt::RenderResult& cpu) {
  ASSERT_EQ(cl.width, cpu.width);
  ASSERT_EQ(cl.height, cpu.height);
  ASSERT_EQ(cl.accum.size(), cpu.accum.size());
  size_t identical = 0, same_primary = 0;
  for (size_t i = 0; i < cl.accum.size(); ++i) {
    if (same_bits(cl.accum[i].sum, cpu.accum[i].sum)) ++identical;
    if (cl.primary[i].instance == cpu.primary[i].instance &&
        cl.primary[i].primitive == cpu.primary[i].primitive)
      ++same_primary;
  }
  std::vector<float> a = cl.rgb(), b = cpu.rgb();
  float max_value = 0, max_diff = 0;
  size_t worst = 0;
  for (size_t i = 0; i < a.size(); ++i) {
    ASSERT_TRUE(std::isfinite(a[i])) << label << ": component " << i;
    max_value = std::max({max_value, std::fabs(a[i]), std::fabs(b[i])});
    float d = std::fabs(a[i] - b[i]);
    if (d > max_diff) {
      max_diff = d;
      worst = i / 3;
    }
  }
  double n = static_cast<double>(cl.accum.size());
  std::printf(
      "[ %s ] %dx%d: %.2f%% of pixel sums bit-identical, %.2f%% same primary hit, "
      "max |rgb difference| %.3g (max value %.3g, worst pixel %zu,%zu), rays %llu vs "
      "%llu\n",
      label.c_str(), cl.width, cl.height, 100.0 * identical / n, 100.0 * same_primary / n, max_diff,
      max_value, worst % cl.width, worst / cl.width, static_cast<unsigned long long>(cl.rays),
      static_cast<unsigned long long>(cpu.rays));
  EXPECT_GT(max_value, 0.0f) << label << ": black image";
  EXPECT_LE(max_diff, 1e-3f * max_value) << label;
  EXPECT_GE(identical, cl.accum.size() / 2) << label << ": most pixels should be bit-identical";
}

bool identical(const rt::RenderResult& a, const rt::RenderResult& b) {
  return a.accum.size() == b.accum.size() &&
         std::memcmp(a.accum.data(), b.accum.data(), a.accum.size() * sizeof(PixelAccum)) == 0;
}

TEST(OpenCl, StructLayoutsMatchTheDevice) {
  REQUIRE_DEVICE(r);
  // Finds the renderer's device and builds the types with every feature compiled out.
  cl::Device device;
  bool found = false;
  std::vector<cl::Platform> platforms;
  cl::Platform::get(&platforms);
  for (auto& p : platforms) {
    std::vector<cl::Device> devs;
    try {
      p.getDevices(CL_DEVICE_TYPE_ALL, &devs);
    } catch (const cl::Error&) {
      continue;
    }
    for (auto& d : devs) {
      std::string name = d.getInfo<CL_DEVICE_NAME>();
      while (!name.empty() && (name.back() == '\0' || name.back() == ' ')) name.pop_back();
      if (!found && name == r->name()) {
        device = d;
        found = true;
      }
    }
  }
  ASSERT_TRUE(found) << r->name();
  cl::Context ctx(device);
  cl::CommandQueue queue(ctx, device);
  // The kernel's own rt_sizes, generated from cl/data_arrays.h, against the host's table
  // generated from the same list, with every feature compiled out.
  // Both node widths: the kernel's struct at each against the host's arrays at each.
  for (int width : {4, 8}) {
    if (!rt::valid_bvh_width(width)) continue;  // A build of RT_BVH_WIDTH=8 makes 8 only.
    SCOPED_TRACE("RT_BVH_WIDTH=" + std::to_string(width));
    cl::Program program(ctx, std::string(rt::kKernelSource));
    try {
      program.build(
          {device},
          ("-cl-std=CL1.2 -DRT_KERNEL_FEATURES=0 -DRT_BVH_WIDTH=" + std::to_string(width)).c_str());
    } catch (const cl::Error&) {
      FAIL() << program.getBuildInfo<CL_PROGRAM_BUILD_LOG>(device);
    }
    std::vector<std::pair<const char*, uint64_t>> host = rt::scene_layout(width);
    ASSERT_GE(host.size(), 11u);  // float3, header, camera, outputs and the six arrays.
    cl::Kernel k(program, "rt_sizes");
    cl::Buffer out(ctx, CL_MEM_WRITE_ONLY, host.size() * sizeof(cl_int));
    k.setArg(0, out);
    queue.enqueueNDRangeKernel(k, cl::NullRange, cl::NDRange(1), cl::NullRange);
    std::vector<cl_int> s(host.size());
    queue.enqueueReadBuffer(out, CL_TRUE, 0, s.size() * sizeof(cl_int), s.data());
    for (size_t i = 0; i < host.size(); ++i) EXPECT_EQ(s[i], (int)host[i].second) << host[i].first;
  }
}

// The OpenCL device on a CPU traverses 8-wide nodes (RenderDevice::bvh_width), the CPU
// reference 4-wide ones: the images must still be the same bytes, which ties settled by
// index rather than by visiting order make them (ClosestHitWins in cl/bvh/bvh.h). Scenes of
// meshes, instances and spheres, all three renders with the same seed.
TEST(OpenCl, EveryBvhWidthRendersTheSameImage) {
  REQUIRE_DEVICE(r);
  if (!rt::valid_bvh_width(4) || !rt::valid_bvh_width(8)) GTEST_SKIP() << "an 8-wide build";
  for (const char* rel : {"/hw1/bunny.xml", "/hw1/scienceTree.xml", "/hw2/ellipsoids.xml",
                          "/hw2/spheres.xml", "/hw3/tap_water/xml/tap_0200.xml"}) {
    SCOPED_TRACE(rel);
    Loaded four, eight;
    try {
      four = load(rel, 4, 64, 4);
      eight = load(rel, 4, 64, 8);
    } catch (const std::exception& e) {  // The scene or its PLY files are not in ../shared.
      std::printf("[ skipped ] %s\n", e.what());
      continue;
    }
    ASSERT_EQ(eight.flat.bvh_width, 8);
    ASSERT_EQ(eight.flat.triangles.size(), four.flat.triangles.size());
    // Half as many elements would mean the host built 4-wide nodes in 8-wide storage.
    ASSERT_LT(eight.flat.stats.nodes, four.flat.stats.nodes);
    rt::DeviceLoadInfo info;
    rt::RenderResult cl8 = render_on_cl(eight.flat, false, &info);
    EXPECT_NE(info.build_options.find("-DRT_BVH_WIDTH=8"), std::string::npos);
    rt::RenderResult cl4 = render_on_cl(four.flat, false);
    rt::RenderResult cpu = render_on_cpu(four.flat);
    EXPECT_TRUE(identical(cl8, cpu));
    EXPECT_TRUE(identical(cl4, cpu));
    // The same first hits, primitive for primitive (the fields, not the padding).
    int other_hits = 0;
    for (size_t i = 0; i < cpu.primary.size(); ++i) {
      const PrimaryInfo &a = cl8.primary[i], &b = cpu.primary[i];
      other_hits += a.instance != b.instance || a.primitive != b.primitive || a.t != b.t ||
                    a.normal.x != b.normal.x || a.normal.y != b.normal.y ||
                    a.normal.z != b.normal.z;
    }
    EXPECT_EQ(other_hits, 0);
    // The CPU reference renders its own width only, and says so.
    rt::CpuDevice cpu_device(1);
    EXPECT_THROW(cpu_device.load(eight.flat), std::runtime_error);
  }
}

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

TEST(OpenCl, MatchesCpuOnSimple) {
  REQUIRE_DEVICE(r);
  SKIP_WITHOUT_SCENE("/hw1/simple.xml");
  Loaded l = load("/hw1/simple.xml", 0, 96);
  expect_agree("hw1/simple", render_on_cl(l.flat, false), render_on_cpu(l.flat));
}

TEST(OpenCl, MatchesCpuOnTransformedSpheres) {
  REQUIRE_DEVICE(r);
  SKIP_WITHOUT_SCENE("/hw2/spheres.xml");
  Loaded l = load("/hw2/spheres.xml", 0, 96);
  ASSERT_TRUE(l.flat.header.features & RT_FEATURE_TRANSFORMS);
  expect_agree("hw2/spheres", render_on_cl(l.flat, false), render_on_cpu(l.flat));
}

TEST(OpenCl, MatchesCpuOnAreaLightsWithSampling) {
  REQUIRE_DEVICE(r);
  SKIP_WITHOUT_SCENE("/hw3/cornellbox_area.xml");
  Loaded l = load("/hw3/cornellbox_area.xml", 4, 64);
  ASSERT_TRUE(l.flat.header.features & RT_FEATURE_AREA_LIGHTS);
  rt::RenderResult cl = render_on_cl(l.flat, false);
  EXPECT_EQ(cl.samples, 64u * 64u * 4u);
  expect_agree("hw3/cornellbox_area 4 spp", cl, render_on_cpu(l.flat));
}

// Odd sizes: the global size is rounded up to the work-group size, and the kernel must
// skip the extra work-items.
TEST(OpenCl, OddImageSize) {
  REQUIRE_DEVICE(r);
  SKIP_WITHOUT_SCENE("/hw1/simple.xml");
  Loaded l = load("/hw1/simple.xml", 0, 37);
  l.flat.header.camera.height = 13;
  expect_agree("hw1/simple 37x13", render_on_cl(l.flat, false), render_on_cpu(l.flat));
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

// Runs a shell command; returns its exit status (or -1).
int run(const std::string& cmd) {
  int status = std::system(cmd.c_str());
  if (status == -1 || !WIFEXITED(status)) return -1;
  return WEXITSTATUS(status);
}

std::string slurp(const fs::path& p) {
  std::ifstream in(p);
  std::stringstream ss;
  ss << in.rdbuf();
  return ss.str();
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
