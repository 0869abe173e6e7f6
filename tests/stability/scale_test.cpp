// Scale and translation invariance: the stage (tests/support/stability_scenes.h) mapped by
// x -> s x + t (s = 1e-4, 1e4; t 1e5 from the origin), with and without the scene's epsilon,
// must render the same image (compare tool: Welch per pixel, independent seeds, 24 spp
// unstratified). The scene's absolute epsilon at scale 1e-4 is a known limit, kept as a test.
//
// Each case renders on the CPU reference, checks its property, then renders the same scenes
// on the OpenCL kernel when there is one and requires the devices to agree
// (tests/support/stability_harness.h).
#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <string>
#include <utility>
#include <vector>

#include "support/stability_harness.h"

namespace {

using namespace stab;

struct ScaleFigures {
  cmp::Verdict verdict;
  double mean_abs_rel = 0;  // mean |variant - original| over the mean original value
  size_t nonfinite = 0;
};

// Original (seed 0) against the mapped scene (seed 1) on one device.
ScaleFigures CompareScaled(Dev d, double s, Vec3d t, bool use_eps, const std::string& label,
                           Shots* shots) {
  rt::RenderOptions o;
  o.spp = kStageSpp;
  o.use_scene_epsilon = use_eps;
  // Scale invariance is --ray-offset robust's promise; the default (the course's offset, the
  // scene's epsilon alone) is an absolute length, as in the known limit below.
  o.robust_offset = true;
  rt::SceneDesc base = Stage();
  rt::RenderResult a = RenderOn(d, Flatten(base, o), label + "_original");
  o.seed = 1;
  rt::RenderResult b = RenderOn(d, Flatten(MapScene(base, s, t), o), label);
  ExpectFinite(a, label + " original " + Name(d));
  ExpectFinite(b, label + " " + Name(d));
  ScaleFigures f;
  f.verdict = WelchVerdict(a, b);
  f.nonfinite = b.nonfinite();
  std::vector<float> ra = a.rgb(), rb = b.rgb();
  double num = 0, den = 0;
  for (size_t i = 0; i < ra.size(); ++i) {
    num += std::fabs(static_cast<double>(rb[i]) - ra[i]);
    den += std::fabs(ra[i]);
  }
  f.mean_abs_rel = num / den;
  std::printf("[ scale ] %-34s %-3s %s; mean |diff| %.4f of the mean;%s\n", label.c_str(), Name(d),
              Describe(f.verdict).c_str(), f.mean_abs_rel, g_last_failing_cells.c_str());
  shots->push_back({label + " original", std::move(a)});
  shots->push_back({label, std::move(b)});
  return f;
}

const Vec3d kFarAway = V(1e5 / std::sqrt(3.0), -1e5 / std::sqrt(3.0), 1e5 / std::sqrt(3.0));

// With use_scene_epsilon = false only the scale-aware offset moves spawned rays: the image
// must not depend on the scene's scale or position.
void ExpectScaleInvariant(double s, Vec3d t, bool use_eps, const std::string& label) {
  auto run = [&](Dev d) {
    Shots shots;
    ScaleFigures f = CompareScaled(d, s, t, use_eps, label, &shots);
    EXPECT_TRUE(f.verdict.pass) << label << " (" << Name(d) << "): " << Describe(f.verdict)
                                << ", mean |diff| " << f.mean_abs_rel;
    return shots;
  };
  RUN_BOTH_DEVICES(run);
}

TEST(StabilityScale, ScaledDown1e4WithoutSceneEpsilon) {
  ExpectScaleInvariant(1e-4, {}, false, "scale_1e-4_noeps");
}

TEST(StabilityScale, ScaledUp1e4WithoutSceneEpsilon) {
  ExpectScaleInvariant(1e4, {}, false, "scale_1e4_noeps");
}

TEST(StabilityScale, Translated1e5WithoutSceneEpsilon) {
  ExpectScaleInvariant(1, kFarAway, false, "translate_1e5_noeps");
}

TEST(StabilityScale, ScaledUp1e4WithSceneEpsilon) {
  ExpectScaleInvariant(1e4, {}, true, "scale_1e4_eps");
}

TEST(StabilityScale, Translated1e5WithSceneEpsilon) {
  ExpectScaleInvariant(1, kFarAway, true, "translate_1e5_eps");
}

// Known limit, kept as a test: the scene's ShadowRayEpsilon (1e-3) is an absolute length,
// ten original units once the stage is scaled by 1e-4, so shadow and secondary rays start
// far off their surfaces and the image changes (shadows vanish, reflections shift). The
// test asserts that the compare tool sees it, with the size of the failure measured when
// the test was written; use_scene_epsilon = false (above) is the remedy.
TEST(StabilityScale, ScaledDown1e4WithSceneEpsilonIsAKnownLimit) {
  auto run = [&](Dev d) {
    Shots shots;
    ScaleFigures f = CompareScaled(d, 1e-4, {}, true, "scale_1e-4_eps", &shots);
    EXPECT_FALSE(f.verdict.pass) << "the absolute epsilon no longer breaks a 1e-4 scene: "
                                    "update this known-limit test";
    // Measured when written (both devices): 130 rejected pixel-channels of 4635 tested,
    // mean |difference| 4.6% of the mean value (mirror and glass go black, shadows thin).
    // A figure far from that means the engine changed: look, then update.
    size_t failed = f.verdict.rejections + f.verdict.deterministic;
    EXPECT_GE(failed, 65u) << Describe(f.verdict);
    EXPECT_LE(failed, 260u) << Describe(f.verdict);
    EXPECT_GE(f.mean_abs_rel, 0.023);
    EXPECT_LE(f.mean_abs_rel, 0.093);
    return shots;
  };
  RUN_BOTH_DEVICES(run);
}

}  // namespace
