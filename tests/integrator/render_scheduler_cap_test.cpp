// The scheduler under --checkpoint: no pass is planned longer than the interval (but at
// least one sample of the image), so a checkpoint, written between passes, comes within
// about one interval of being due even on an image whose passes would otherwise last
// seconds.
#include <gtest/gtest.h>

#include <vector>

#include "integrator/render_scheduler.h"

namespace {

// The sample counts of the passes of a render whose row-samples each cost `per_row_sample`
// exactly, checking that each pass lasts at most `cap` seconds or is one sample.
std::vector<int> CappedPasses(rt::RenderScheduler& s, double per_row_sample, double cap) {
  std::vector<int> counts;
  for (std::vector<rt::RenderWork> pass = s.plan(); !pass.empty(); pass = s.plan()) {
    counts.push_back(pass[0].samples());
    double seconds = 0;
    for (const rt::RenderWork& w : pass) {
      const double t = per_row_sample * w.rows() * w.samples();
      s.record(w, t);
      seconds += t;
    }
    if (pass[0].samples() > 1) {
      EXPECT_LE(seconds, cap * (1 + 1e-9)) << "pass " << counts.size();
    }
  }
  return counts;
}

// A 1000 x 1000 image at 0.12 s a sample: uncapped, its passes grow to 16 and 19 samples
// (about 2 s each, tests/integrator/render_scheduler_last_pass_test.cpp); under a 0.5 s
// interval they stop at 4 samples (0.48 s), and every sample is still taken.
TEST(RenderSchedulerCap, PassesStayWithinTheCheckpointInterval) {
  rt::RenderScheduler s(1000, 1000, 40, 8);
  s.cap_pass_seconds(0.5);
  EXPECT_EQ(CappedPasses(s, 1.2e-4, 0.5), (std::vector<int>{1, 4, 4, 4, 4, 4, 4, 4, 4, 4, 3}));
  EXPECT_EQ(s.samples_done(), 40);
}

// The last samples are not taken together with the pass before them when that would pass
// the interval: 9 samples come as 1 + 4 + 4, not 1 + 8 (0.96 s).
TEST(RenderSchedulerCap, LastPassIsNotMergedPastTheInterval) {
  rt::RenderScheduler s(1000, 1000, 9, 8);
  s.cap_pass_seconds(0.5);
  EXPECT_EQ(CappedPasses(s, 1.2e-4, 0.5), (std::vector<int>{1, 4, 4}));
  // An interval the merged pass fits in keeps it: 1 + 8 within 1 s.
  rt::RenderScheduler t(1000, 1000, 9, 8);
  t.cap_pass_seconds(1.0);
  EXPECT_EQ(CappedPasses(t, 1.2e-4, 1.0), (std::vector<int>{1, 8}));
}

// An interval shorter than one sample of the image leaves passes of one sample: a pass
// never splits a sample between checkpoints (every pixel holds the same count).
TEST(RenderSchedulerCap, AnIntervalBelowOneSampleGivesOneSamplePasses) {
  rt::RenderScheduler s(1000, 1000, 5, 8);
  s.cap_pass_seconds(0.05);
  EXPECT_EQ(CappedPasses(s, 1.2e-4, 0.05), (std::vector<int>{1, 1, 1, 1, 1}));
}

// A small image, whose passes the target keeps short anyway, plans the same passes under a
// long interval as without one.
TEST(RenderSchedulerCap, ALongIntervalChangesNothing) {
  rt::RenderScheduler a(64, 32, 4000, 1), b(64, 32, 4000, 1);
  b.cap_pass_seconds(100);
  EXPECT_EQ(CappedPasses(a, 2e-5, 1e9), CappedPasses(b, 2e-5, 100));
}

}  // namespace
