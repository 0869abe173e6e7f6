// Interrupting a real render through the executable, on each device: the first SIGINT ends
// sampling at the end of a pass and writes the image with the samples taken (every pixel
// the same count), a second SIGINT or a SIGTERM aborts with 130 / 143; never a temporary
// file, never a half-written image.
#include <gtest/gtest.h>
#include <signal.h>

#include <chrono>
#include <regex>
#include <string>
#include <thread>
#include <vector>

#include "io/moments.h"
#include "io/png_io.h"
#include "support/cli_harness.h"

namespace {

namespace fs = std::filesystem;
using namespace rt::test;

// A million samples per pixel of the tiny scene: minutes of work, so a signal always lands
// while sampling. One CPU thread keeps the suite's CPU time low; the image does not depend
// on it.
const char* const kLong = " --spp 1000000";

class Interrupt : public DeviceCliFixture {
 protected:
  // Starts a render of `scene_text` on the test's device.
  pid_t start_render(const std::string& scene_text, const std::string& extra) {
    const std::string scene = write("s.xml", scene_text);
    return start(quote(scene) + " --quiet" + device_flag() + " --threads 1 --output-dir " +
                 quote(out_) + extra);
  }
  static void pause(int ms) { std::this_thread::sleep_for(std::chrono::milliseconds(ms)); }
};

// The count the executable reports for `image`, or -1.
int reported_samples(const std::string& err, const std::string& image) {
  std::smatch m;
  if (!std::regex_search(err, m, std::regex(image + " written with ([0-9]+) of ([0-9]+)")))
    return -1;
  return std::stoi(m[1]);
}

TEST_P(Interrupt, FirstSigintWritesTheSamplesTaken) {
  pid_t pid = start_render(kTinyScene, std::string(kLong) + " --moments");
  pause(100);
  kill(pid, SIGINT);
  Outcome r = finish(pid);
  EXPECT_EQ(r.code, 130) << r.err;
  const int n = reported_samples(r.err, "simple.png");
  EXPECT_GT(n, 0) << r.err;
  EXPECT_LT(n, 1000000) << r.err;
  EXPECT_EQ(output_files().size(), 2u);  // The image and its moments, no temporary file.
  EXPECT_EQ(rt::read_png(out_ + "/simple.png").width, 16);
  rt::MomentImage m = rt::read_moments(out_ + "/simple.moments.exr");
  EXPECT_EQ(m.info.spp, n);
  for (uint32_t count : m.count) ASSERT_EQ(count, static_cast<uint32_t>(n));
}

// A scene of two cameras: the first finishes its one sample, the interrupt lands while the
// second samples; the first image is whole, the second has the samples taken.
TEST_P(Interrupt, SigintAfterOneImageKeepsItWhole) {
  std::string two = replaced(kTinyScene, "</Cameras>", R"(<Camera id="2">
            <Position>0 0 0</Position> <Gaze>0 0 -1</Gaze> <Up>0 1 0</Up>
            <NearPlane>-1 1 -0.5 0.5</NearPlane> <NearDistance>1</NearDistance>
            <ImageResolution>16 8</ImageResolution> <NumSamples>1000000</NumSamples>
            <ImageName>second.png</ImageName>
        </Camera>
    </Cameras>)");
  pid_t pid = start_render(two, "");
  // Up to a minute: a kernel not in the cache yet is built first, slowly on a loaded machine.
  for (int i = 0; i < 12000 && !fs::exists(out_ + "/simple.png"); ++i) pause(5);
  pause(100);
  kill(pid, SIGINT);
  Outcome r = finish(pid);
  EXPECT_EQ(r.code, 130) << r.err;
  EXPECT_EQ(rt::read_png(out_ + "/simple.png").width, 16);
  const int n = reported_samples(r.err, "second.png");
  EXPECT_GT(n, 0) << r.err;
  EXPECT_LT(n, 1000000) << r.err;
  EXPECT_EQ(rt::read_png(out_ + "/second.png").width, 16);
  EXPECT_EQ(output_files().size(), 2u);
}

// The second SIGINT comes while the first is being honoured (the pass finishing or the
// image being written): the run aborts, and what is left is whole or absent.
TEST_P(Interrupt, SecondSigintAborts) {
  pid_t pid = start_render(kTinyScene, kLong);
  pause(100);
  kill(pid, SIGINT);
  pause(20);
  kill(pid, SIGINT);
  Outcome r = finish(pid);
  EXPECT_EQ(r.code, 130) << r.err;
  for (const std::string& f : output_files()) {
    EXPECT_EQ(f, "simple.png") << "a temporary file was left behind";
    if (f == "simple.png") {
      EXPECT_EQ(rt::read_png(out_ + "/simple.png").width, 16);
    }
  }
}

TEST_P(Interrupt, SigtermAbortsWithoutAnImage) {
  pid_t pid = start_render(kTinyScene, kLong);
  pause(50);
  kill(pid, SIGTERM);
  Outcome r = finish(pid);
  EXPECT_EQ(r.code, 143) << r.err;
  EXPECT_TRUE(output_files().empty());
}

RT_INSTANTIATE_ON_DEVICES(Interrupt);

}  // namespace
