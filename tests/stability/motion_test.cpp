// Motion larger than the scene: a sphere flying 1e4 units away over the shutter must give
// the analytic time-averaged coverage.
//
// Each case renders on the CPU reference, checks its property, then renders the same scenes
// on the OpenCL kernel when there is one and requires the devices to agree
// (tests/support/stability_harness.h).
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <string>
#include <utility>
#include <vector>

#include "support/stability_harness.h"

namespace {

using namespace stab;

TEST(StabilityMotion, MotionLargerThanTheSceneHasTheRightCoverage) {
  const int size = 32, spp = 64;
  const double speed = 1e4, d0 = 5, half = 0.02;
  Builder b;
  b.scene().ambient = Gray(kAmbient);
  b.sphere(V(0, 0, -d0), 1, b.material(AmbientOnly()), V(0, 0, -speed));
  // Static scene content around it, far outside the view.
  b.quad(V(-3, -3, -8), V(3, -3, -8), V(3, -2.5, -8), V(-3, -2.5, -8), b.material(AmbientOnly()));
  b.camera(V(0, 0, 0), V(0, 0, -1), V(0, 1, 0), half, half, 1, size, size);
  rt::SceneDesc receding = b.scene();
  // And sideways: 1e4 across a view 10 units wide (it is in view ~1e-3 of the shutter).
  Builder side;
  side.scene().ambient = Gray(kAmbient);
  side.sphere(V(-5e3, 0, -10), 1, side.material(AmbientOnly()), V(1e4, 0, 0));
  side.camera(V(0, 0, 0), V(0, 0, -1), V(0, 1, 0), 0.5, 0.5, 1, size, size);

  // Expected coverage per pixel.
  std::vector<double> expect(size * size);
  const int sub = 16;
  for (int y = 0; y < size; ++y)
    for (int x = 0; x < size; ++x) {
      double acc = 0;
      for (int j = 0; j < sub; ++j)
        for (int i = 0; i < sub; ++i) {
          double fx = -half + 2 * half * (x + (i + 0.5) / sub) / size;
          double fy = half - 2 * half * (y + (j + 0.5) / sub) / size;
          double sin_t = std::sqrt(fx * fx + fy * fy) / std::sqrt(fx * fx + fy * fy + 1);
          acc += std::clamp((1 / sin_t - d0) / speed, 0.0, 1.0);
        }
      expect[static_cast<size_t>(y) * size + x] = acc / (sub * sub);
    }
  auto run = [&](Dev d) {
    Shots shots;
    rt::RenderOptions o;
    o.spp = spp;
    rt::RenderResult r = RenderOn(d, Flatten(receding, o), "motion_receding");
    ExpectFinite(r, std::string("receding ") + Name(d));
    std::vector<float> rgb = r.rgb();
    // Rings by distance from the centre in pixels: 0-2, 2-5, 5-9, 9-23.
    const double edges[] = {0, 2, 5, 9, 23};
    double got[4] = {0, 0, 0, 0}, want[4] = {0, 0, 0, 0}, var[4] = {0, 0, 0, 0};
    for (int y = 0; y < size; ++y)
      for (int x = 0; x < size; ++x) {
        size_t i = static_cast<size_t>(y) * size + x;
        double rr = std::hypot(x + 0.5 - size / 2.0, y + 0.5 - size / 2.0);
        int k = 0;
        while (k < 3 && rr >= edges[k + 1]) ++k;
        double p = expect[i];
        got[k] += rgb[i * 3] / kAmbient * spp;
        want[k] += p * spp;
        var[k] += spp * p * (1 - p);  // Binomial; stratified time only lowers it.
      }
    double tg = 0, tw = 0, tv = 0;
    for (int k = 0; k < 4; ++k) {
      double z = (got[k] - want[k]) / std::sqrt(var[k] + 1e-9);
      std::printf("[ motion ] ring %d %-3s %.1f hits, expected %.1f +- %.1f (z = %+.2f)\n", k,
                  Name(d), got[k], want[k], std::sqrt(var[k]), z);
      EXPECT_LT(std::fabs(z), 5) << "ring " << k << " (" << Name(d) << ")";
      tg += got[k];
      tw += want[k];
      tv += var[k];
    }
    EXPECT_LT(std::fabs(tg - tw) / std::sqrt(tv), 5) << Name(d);
    shots.push_back({"motion receding", std::move(r)});
    rt::RenderResult s = RenderOn(d, Flatten(side.scene(), o), "motion_sideways");
    ExpectFinite(s, std::string("sideways ") + Name(d));
    shots.push_back({"motion sideways", std::move(s)});
    return shots;
  };
  RUN_BOTH_DEVICES(run);
}

}  // namespace
