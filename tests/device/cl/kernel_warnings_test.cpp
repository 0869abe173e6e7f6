// The kernel compiles without a single warning on the OpenCL device, for the feature sets at
// both ends (none compiled in, all compiled in), for a CPU device's and a GPU's code paths
// (RT_CL_CPU_DEVICE, cl/integrator/pixel.h) and for both node widths. PoCL copies a build's warnings to
// stderr itself, where `--quiet` cannot stop them: a warning in the kernel is noise in every
// user's terminal (the constant operand of && that cl/camera/camera_batch.h once had, with depth of
// field compiled out, printed "1 warning generated." on each kernel compile).
#define CL_HPP_ENABLE_EXCEPTIONS
#include <gtest/gtest.h>
#include <CL/opencl.hpp>

#include <string>
#include <vector>

#include "cl/features.h"
#include "device/cl/cl_program.h"

namespace {

// The first OpenCL device of the first platform that has one, or false.
bool FirstDevice(cl::Device* device) {
  std::vector<cl::Platform> platforms;
  try {
    cl::Platform::get(&platforms);
  } catch (const cl::Error&) {
    return false;
  }
  for (cl::Platform& p : platforms) {
    std::vector<cl::Device> devices;
    try {
      p.getDevices(CL_DEVICE_TYPE_ALL, &devices);
    } catch (const cl::Error&) {
      continue;
    }
    if (!devices.empty()) {
      *device = devices[0];
      return true;
    }
  }
  return false;
}

TEST(OpenClKernel, BuildsWithoutWarnings) {
  cl::Device device;
  if (!FirstDevice(&device)) GTEST_SKIP() << "no OpenCL device";
  cl::Context context(device);
  // Both node widths (cl/bvh/simd.h): the suite's host builds only the default, 4, so the
  // kernel's width-8 code would otherwise go uncompiled.
  for (int width : {4, 8}) {
    for (int features : {0, (int)RT_FEATURE_ALL}) {
      for (const char* target : {"", " -DRT_CL_CPU_DEVICE=1"}) {
        std::string options = "-cl-std=CL1.2 -DRT_KERNEL_FEATURES=" + std::to_string(features) +
                              " -DRT_BVH_WIDTH=" + std::to_string(width) + target;
        cl::Program program(context, std::string(rt::kKernelSource));
        try {
          program.build({device}, options.c_str());
        } catch (const cl::Error&) {
          FAIL() << options << ":\n" << program.getBuildInfo<CL_PROGRAM_BUILD_LOG>(device);
        }
        std::string log = program.getBuildInfo<CL_PROGRAM_BUILD_LOG>(device);
        EXPECT_EQ(log.find("warning"), std::string::npos) << options << ":\n" << log;
      }
    }
  }
}

}  // namespace
