// The scheduler's last pass: a pass after which the samples left would make a last pass no
// larger than it takes them too, unless a stop rule needs the passes as checkpoints.
#include <gtest/gtest.h>

#include <vector>

#include "integrator/render_scheduler.h"

namespace {

// The sample counts of the passes of a render whose row-samples each cost `per_row_sample`.
std::vector<int> PassSamples(rt::RenderScheduler& s, double per_row_sample) {
  std::vector<int> counts;
  for (std::vector<rt::RenderWork> pass = s.plan(); !pass.empty(); pass = s.plan()) {
    counts.push_back(pass[0].samples());
    for (const rt::RenderWork& w : pass) {
      EXPECT_EQ(w.sample_begin, pass[0].sample_begin);
      EXPECT_EQ(w.sample_end, pass[0].sample_end);
      s.record(w, per_row_sample * w.rows() * w.samples());
    }
  }
  return counts;
}

// tap_0200 at 9 samples on one thread: one sample of a 1000 x 1000 image takes ~0.12 s, so the
// target (0.15 s over 66 rows) would take 19 samples: the 8 left come in one pass.
TEST(RenderSchedulerRest, TapAtNineSamplesTakesOnePlusEight) {
  rt::RenderScheduler s(1000, 1000, 9, 8);
  EXPECT_EQ(PassSamples(s, 1.2e-4), (std::vector<int>{1, 8}));
  EXPECT_EQ(s.samples_done(), 9);
}

TEST(RenderSchedulerRest, StopRulesKeepTheFourfoldCheckpoints) {
  rt::RenderScheduler s(1000, 1000, 9, 8);
  s.keep_checkpoints();
  EXPECT_EQ(PassSamples(s, 1.2e-4), (std::vector<int>{1, 4, 4}));
}

// Growth stays fourfold while more is left than twice the pass: at the same cost as above,
// 20 samples come as 1 + 4 + 15 and 40 as 1 + 4 + 16 + 19 (the last pass the target's 19).
TEST(RenderSchedulerRest, LongerRendersStillGrowFourfold) {
  rt::RenderScheduler a(1000, 1000, 20, 8);
  EXPECT_EQ(PassSamples(a, 1.2e-4), (std::vector<int>{1, 4, 15}));
  rt::RenderScheduler b(1000, 1000, 40, 8);
  EXPECT_EQ(PassSamples(b, 1.2e-4), (std::vector<int>{1, 4, 16, 19}));
}

// A slow image, whose target is one sample a pass at 0.01 s a row-sample, takes its last two
// samples in one pass of bands half as tall, each band still about the target.
TEST(RenderSchedulerRest, SlowImagesTakeTheirLastTwoSamplesTogether) {
  rt::RenderScheduler s(1000, 1000, 5, 8);
  EXPECT_EQ(PassSamples(s, 1e-2), (std::vector<int>{1, 1, 1, 2}));
  rt::RenderScheduler t(1000, 1000, 5, 8);
  std::vector<rt::RenderWork> pass = t.plan();
  for (; !pass.empty() && pass[0].samples() == 1; pass = t.plan())
    for (const rt::RenderWork& w : pass) t.record(w, 1e-2 * w.rows() * w.samples());
  ASSERT_FALSE(pass.empty());
  EXPECT_EQ(pass[0].samples(), 2);
  for (size_t i = 0; i + 1 < pass.size(); ++i)
    EXPECT_NEAR(1e-2 * pass[i].rows() * pass[i].samples(), 0.15, 0.02) << "band " << i;
}

}  // namespace
