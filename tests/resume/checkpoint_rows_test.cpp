// A checkpoint whose rows hold different sample counts (a distributed render stopped with
// its bands at different passes, src/io/checkpoint.h): the counts survive the file, a
// damaged "rows" line is refused, and one process refuses to continue such a film.
#include <gtest/gtest.h>
#include <signal.h>

#include <chrono>
#include <filesystem>
#include <fstream>
#include <string>
#include <thread>

#include "io/checkpoint.h"
#include "io/partial_mark.h"
#include "support/cli_harness.h"

namespace {

namespace fs = std::filesystem;
using namespace rt::test;

// 2 pixels a row, 4 rows: two rows at 5 samples, two at 3.
rt::Checkpoint banded() {
  rt::Checkpoint c;
  c.key = {{"inputs", "0123"}, {"camera", "0"}};
  c.spp = 3;
  c.row_spp = {5, 5, 3, 3};
  c.accum.resize(8);
  c.primary.resize(8);
  for (size_t i = 0; i < c.accum.size(); ++i) {
    c.accum[i].sum.x = static_cast<float>(i);
    c.accum[i].sum.w = static_cast<float>(i < 4 ? 5 : 3);
    c.primary[i].primitive = static_cast<int>(i);
  }
  return c;
}

TEST_F(CliFixture, CheckpointRowCountsSurviveTheFile) {
  const std::string path = out_ + "/x.rtcheckpoint";
  rt::write_checkpoint(path, banded());
  EXPECT_NE(slurp(path).find("\nrows 2x5,2x3\n"), std::string::npos);
  const rt::Checkpoint back = rt::read_checkpoint(path);
  EXPECT_EQ(back.spp, 3);
  EXPECT_EQ(back.row_spp, (std::vector<int>{5, 5, 3, 3}));
  EXPECT_EQ(back.key, banded().key);
  ASSERT_EQ(back.accum.size(), 8u);
  EXPECT_EQ(back.accum[7].sum.x, 7.0f);
  EXPECT_EQ(back.primary[6].primitive, 6);
  const rt::Checkpoint head = rt::read_checkpoint_header(path);
  EXPECT_EQ(head.row_spp, back.row_spp);
  EXPECT_EQ(head.spp, 3);
  EXPECT_TRUE(head.accum.empty());

  rt::Checkpoint uniform = banded();
  uniform.row_spp.clear();
  rt::write_checkpoint(path, uniform);
  EXPECT_EQ(slurp(path).find("\nrows "), std::string::npos);
  EXPECT_TRUE(rt::read_checkpoint(path).row_spp.empty());
}

TEST_F(CliFixture, CheckpointWithDamagedRowsIsRefused) {
  const std::string path = out_ + "/x.rtcheckpoint";
  for (const auto& [from, to] : {std::pair{"rows 2x5,2x3", "rows 3x5,2x3"},  // 5 rows, 8 pixels
                                 {"rows 2x5,2x3", "rows 2x5,2x4"},           // least is not spp
                                 {"rows 2x5,2x3", "rows 2y5,2x3"}}) {        // not a run
    rt::write_checkpoint(path, banded());
    std::string bytes = slurp(path);
    bytes.replace(bytes.find(from), std::string(from).size(), to);
    std::ofstream(path, std::ios::binary) << bytes;
    try {
      rt::read_checkpoint(path);
      ADD_FAILURE() << to << " was read";
    } catch (const std::runtime_error& e) {
      EXPECT_NE(std::string(e.what()).find(path + ": cannot read checkpoint"), std::string::npos)
          << e.what();
    }
  }
}

// An interrupted one-process render's checkpoint, given rows at different counts: a single
// process refuses it in one line and leaves the partial image as it was.
TEST_F(CliFixture, OneProcessRefusesABandedCheckpoint) {
  const std::string scene = write("s.xml", kTinyScene);
  const std::string args = quote(scene) + " --quiet --device cpu --output-dir " + quote(out_) +
                           " --resolution-scale 4 --seed 3 --threads 1 --spp 4000";
  const pid_t pid = start(args + " --checkpoint 0.05");
  const fs::path cp = fs::path(out_) / "simple.png.rtcheckpoint";
  for (int i = 0; i < 2000 && !fs::exists(cp); ++i)
    std::this_thread::sleep_for(std::chrono::milliseconds(5));
  kill(pid, SIGINT);
  ASSERT_EQ(finish(pid).code, 130);
  rt::Checkpoint c = rt::read_checkpoint(cp.string());
  c.row_spp.assign(c.accum.size() / 64, c.spp);  // 64 pixels a row.
  c.row_spp.back() = c.spp + 1;
  rt::write_checkpoint(cp.string(), c);
  const std::string image = slurp(out_ + "/simple.png");
  const Outcome r = run(args + " --resume");
  EXPECT_EQ(r.code, 1);
  EXPECT_NE(r.err.find(cp.string() + ": not continued here: its bands of rows hold different "
                                     "sample counts"),
            std::string::npos)
      << r.err;
  expect_one_error_line(r);
  EXPECT_EQ(slurp(out_ + "/simple.png"), image);
}

}  // namespace
