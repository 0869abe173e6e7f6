// The memory check before a render, through the executable on each device: a render that
// cannot fit is refused before anything is allocated, in one line naming the resolution
// and the bytes needed.
#include <gtest/gtest.h>

#include <string>

#include "support/cli_harness.h"
#include "support/device_harness.h"

namespace {

using namespace rt::test;

class Memory : public CliFixture, public ::testing::WithParamInterface<rt::Device> {};

TEST_P(Memory, HugeResolutionIsRefusedBeforeRendering) {
  std::string why;
  if (GetParam() == rt::Device::kOpenCl && !shared_device(rt::Device::kOpenCl, &why))
    GTEST_SKIP() << "no OpenCL device: " << why;
  // 32768 x 16 = 524288 pixels a side: 2.7e11 pixels, terabytes of film on any device.
  const std::string scene =
      write("s.xml", replaced(kTinyScene, "<ImageResolution>16 8", "<ImageResolution>32768 32768"));
  Outcome r = run(quote(scene) + " --quiet --device " + device_label(GetParam()) +
                  " --resolution-scale 16 --output-dir " + quote(out_));
  EXPECT_EQ(r.code, 1);
  expect_one_error_line(r);
  EXPECT_NE(r.err.find("simple.png: 524288x524288 pixels need "), std::string::npos) << r.err;
  EXPECT_NE(r.err.find(" bytes)"), std::string::npos) << r.err;
  EXPECT_TRUE(output_files().empty());
}

INSTANTIATE_TEST_SUITE_P(Devices, Memory, ::testing::Values(rt::Device::kCpu, rt::Device::kOpenCl),
                         [](const auto& info) { return std::string(device_label(info.param)); });

}  // namespace
