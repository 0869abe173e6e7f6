// Grazing rays: a diffuse plane 1e6 wide seen and lit at grazing angles must show the
// analytic Blinn-Phong value everywhere, with no shadow acne.
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

TEST(StabilityGrazing, HugePlaneMatchesAnalyticBlinnPhong) {
  const int w = 48, h = 32;
  const double kd = 0.8, half = 5e5;
  const Vec3d light = V(0, 20, -200), intensity = Gray(1e8);
  const double position_error = 8 * (std::nextafter(float(half), 1e30f) - float(half));
  const Vec3d eye = V(0.3, 1, 0);
  auto look = [&](double pitch) {
    return eye + V(0.2 * std::sin(pitch), -std::sin(pitch), -std::cos(pitch));
  };
  // The scene as described, or turned as a whole by 20 degrees about a skew axis, so the
  // plane is no longer axis-aligned and its hit points are rounded off the plane too.
  auto scene_turned = [&](const Mat4& turn) {
    Builder b;
    int mat = b.material(Plain(Gray(kd)));
    b.quad(turn.point(V(-half, 0, -half)), turn.point(V(-half, 0, half)),
           turn.point(V(half, 0, half)), turn.point(V(half, 0, -half)), mat);
    b.point_light(turn.point(light), intensity);
    b.camera(turn.point(eye), turn.point(look(2.0 * M_PI / 180)), turn.vector(V(0, 1, 0)), 0.12,
             0.08, 1, w, h);
    b.camera(turn.point(eye), turn.point(look(1e-4)), turn.vector(V(0, 1, 0)), 0.12, 1.2e-4, 1, w,
             h);
    return b.scene();
  };
  const rt::SceneDesc plain = scene_turned(Mat4()),
                      turned = scene_turned(Mat4::rotation(20, V(1, 0.3, 0.2)));

  auto run = [&](Dev d) {
    Shots shots;
    for (int cam = 0; cam < 2; ++cam)
      for (int variant = 0; variant < 4; ++variant) {
        bool use_eps = (variant & 1) == 0, turn = variant >= 2;
        // The analytic side works in the unturned frame (t is the same in both).
        const rt::CameraDesc& c = plain.cameras[cam];
        Vec3d cw = rt::normalize(c.gaze) * -1.0, cu = rt::normalize(rt::cross(c.up, cw));
        Vec3d cv = rt::cross(cw, cu);
        rt::RenderOptions o;
        o.spp = 1;
        o.use_scene_epsilon = use_eps;
        // The huge plane's scale needs the scale-aware offset beside the scene's epsilon;
        // the course's offset (the default) leaves acne here, as the course's renderer would.
        o.robust_offset = true;
        std::string label = std::string(cam == 0 ? "grazing view" : "grazing horizon") +
                            (use_eps ? " eps=scene" : " eps=none") + (turn ? " turned" : "");
        rt::RenderResult r = RenderOn(d, Flatten(turn ? turned : plain, o, cam), label);
        ExpectFinite(r, label + " " + Name(d));
        std::vector<float> rgb = r.rgb();
        size_t hits = 0, acne = 0, bright = 0, slipped = 0;
        double worst_dark = 0, worst_bright = 0, min_cos = 1, max_t = 0;
        for (int y = 0; y < h; ++y)
          for (int x = 0; x < w; ++x) {
            size_t i = static_cast<size_t>(y) * w + x;
            Vec3d film = cw * -c.near_distance +
                         cu * (c.left + (c.right - c.left) * (x + 0.5) / w) +
                         cv * (c.top - (c.top - c.bottom) * (y + 0.5) / h);
            Vec3d dir = rt::normalize(film);
            double t_exact = dir.y < 0 ? -eye.y / dir.y : INFINITY;
            Vec3d pe = eye + dir * t_exact;
            bool inside =
                std::isfinite(t_exact) && std::fabs(pe.x) < half && std::fabs(pe.z) < half;
            const PrimaryInfo& pi = r.primary[i];
            if (pi.instance < 0) {
              // A miss is right beyond the plane's edge or above the horizon; the last 0.1%
              // of the plane is left out (float and exact rays straddle the edge there).
              if (inside && std::max(std::fabs(pe.x), std::fabs(pe.z)) < 0.999 * half) ++slipped;
              continue;
            }
            ++hits;
            // The renderer's hit along the exact direction, put back onto the plane.
            Vec3d p = eye + dir * static_cast<double>(pi.t);
            p.y = 0;
            Vec3d to = light - p;
            double d2 = rt::dot(to, to), dist = std::sqrt(d2), cos_t = to.y / dist;
            min_cos = std::min(min_cos, std::fabs(dir.y));
            max_t = std::max(max_t, static_cast<double>(pi.t));
            double expect = kd * cos_t * intensity.x / d2;
            double rel = (rgb[i * 3] - expect) / expect;
            // Turned, the camera ray's own rounding (~1e-7 rad) moves grazing hits along the
            // plane by 1e-7 t / sin(grazing): that much more slack in the position.
            double slack = turn ? 2e-7 * pi.t / std::fabs(dir.y) : 0.0;
            double tol = 1e-4 + 3 * (position_error + slack) / dist;
            acne += rel < -tol;
            bright += rel > tol;
            worst_dark = std::min(worst_dark, rel / tol);
            worst_bright = std::max(worst_bright, rel / tol);
          }
        std::printf(
            "[ grazing ] %-33s %-3s %4zu hits (to t = %.3g, grazing down to %.2g "
            "rad), %zu darker and %zu brighter than analytic beyond tolerance "
            "(extremes %+.2f, %+.2f of it), %zu slipped through\n",
            label.c_str(), Name(d), hits, max_t, min_cos, acne, bright, worst_dark, worst_bright,
            slipped);
        EXPECT_GT(hits, static_cast<size_t>(w * h / 3)) << label;
        EXPECT_EQ(acne, 0u) << label << " (" << Name(d) << "): shadow acne";
        EXPECT_EQ(bright, 0u) << label << " (" << Name(d) << ")";
        EXPECT_EQ(slipped, 0u) << label << " (" << Name(d) << "): rays through the plane";
        shots.push_back({label, std::move(r)});
      }
    return shots;
  };
  RUN_BOTH_DEVICES(run);
}

}  // namespace
