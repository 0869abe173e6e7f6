// Running the built raytracer executable from a test: a fixture with its own temporary
// directory (the scene it renders is usually kTinyScene), the same once per device, and the
// outcome of a run.
#pragma once

#include <gtest/gtest.h>

#include <sys/types.h>

#include <filesystem>
#include <string>
#include <vector>

#include "device/device.h"
#include "support/test_scene.h"

namespace rt::test {

// `s` quoted for sh.
std::string quote(const std::string& s);

struct Outcome {
  int code = -1;  // Exit status; 124 when `timeout` killed it; 128 + n for signal n.
  std::string out, err;
  double seconds = 0;
};

// One line: exactly one newline, at the end, after the "raytracer: error: " prefix.
void expect_one_error_line(const Outcome& r);

class CliFixture : public TempDirTest {
 protected:
  void SetUp() override;

  // Runs the raytracer with `args` (already quoted), stdin empty, stdout and stderr captured
  // to files (so neither is a terminal), under a timeout of timeout_s_ seconds; `env`
  // prefixes the command.
  Outcome run(const std::string& args, const std::string& env = "");
  // The usual options: CPU, quiet, the temporary output directory.
  Outcome render(const std::string& scene, const std::string& extra = "");
  // Starts the raytracer with `args` in the background like run(), and returns its pid
  // once its signal handlers are installed (so a signal finds them).
  pid_t start(const std::string& args);
  // Waits for a started raytracer (killing it after 30 s) and returns its outcome.
  Outcome finish(pid_t pid);
  // The names in the output directory.
  std::vector<std::string> output_files() const;

  std::string out_;     // The output directory, dir_/out.
  int timeout_s_ = 10;  // run()'s limit: a kernel build under load takes seconds.
};

// A CliFixture whose parameter is the device every run of the test uses; skipped, saying
// why, where no OpenCL device is usable.
class DeviceCliFixture : public CliFixture, public ::testing::WithParamInterface<Device> {
 protected:
  void SetUp() override;
  // " --device cpu" or " --device cl".
  std::string device_flag() const;
};

// The instantiation's names: "cpu" and "cl".
std::string device_param_name(const ::testing::TestParamInfo<Device>& info);

// Instantiates the DeviceCliFixture suite `suite` on both devices, as Devices/<suite>.<test>/cpu
// and .../cl.
#define RT_INSTANTIATE_ON_DEVICES(suite)                                                 \
  INSTANTIATE_TEST_SUITE_P(Devices, suite,                                               \
                           ::testing::Values(::rt::Device::kCpu, ::rt::Device::kOpenCl), \
                           ::rt::test::device_param_name)

}  // namespace rt::test
