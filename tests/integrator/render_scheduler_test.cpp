// The scheduler's policy on synthetic costs (no clocks involved), and render_camera on a
// fake device: passes cover the image once with equal sample counts, bands keep to the
// device's row alignment, and cancellation ends sampling at the end of a pass.
#include <gtest/gtest.h>

#include <atomic>

#include "integrator/render_scheduler.h"

namespace {

// Every pass covers each row exactly once with the same samples.
void ExpectCoversOnce(const std::vector<rt::RenderWork>& pass, int height, int align) {
  ASSERT_FALSE(pass.empty());
  int row = 0;
  for (const rt::RenderWork& w : pass) {
    EXPECT_EQ(w.row_begin, row);
    EXPECT_GT(w.rows(), 0);
    if (w.row_end != height) {
      EXPECT_EQ(w.rows() % align, 0) << "band " << w.row_begin;
    }
    EXPECT_EQ(w.sample_begin, pass[0].sample_begin);
    EXPECT_EQ(w.sample_end, pass[0].sample_end);
    row = w.row_end;
  }
  EXPECT_EQ(row, height);
}

// Records a pass as if each row-sample cost `per_row_sample` seconds.
void RunPass(rt::RenderScheduler& s, const std::vector<rt::RenderWork>& pass,
             double per_row_sample) {
  for (const rt::RenderWork& w : pass) s.record(w, per_row_sample * w.rows() * w.samples());
}

TEST(RenderScheduler, FirstPassIsOneSampleOfTheWholeImage) {
  rt::RenderScheduler s(64, 48, 100, 8);
  std::vector<rt::RenderWork> pass = s.plan();
  ASSERT_EQ(pass.size(), 1u);
  EXPECT_EQ(pass[0].row_begin, 0);
  EXPECT_EQ(pass[0].row_end, 48);
  EXPECT_EQ(pass[0].sample_begin, 0);
  EXPECT_EQ(pass[0].sample_end, 1);
}

TEST(RenderScheduler, QuickImagesGrowPassesAtMostFourfoldToTheTarget) {
  const int height = 10, samples = 100000;
  rt::RenderScheduler s(16, height, samples, 1);
  const double per_row_sample = 1e-5;  // 1e-4 s for one sample of the image.
  int last = 1;
  for (int i = 0; i < 8; ++i) {
    std::vector<rt::RenderWork> pass = s.plan();
    ASSERT_EQ(pass.size(), 1u);
    const int n = pass[0].samples();
    EXPECT_LE(n, 4 * last);
    EXPECT_EQ(pass[0].sample_begin, s.samples_done());
    last = n;
    RunPass(s, pass, per_row_sample);
  }
  // The target (0.15 s) over one sample's 1e-4 s.
  EXPECT_EQ(last, 1500);
  EXPECT_NEAR(s.estimate_seconds(s.plan()), 0.15, 1e-9);
}

TEST(RenderScheduler, SlowImagesAreBandedOnTheAlignment) {
  const int height = 100, align = 8;
  rt::RenderScheduler s(16, height, 10, align);
  RunPass(s, s.plan(), 0.02);  // 2 s for one sample of the image: above the split.
  std::vector<rt::RenderWork> pass = s.plan();
  EXPECT_GT(pass.size(), 1u);
  ExpectCoversOnce(pass, height, align);
  for (const rt::RenderWork& w : pass) EXPECT_EQ(w.samples(), 1);
  // About the target per band: 0.15 s / 0.02 s = 7.5 rows, rounded to the alignment.
  EXPECT_EQ(pass[0].rows(), 8);
}

// A wide image whose one sample is quick but whose pass of several would not be: bands of
// at least kMinBandPixels take several samples each, so a pixel's setup is shared by them.
TEST(RenderScheduler, WideImagesTakeSeveralSamplesPerBand) {
  const int width = 1000, height = 1000, align = 8;
  rt::RenderScheduler s(width, height, 1000, align);
  const double per_row_sample = 1e-4;  // 0.1 s for one sample of the image.
  const int min_rows = static_cast<int>(rt::RenderScheduler::kMinBandPixels / width + 1);
  int last = 1;
  for (int i = 0; i < 4; ++i) {
    std::vector<rt::RenderWork> pass = s.plan();
    ExpectCoversOnce(pass, height, align);
    const int n = pass[0].samples();
    EXPECT_LE(n, 4 * last);
    if (i > 0) {
      EXPECT_GT(n, 1) << "pass " << i;
    }
    for (const rt::RenderWork& w : pass) {
      // At least 64 Ki pixels, within the rounding to the alignment.
      if (w.row_end != height) {
        EXPECT_GE(w.rows() + align / 2, min_rows);
      }
      EXPECT_LE(per_row_sample * w.rows() * n, rt::RenderScheduler::kSplitSeconds);
    }
    last = n;
    RunPass(s, pass, per_row_sample);
  }
  // 0.15 s over the 66 rows of 64 Ki pixels, 6.6 ms a sample: 23 samples, reached after
  // 1, 4 and 16 (fourfold growth).
  EXPECT_EQ(last, 23);
  EXPECT_EQ(s.plan()[0].samples(), 23);
}

// A distributed render's tile: passes cover rows [32, 80) of 100 and nothing else, with
// bands on the alignment from the tile's first row.
TEST(RenderScheduler, TilePassesCoverOnlyTheTilesRows) {
  const int align = 8, begin = 32, end = 80;
  rt::RenderScheduler s(16, 100, 10, align, begin, end);
  std::vector<rt::RenderWork> first = s.plan();
  ASSERT_EQ(first.size(), 1u);
  EXPECT_EQ(first[0].row_begin, begin);
  EXPECT_EQ(first[0].row_end, end);
  RunPass(s, first, 0.05);  // Slow: the next pass is banded.
  std::vector<rt::RenderWork> pass = s.plan();
  EXPECT_GT(pass.size(), 1u);
  int row = begin;
  for (const rt::RenderWork& w : pass) {
    EXPECT_EQ(w.row_begin, row);
    EXPECT_EQ(w.row_begin % align, 0);
    row = w.row_end;
  }
  EXPECT_EQ(row, end);
  EXPECT_EQ(s.samples_done(), 1);
}

TEST(RenderScheduler, NothingLeftOnceEverySampleIsTaken) {
  rt::RenderScheduler s(4, 4, 3, 1);
  while (!s.plan().empty()) RunPass(s, s.plan(), 1e-6);
  EXPECT_EQ(s.samples_done(), 3);
}

// Counts samples per pixel the way a film does; cancels after `cancel_after` renders.
class FakeDevice final : public rt::RenderDevice {
 public:
  explicit FakeDevice(int cancel_after, std::atomic<bool>* cancel)
      : cancel_after_(cancel_after), cancel_(cancel) {}
  std::string name() const override { return "fake"; }
  void check_memory(const rt::MemoryNeed&) const override {}
  rt::DeviceLoadInfo load(const rt::FlatScene& flat, const rt::KernelConfig&) override {
    width_ = flat.header.camera.width;
    film_.assign(static_cast<size_t>(width_) * flat.header.camera.height, PixelAccum{});
    return {};
  }
  uint64_t render(const rt::RenderWork& w) override {
    for (int y = w.row_begin; y < w.row_end; ++y)
      for (int x = 0; x < width_; ++x) {
        PixelAccum& a = film_[static_cast<size_t>(y) * width_ + x];
        EXPECT_EQ(a.sum_sq.w, static_cast<float>(w.sample_begin)) << "samples out of order";
        a.sum_sq.w += static_cast<float>(w.samples());
        a.sum.w = a.sum_sq.w;
      }
    if (++calls_ == cancel_after_) cancel_->store(true);
    return 0;
  }
  void read_accum(std::vector<PixelAccum>* accum) override { *accum = film_; }
  void read_primary(std::vector<PrimaryInfo>* primary) override {
    primary->assign(film_.size(), PrimaryInfo{});
  }

 private:
  int cancel_after_, calls_ = 0, width_ = 0;
  std::atomic<bool>* cancel_;
  std::vector<PixelAccum> film_;
};

TEST(RenderScheduler, CancellationEndsSamplingAfterThePass) {
  rt::FlatScene flat;
  flat.header.camera.width = 8;
  flat.header.camera.height = 4;
  flat.header.camera.samples = 1 << 20;
  std::atomic<bool> cancel{false};
  FakeDevice device(3, &cancel);
  rt::Progress quiet(false, "", 0);
  rt::RenderResult r = rt::render_camera(device, flat, rt::KernelConfig(), quiet, {}, &cancel);
  EXPECT_TRUE(r.cancelled);
  EXPECT_GT(r.spp, 1);
  EXPECT_LT(r.spp, 1 << 20);
  for (const PixelAccum& a : r.accum) ASSERT_EQ(a.sum_sq.w, static_cast<float>(r.spp));
}

// sample_rows takes every sample of the tile's rows and leaves the other rows empty.
TEST(RenderScheduler, SampleRowsFillsOnlyTheTile) {
  rt::FlatScene flat;
  flat.header.camera.width = 8;
  flat.header.camera.height = 12;
  flat.header.camera.samples = 7;
  std::atomic<bool> never{false};
  FakeDevice device(-1, &never);
  device.load(flat, rt::KernelConfig());
  rt::Progress quiet(false, "", 0);
  EXPECT_EQ(rt::sample_rows(device, flat.header.camera, 4, 9, quiet), 7);
  std::vector<PixelAccum> film;
  device.read_accum(&film);
  for (int y = 0; y < 12; ++y)
    EXPECT_EQ(film[static_cast<size_t>(y) * 8].sum_sq.w, y >= 4 && y < 9 ? 7.0f : 0.0f)
        << "row " << y;
}

}  // namespace
