// The scene's arrays on the OpenCL device (src/device/cl/cl_scene_buffers.cpp): the struct
// layouts the kernel compiles against the host's, at both BVH node widths, and the arrays
// of either width rendering the image the CPU reference renders, byte for byte.
#define CL_HPP_ENABLE_EXCEPTIONS
#include <gtest/gtest.h>
#include <CL/opencl.hpp>

#include <filesystem>
#include <stdexcept>
#include <string>
#include <utility>
#include <vector>

#include "bvh/bvh_lanes.h"
#include "device/cl/cl_program.h"
#include "device/cl/cl_scene_buffers.h"
#include "device/cpu/cpu_device.h"
#include "support/cl_harness.h"
#include "support/device_harness.h"

namespace fs = std::filesystem;

namespace {

using namespace rt::test;

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
    ASSERT_EQ(eight.kernel.bvh_width, 8);
    ASSERT_EQ(eight.flat.triangles.size(), four.flat.triangles.size());
    // Half as many elements would mean the host built 4-wide nodes in 8-wide storage.
    ASSERT_LT(eight.flat.stats.nodes, four.flat.stats.nodes);
    rt::DeviceLoadInfo info;
    rt::RenderResult cl8 = render_on_cl(eight.flat, false, &info, eight.kernel);
    EXPECT_NE(info.build_options.find("-DRT_BVH_WIDTH=8"), std::string::npos);
    rt::RenderResult cl4 = render_on_cl(four.flat, false, nullptr, four.kernel);
    rt::RenderResult cpu = render_cpu(four.flat);
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
    EXPECT_THROW(cpu_device.load(eight.flat, eight.kernel), std::runtime_error);
  }
}

}  // namespace
