// Stopping a render and continuing it, through the executable, on each device: an
// interrupted image is written marked partial with its checkpoint; --resume (or
// --skip-existing) continues it to the bytes of an uninterrupted render (PNG, EXR, moments);
// --skip-existing never takes a partial output for a finished one; --checkpoint writes at
// the interval asked; a checkpoint made with other settings is refused in one line.
#include <gtest/gtest.h>
#include <signal.h>

#include <chrono>
#include <filesystem>
#include <regex>
#include <string>
#include <thread>

#include "io/checkpoint.h"
#include "io/partial_mark.h"
#include "support/cli_harness.h"

namespace {

namespace fs = std::filesystem;
using namespace rt::test;

// The tiny scene at 64x32 with this many samples takes a few seconds on one thread, so an
// interrupt after the first checkpoint lands well before the end.
const char* const kFlags = " --resolution-scale 4 --seed 3 --moments --threads 1";

int count(const std::string& text, const std::string& what) {
  int n = 0;
  for (size_t at = text.find(what); at != std::string::npos; at = text.find(what, at + 1)) ++n;
  return n;
}

class Resume : public DeviceCliFixture {
 protected:
  void SetUp() override {
    DeviceCliFixture::SetUp();
    if (IsSkipped()) return;
    timeout_s_ = 60;  // Renders of seconds, which a loaded machine stretches.
    scene_ = write("s.xml", kTinyScene);
    spp_ = GetParam() == rt::Device::kOpenCl ? " --spp 6000" : " --spp 4000";
  }
  std::string args(const std::string& dir, const std::string& extra) const {
    return quote(scene_) + " --quiet" + device_flag() + " --output-dir " + quote(dir) + kFlags +
           spp_ + extra;
  }
  // The uninterrupted render, in its own folder.
  fs::path reference() {
    const fs::path dir = fs::path(dir_) / "ref";
    fs::create_directories(dir);
    const Outcome r = run(args(dir.string(), ""));
    EXPECT_EQ(r.code, 0) << r.err;
    return dir;
  }
  // A render interrupted once its first checkpoint is there; returns its outcome.
  Outcome interrupted(const std::string& extra = "") {
    const pid_t pid = start(args(out_, " --checkpoint 0.05" + extra));
    const fs::path cp = fs::path(out_) / "simple.png.rtcheckpoint";
    for (int i = 0; i < 2000 && !fs::exists(cp); ++i)
      std::this_thread::sleep_for(std::chrono::milliseconds(5));
    kill(pid, SIGINT);
    return finish(pid);
  }
  // --skip-existing without --quiet, so its notice about a partial image is shown.
  Outcome skip_existing() {
    std::string a = args(out_, " --skip-existing");
    a.replace(a.find(" --quiet"), 8, "");
    return run(a);
  }
  // A run with `flag` leaves the complete image as it is.
  void expect_kept_by(const std::string& flag) {
    const auto before = fs::last_write_time(out_ + "/simple.png");
    ASSERT_EQ(run(args(out_, flag)).code, 0);
    EXPECT_EQ(fs::last_write_time(out_ + "/simple.png"), before) << flag;
  }
  void expect_same_as(const fs::path& ref) {
    for (const char* name : {"simple.png", "simple.moments.exr"})
      EXPECT_EQ(slurp(fs::path(out_) / name), slurp(ref / name)) << name << " differs";
    EXPECT_FALSE(fs::exists(fs::path(out_) / "simple.png.rtcheckpoint"));
  }
  std::string scene_, spp_;
};

TEST_P(Resume, InterruptedThenResumedIsByteIdentical) {
  const fs::path ref = reference();
  const Outcome cut = interrupted();
  ASSERT_EQ(cut.code, 130) << cut.err;
  EXPECT_NE(cut.err.find("and its checkpoint"), std::string::npos) << cut.err;
  const rt::OutputStatus st = rt::output_status(out_ + "/simple.png");
  ASSERT_EQ(st.state, rt::OutputState::kPartial);
  EXPECT_TRUE(std::regex_match(st.mark, std::regex("[0-9]+ of " + spp_.substr(7)))) << st.mark;
  EXPECT_EQ(rt::output_status(out_ + "/simple.moments.exr").state, rt::OutputState::kPartial);
  EXPECT_EQ(rt::output_status(ref.string() + "/simple.png").state, rt::OutputState::kComplete);
  EXPECT_NE(slurp(out_ + "/simple.png"), slurp(ref / "simple.png"));
  const Outcome r = run(args(out_, " --resume"));
  ASSERT_EQ(r.code, 0) << r.err;
  expect_same_as(ref);
  expect_kept_by(" --resume");  // Complete now.
}

TEST_P(Resume, SkipExistingContinuesAPartialImage) {
  const fs::path ref = reference();
  ASSERT_EQ(interrupted().code, 130);
  const Outcome r = skip_existing();
  ASSERT_EQ(r.code, 0) << r.err;
  EXPECT_NE(r.err.find("simple.png is partial ("), std::string::npos) << r.err;
  EXPECT_NE(r.err.find("continuing it from its checkpoint"), std::string::npos) << r.err;
  expect_same_as(ref);
  expect_kept_by(" --skip-existing");  // Complete now.
}

TEST_P(Resume, SkipExistingRendersAPartialImageWithoutCheckpointAgain) {
  const fs::path ref = reference();
  ASSERT_EQ(interrupted().code, 130);
  fs::remove(out_ + "/simple.png.rtcheckpoint");
  const Outcome r = skip_existing();
  ASSERT_EQ(r.code, 0) << r.err;
  EXPECT_NE(r.err.find("no checkpoint, rendering it again"), std::string::npos) << r.err;
  expect_same_as(ref);
}

TEST_P(Resume, MismatchedCheckpointIsRefused) {
  ASSERT_EQ(interrupted().code, 130);
  const std::string before = slurp(out_ + "/simple.png");
  const Outcome r = run(args(out_, " --resume --seed 4"));
  EXPECT_EQ(r.code, 1);
  expect_one_error_line(r);
  EXPECT_NE(r.err.find("simple.png.rtcheckpoint: not continued: --seed is 3 in the "
                       "checkpoint, 4 in this run"),
            std::string::npos)
      << r.err;
  EXPECT_EQ(slurp(out_ + "/simple.png"), before);
  const Outcome scale = run(args(out_, " --resume --resolution-scale 2"));
  EXPECT_NE(scale.err.find("resolution is 64x32 in the checkpoint, 32x16"), std::string::npos)
      << scale.err;
}

// A render of about two seconds with --checkpoint 0.25: each checkpoint is written at the
// end of the first pass 0.25 s or more after the last (its stats line says how long after),
// passes are planned no longer than that (tests/integrator/render_scheduler_cap_test.cpp),
// so the render writes some, each with more samples; an interval longer than the render
// writes none.
TEST_P(Resume, CheckpointWritesAtTheIntervalAsked) {
  const Outcome r = run(args(out_, " --checkpoint 0.25 --stats"));
  ASSERT_EQ(r.code, 0) << r.err;
  const std::regex line(
      "stats: checkpoint: [^\\n]* at ([0-9]+) of [0-9]+ samples per pixel, "
      "([0-9.]+) s after the last or the start\\n");
  int n = 0, last_spp = 0;
  for (std::sregex_iterator it(r.err.begin(), r.err.end(), line), end; it != end; ++it, ++n) {
    EXPECT_GT(std::stoi((*it)[1]), last_spp) << r.err;
    last_spp = std::stoi((*it)[1]);
    EXPECT_GE(std::stod((*it)[2]), 0.25) << r.err;
  }
  EXPECT_EQ(n, count(r.err, "stats: checkpoint: ")) << r.err;
  std::smatch m;
  ASSERT_TRUE(std::regex_search(r.err, m, std::regex("render ([0-9.]+) s"))) << r.err;
  const double seconds = std::stod(m[1]);
  EXPECT_GE(n, 1) << r.err;
  // Every checkpoint after the first lies 0.25 s or more after the one before, within the
  // sampling's time (the first may follow the scene's load at once).
  EXPECT_LE(n, static_cast<int>(seconds / 0.25) + 1) << r.err;
  EXPECT_FALSE(fs::exists(out_ + "/simple.png.rtcheckpoint"));  // Removed once complete.
  EXPECT_EQ(rt::output_status(out_ + "/simple.png").state, rt::OutputState::kComplete);
  const Outcome none = run(args(out_, " --checkpoint 100 --stats"));
  EXPECT_EQ(count(none.err, "stats: checkpoint: "), 0) << none.err;
}

// Without --checkpoint or --resume an interrupt leaves the image, marked partial, and no
// other file (--skip-existing then renders it again, tested above).
TEST_P(Resume, PlainInterruptLeavesNoCheckpoint) {
  const pid_t pid = start(args(out_, ""));
  std::this_thread::sleep_for(std::chrono::milliseconds(300));  // Seconds of passes ahead.
  kill(pid, SIGINT);
  const Outcome r = finish(pid);
  ASSERT_EQ(r.code, 130) << r.err;
  EXPECT_EQ(r.err.find("checkpoint"), std::string::npos) << r.err;
  EXPECT_EQ(rt::output_status(out_ + "/simple.png").state, rt::OutputState::kPartial);
  EXPECT_FALSE(fs::exists(out_ + "/simple.png.rtcheckpoint"));
}

RT_INSTANTIATE_ON_DEVICES(Resume);

// A tone-mapped camera whose EXR exists but whose PNG does not is rendered, not skipped.
TEST_F(CliFixture, SkipExistingNeedsEveryOutputOfTheCamera) {
  const std::string scene =
      write("t.xml", replaced(replaced(kTinyScene, "simple.png", "simple.exr"), "</Camera>",
                              "<Tonemap><TMO>Photographic</TMO><TMOOptions>0.18 1</TMOOptions>"
                              "<Saturation>1.0</Saturation><Gamma>2.2</Gamma></Tonemap></Camera>"));
  ASSERT_EQ(render(scene).code, 0);
  ASSERT_TRUE(fs::exists(out_ + "/simple.png"));
  fs::remove(out_ + "/simple.png");
  ASSERT_EQ(render(scene, "--skip-existing").code, 0);
  EXPECT_TRUE(fs::exists(out_ + "/simple.png"));
  EXPECT_EQ(rt::output_status(out_ + "/simple.exr").state, rt::OutputState::kComplete);
  // With --moments, the missing moment file makes the camera render again too.
  ASSERT_EQ(render(scene, "--skip-existing --moments").code, 0);
  EXPECT_TRUE(fs::exists(out_ + "/simple.moments.exr"));
}

}  // namespace
