// Needles and slivers: a fan disk of thin triangles and a needle of aspect 1e6 must be
// watertight (full coverage inside their silhouettes).
//
// Each case renders on the CPU reference, checks its property, then renders the same scenes
// on the OpenCL kernel when there is one and requires the devices to agree
// (tests/support/stability_harness.h).
#include <gtest/gtest.h>

#include <array>
#include <cmath>
#include <cstdio>
#include <string>
#include <utility>
#include <vector>

#include "support/stability_harness.h"

namespace {

using namespace stab;

// A disk of radius 1 as a fan of kFan triangles around its centre (each 2 pi / kFan wide:
// aspect ~1300), tilted and off-centre, seen by a 16-spp camera.
TEST(StabilityNeedles, FanDiskOfThinTrianglesIsWatertight) {
  const int kFan = 8192, size = 48;
  const Mat4 tilt = Mat4::translation(V(0.11, -0.07, 0)) * Mat4::rotation(35, V(1, 0.6, 0.2));
  std::vector<Vec3d> pos = {tilt.point(V(0, 0, 0))};
  std::vector<std::array<int, 3>> tris;
  for (int i = 0; i < kFan; ++i) {
    double a = 2 * M_PI * i / kFan;
    pos.push_back(tilt.point(V(std::cos(a), std::sin(a), 0)));
    tris.push_back({{0, 1 + i, 1 + (i + 1) % kFan}});
  }
  const Vec3d centre = tilt.point(V(0, 0, 0)), normal = rt::normalize(tilt.vector(V(0, 0, 1)));
  const Vec3d eye = V(0, 0, 4);
  auto scene_with = [&](bool lit) {
    Builder b;
    b.scene().ambient = Gray(lit ? 0 : kAmbient);
    int m = b.material(lit ? Plain(V(0.7, 0.6, 0.5), Gray(0.3), 30) : AmbientOnly());
    b.mesh(pos, tris, m, /*smooth=*/lit);
    if (lit) b.point_light(V(1, 2, 5), Gray(3000));
    b.camera(eye, V(0, 0, 0), V(0, 1, 0), 0.3, 0.3, 1, size, size);
    return b.scene();
  };
  rt::SceneDesc coverage = scene_with(false), lit = scene_with(true);
  const rt::CameraDesc& c = coverage.cameras[0];
  // Inside when the ray through film point (fx, fy) meets the disk's plane within the
  // inscribed polygon's radius, less a margin of 1e-4.
  auto inside = [&](double fx, double fy) {
    Vec3d dir = V(c.left + (c.right - c.left) * fx / size, c.top - (c.top - c.bottom) * fy / size,
                  -c.near_distance);
    double t = rt::dot(centre - eye, normal) / rt::dot(dir, normal);
    Vec3d q = eye + dir * t - centre;
    return rt::length(q) < std::cos(M_PI / kFan) - 1e-4;
  };
  auto run = [&](Dev d) {
    Shots shots;
    rt::RenderOptions o;
    o.spp = 16;
    rt::RenderResult r = RenderOn(d, Flatten(coverage, o), "fan_coverage");
    ExpectFinite(r, std::string("fan coverage ") + Name(d));
    size_t interior = 0, leaky = 0;
    std::vector<float> rgb = r.rgb();
    for (int y = 0; y < size; ++y)
      for (int x = 0; x < size; ++x) {
        // The pixel square is inside when its four corners are (the silhouette is convex).
        if (!(inside(x, y) && inside(x + 1, y) && inside(x, y + 1) && inside(x + 1, y + 1)))
          continue;
        ++interior;
        size_t i = static_cast<size_t>(y) * size + x;
        if (rgb[i * 3] != kAmbient || r.primary[i].instance < 0) ++leaky;
      }
    std::printf(
        "[ needles ] fan of %d triangles %-3s %zu interior pixels x 16 spp, %zu with a "
        "sample that slipped through\n",
        kFan, Name(d), interior, leaky);
    EXPECT_GT(interior, 300u);
    EXPECT_EQ(leaky, 0u) << Name(d);
    shots.push_back({"fan coverage", std::move(r)});
    rt::RenderResult s = RenderOn(d, Flatten(lit, o), "fan_lit");
    ExpectFinite(s, std::string("fan lit, smooth ") + Name(d));
    size_t dark = 0;
    std::vector<float> srgb = s.rgb();
    for (int y = 0; y < size; ++y)
      for (int x = 0; x < size; ++x)
        if (inside(x, y) && inside(x + 1, y) && inside(x, y + 1) && inside(x + 1, y + 1))
          dark += !(srgb[(static_cast<size_t>(y) * size + x) * 3] > 0);
    EXPECT_EQ(dark, 0u) << "lit fan (" << Name(d) << "): interior pixels without light";
    shots.push_back({"fan lit", std::move(s)});
    return shots;
  };
  RUN_BOTH_DEVICES(run);
}

// The square [-1,1]^2 (z = 0) tiled by six triangles, one of them the needle
// (-1,0) (1,0) (0.3,2e-6): base 2, height 2e-6, aspect 1e6. An anamorphic camera zooms onto
// the needle: its rows span 4e-6 vertically (so dozens of rows cross the needle and its
// neighbours' long edges) and its columns the square's whole width. Every sample whose
// film footprint lies inside the square must hit. Run once as modelled and once moved 1e3
// away from the origin along x and z (float spacing there is 6e-5, the needle is then a
// thirtieth of an ulp thick in world space, and the test is about not slipping between
// its neighbours).
TEST(StabilityNeedles, NeedleOfAspect1e6IsWatertight) {
  const int w = 64, h = 48;
  const double needle = 2e-6;
  auto scene_at = [&](Vec3d offset, bool lit) {
    Builder b;
    b.scene().ambient = Gray(lit ? 0 : kAmbient);
    int m = b.material(lit ? Plain(V(0.7, 0.6, 0.5), Gray(0.3), 30) : AmbientOnly());
    std::vector<Vec3d> p = {V(-1, -1, 0), V(1, -1, 0), V(1, 1, 0),       V(-1, 1, 0),
                            V(-1, 0, 0),  V(1, 0, 0),  V(0.3, needle, 0)};
    for (auto& v : p) v = v + offset;
    // A B C D M1 M2 E = 0 1 2 3 4 5 6.
    b.mesh(p, {{{0, 1, 5}}, {{0, 5, 4}}, {{4, 5, 6}}, {{4, 6, 3}}, {{6, 2, 3}}, {{6, 5, 2}}}, m,
           /*smooth=*/lit);
    if (lit) b.point_light(offset + V(0.5, 0.4, 2), Gray(300));
    Vec3d eye = offset + V(0.05, needle / 2, 3);
    b.camera(eye, eye + V(0, 0, -1), V(0, 1, 0), 1.15 / 3, 2e-6 / 3, 1, w, h);
    return b.scene();
  };
  auto run = [&](Dev d) {
    Shots shots;
    for (Vec3d offset : {V(0, 0, 0), V(1e3, 0, 1e3)}) {
      std::string label = offset.x == 0 ? "needle" : "needle at 1e3";
      rt::SceneDesc cov = scene_at(offset, false);
      const rt::CameraDesc& c = cov.cameras[0];
      rt::RenderOptions o;
      o.spp = 16;
      rt::RenderResult r = RenderOn(d, Flatten(cov, o), label + "_coverage");
      ExpectFinite(r, label + " coverage " + Name(d));
      std::vector<float> rgb = r.rgb();
      size_t interior = 0, leaky = 0;
      for (int y = 0; y < h; ++y)
        for (int x = 0; x < w; ++x) {
          // Columns map to x = eye.x + 3 * film x; rows stay well inside |y| < 1.
          double x0 = c.position.x - offset.x + 3 * (c.left + (c.right - c.left) * x / w);
          double x1 = c.position.x - offset.x + 3 * (c.left + (c.right - c.left) * (x + 1) / w);
          if (x0 < -0.999 || x1 > 0.999) continue;
          ++interior;
          size_t i = static_cast<size_t>(y) * w + x;
          if (rgb[i * 3] != kAmbient) ++leaky;
        }
      std::printf(
          "[ needles ] %-14s %-3s %zu interior pixels x 16 spp, %zu with a sample that "
          "slipped through\n",
          label.c_str(), Name(d), interior, leaky);
      EXPECT_GT(interior, 1000u);
      EXPECT_EQ(leaky, 0u) << label << " (" << Name(d) << ")";
      shots.push_back({label + " coverage", std::move(r)});
      rt::RenderResult s = RenderOn(d, Flatten(scene_at(offset, true), o), label + "_lit");
      ExpectFinite(s, label + " lit, smooth " + Name(d));
      shots.push_back({label + " lit", std::move(s)});
    }
    return shots;
  };
  RUN_BOTH_DEVICES(run);
}

}  // namespace
