// Spawned rays over 10^-8 .. 10^8: a mirror's reflected image must equal the directly seen
// image at every scale, so reflected rays neither re-hit their mirror nor start off it.
//
// Each case renders on the CPU reference, checks its property, then renders the same scenes
// on the OpenCL kernel when there is one and requires the devices to agree
// (tests/support/stability_harness.h).
#include <gtest/gtest.h>

#include <cstdio>
#include <string>
#include <utility>

#include "support/stability_harness.h"

namespace {

using namespace stab;

struct MirrorScenes {
  rt::SceneDesc with_mirror, direct;
};

MirrorScenes MirrorSetup(double s, int size) {
  const Vec3d n = rt::normalize(V(0.2, 1, 0.1));
  const Vec3d t1 = rt::normalize(rt::cross(V(0, 0, 1), n)), t2 = rt::cross(n, t1);
  const Vec3d c0 = V(0.3, 0.1, -0.2) * s;
  // Mirror-frame coordinates (along t1, along n, along t2), in units of s.
  auto at = [&](double x, double hgt, double z) { return c0 + (t1 * x + n * hgt + t2 * z) * s; };
  auto reflect = [&](Vec3d p) { return p - n * (2 * rt::dot(p - c0, n)); };
  auto reflect_v = [&](Vec3d v) { return v - n * (2 * rt::dot(v, n)); };
  auto build = [&](bool mirror, bool reflected_camera) {
    Builder b;
    b.scene().max_depth = 3;
    int diffuse = b.material(Plain(V(0.8, 0.7, 0.4), Gray(0.2), 20));
    int ball = b.material(Plain(V(0.2, 0.4, 0.9), Gray(0.5), 50));
    int reflector = b.material(Mirror(Gray(1)));
    // The mirror faces the camera: one seen from behind reflects from its far side, as the
    // course's renderer does (cl/material/mirror.h), which is not what this test is about.
    if (mirror) b.quad(at(-6, 0, -6), at(6, 0, -6), at(6, 0, 6), at(-6, 0, 6), reflector);
    // The diffuse plane 3 above the mirror, facing it.
    b.quad(at(-3, 3, -3), at(-3, 3, 3), at(3, 3, 3), at(3, 3, -3), diffuse);
    b.sphere(at(-0.6, 2.2, 0.4), 0.5 * s, ball);
    b.point_light(at(1.5, 1.4, 0.5), Gray(400 * s * s));
    Vec3d eye = at(4, 2, 0.3), target = at(2, 0, 0), up = n;
    if (reflected_camera) {
      eye = reflect(eye);
      target = reflect(target);
      up = reflect_v(up);
    }
    b.camera(eye, target, up, 0.35 * s, 0.35 * s, 1 * s, size, size);
    return b.scene();
  };
  return {build(true, false), build(false, true)};
}

// Mirrors a moment image left-right (the reflected camera's image is mirrored).
rt::MomentImage FlipX(rt::MomentImage m) {
  rt::MomentImage out = m;
  for (int y = 0; y < m.height; ++y)
    for (int x = 0; x < m.width; ++x) {
      size_t i = static_cast<size_t>(y) * m.width + x;
      size_t j = static_cast<size_t>(y) * m.width + (m.width - 1 - x);
      for (int c = 0; c < 3; ++c) {
        out.mean[j * 3 + c] = m.mean[i * 3 + c];
        out.var[j * 3 + c] = m.var[i * 3 + c];
        out.normal[j * 3 + c] = m.normal[i * 3 + c];
      }
      out.count[j] = m.count[i];
      out.first_t[j] = m.first_t[i];
      out.instance[j] = m.instance[i];
      out.primitive[j] = m.primitive[i];
    }
  return out;
}

class StabilityMirror : public ::testing::TestWithParam<double> {};

TEST_P(StabilityMirror, MirroredImageEqualsDirectImage) {
  const double s = GetParam();
  const int size = 32;
  MirrorScenes scenes = MirrorSetup(s, size);
  char tag[32];
  std::snprintf(tag, sizeof tag, "mirror s=%g", s);
  auto run = [&](Dev d) {
    Shots shots;
    rt::RenderOptions o;
    o.spp = 24;
    o.use_scene_epsilon = false;
    rt::RenderResult a = RenderOn(d, Flatten(scenes.with_mirror, o), std::string(tag) + "_A");
    o.seed = 1;
    rt::RenderResult b = RenderOn(d, Flatten(scenes.direct, o), std::string(tag) + "_B");
    ExpectFinite(a, std::string(tag) + " reflected " + Name(d));
    ExpectFinite(b, std::string(tag) + " direct " + Name(d));
    rt::MomentImage ma = Moments(a, "a"), mb = FlipX(Moments(b, "b"));
    cmp::Verdict v = WelchVerdict(ma, mb);
    // Pixels that see less through the mirror than directly by more than 10%.
    size_t darker = 0;
    double sum_a = 0, sum_b = 0;
    for (size_t i = 0; i < ma.mean.size(); ++i) {
      darker += ma.mean[i] < 0.9 * mb.mean[i] - 1e-3;
      sum_a += ma.mean[i];
      sum_b += mb.mean[i];
    }
    std::printf(
        "[ mirror ] s=%-6g %-3s %s; image mean %.2f reflected vs %.2f direct, %zu "
        "values >10%% darker;%s\n",
        s, Name(d), Describe(v).c_str(), sum_a / ma.mean.size(), sum_b / mb.mean.size(), darker,
        g_last_failing_cells.c_str());
    EXPECT_TRUE(v.pass) << tag << " (" << Name(d) << "): " << Describe(v);
    shots.push_back({std::string(tag) + " reflected", std::move(a)});
    shots.push_back({std::string(tag) + " direct", std::move(b)});
    return shots;
  };
  RUN_BOTH_DEVICES(run);
}

INSTANTIATE_TEST_SUITE_P(Scales, StabilityMirror, ::testing::Values(1e-8, 1e-4, 1.0, 1e4, 1e8),
                         [](const ::testing::TestParamInfo<double>& i) {
                           char buf[16];
                           std::snprintf(buf, sizeof buf, "s%g", i.param);
                           std::string n = buf;
                           for (char& c : n)
                             if (c == '-')
                               c = 'm';
                             else if (c == '+' || c == '.')
                               c = '_';
                           return n;
                         });

}  // namespace
