// Extreme indices of refraction (1, just above 1, huge) and total internal reflection: glass
// of index 1 changes nothing, a huge index behaves like a mirror, and no energy is created.
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

rt::SceneDesc GlassScene(const Material* glass, bool back_wall) {
  Builder b;
  b.scene().max_depth = 8;
  int m[2] = {b.material(Plain(V(0.9, 0.8, 0.3))), b.material(Plain(V(0.2, 0.5, 0.9)))};
  for (int i = 0; i < 6; ++i)
    for (int j = 0; j < 6; ++j) {
      double x = -3 + i, y = -3 + j;
      b.quad(V(x, y, -3), V(x + 1, y, -3), V(x + 1, y + 1, -3), V(x, y + 1, -3), m[(i + j) % 2]);
    }
  b.point_light(V(0.5, 0.8, -1.6), Gray(600));
  if (back_wall) {
    // Something for a mirror-like sphere to reflect: a lit wall behind the camera.
    int back = b.material(Plain(V(0.8, 0.3, 0.3)));
    b.quad(V(-8, -8, 9), V(-8, 8, 9), V(8, 8, 9), V(8, -8, 9), back);
    b.quad(V(-8, -2, 9), V(8, -2, 9), V(8, -2, -3), V(-8, -2, -3), m[0]);  // A floor.
    b.point_light(V(1, 3, 7), Gray(2000));
  }
  if (glass) b.sphere(V(0, 0, 0), 1, b.material(*glass));
  b.camera(V(0, 0, 5), V(0, 0, 0), V(0, 1, 0), 0.5, 0.5, 1, 40, 40);
  return b.scene();
}

struct Diff {
  double mean_rel = 0;  // sum |a - b| / sum |a|
  double max_rel = 0;   // max |a - b| / (image max)
  size_t over = 0;      // values differing by more than `tol` of the image max
};

Diff ImageDiff(const rt::RenderResult& a, const rt::RenderResult& b, double tol) {
  std::vector<float> ra = a.rgb(), rb = b.rgb();
  double vmax = 0, num = 0, den = 0;
  for (float v : ra) vmax = std::max(vmax, std::fabs(static_cast<double>(v)));
  Diff d;
  for (size_t i = 0; i < ra.size(); ++i) {
    double e = std::fabs(static_cast<double>(ra[i]) - rb[i]);
    num += e;
    den += std::fabs(ra[i]);
    d.max_rel = std::max(d.max_rel, e / vmax);
    d.over += e > tol * vmax;
  }
  d.mean_rel = num / den;
  return d;
}

// The wall without the sphere and with a glass sphere of index `ior` (24 spp, equal seeds,
// so the same camera rays), both checked finite.
std::pair<rt::RenderResult, rt::RenderResult> RenderWithoutAndWith(Dev d, double ior,
                                                                   const std::string& name) {
  const Material glass = Dielectric(ior);
  rt::RenderOptions o;
  o.spp = 24;
  rt::RenderResult without = RenderOn(d, Flatten(GlassScene(nullptr, false), o), "ior_none");
  rt::RenderResult with = RenderOn(d, Flatten(GlassScene(&glass, false), o), "ior_" + name);
  ExpectFinite(without, std::string("no sphere ") + Name(d));
  ExpectFinite(with, "IOR " + name + " " + Name(d));
  return {std::move(without), std::move(with)};
}

// IOR 1: no visible interface. Same seed, so the same camera rays: the image must equal the
// one without the sphere (compare tool, Welch per pixel), and per pixel to 1e-3 of the
// image maximum except where a ray passes within the spawn offset of a chequer edge
// (allowed: 0.5% of the values).
TEST(StabilityRefraction, IndexOneLeavesTheImageUnchanged) {
  auto run = [&](Dev d) {
    Shots shots;
    auto [a, b] = RenderWithoutAndWith(d, 1.0, "1");
    cmp::Verdict v = WelchVerdict(a, b);
    Diff df = ImageDiff(a, b, 1e-3);
    std::printf("[ ior 1 ] %-3s %s; mean |diff| %.2e, max %.2e of max, %zu values > 1e-3;%s\n",
                Name(d), Describe(v).c_str(), df.mean_rel, df.max_rel, df.over,
                g_last_failing_cells.c_str());
    EXPECT_TRUE(v.pass) << Name(d) << ": " << Describe(v);
    EXPECT_LE(df.over, a.rgb().size() / 200) << Name(d);
    EXPECT_LE(df.mean_rel, 1e-4) << Name(d);
    shots.push_back({"ior none", std::move(a)});
    shots.push_back({"ior 1", std::move(b)});
    return shots;
  };
  RUN_BOTH_DEVICES(run);
}

// IOR 1.0001: Fresnel reflection of 2.5e-9 at normal incidence, deflection of 1e-4 rad
// times tan(incidence); only a ring at the silhouette, where Fresnel reflection goes to 1,
// may differ visibly.
TEST(StabilityRefraction, IndexJustAboveOneDiffersByATinyAmount) {
  auto run = [&](Dev d) {
    Shots shots;
    auto [a, b] = RenderWithoutAndWith(d, 1.0001, "1.0001");
    Diff df = ImageDiff(a, b, 1e-2);
    std::printf("[ ior 1.0001 ] %-3s mean |diff| %.2e, max %.2e of max, %zu values > 1e-2\n",
                Name(d), df.mean_rel, df.max_rel, df.over);
    EXPECT_LE(df.mean_rel, 2e-3) << Name(d);
    EXPECT_LE(df.over, a.rgb().size() / 100) << Name(d);
    shots.push_back({"ior 1.0001", std::move(b)});
    return shots;
  };
  RUN_BOTH_DEVICES(run);
}

// IOR 1e4: the sphere must act as a mirror. Its reflectance is >= 0.9996 except in a
// band of grazing incidence cos < ~10 / IOR, where the p-polarised reflectance dips to 0
// at Brewster's angle (cos = 1e-4): physics, not error. Compared with the same sphere as a
// perfect mirror: every value within 1e-3 of itself + 5e-4 of the image maximum (light
// leaving the sphere's inside), except on pixels whose footprint reaches the grazing band
// (impact parameter > 0.995 of the radius, cos < 0.1), which may only be darker, by at
// most 5% (measured: 0.5% at 8 spp).
TEST(StabilityRefraction, HugeIndexBehavesLikeAMirror) {
  Material glass = Dielectric(1e4), mirror = Mirror(Gray(1));
  rt::SceneDesc a_scene = GlassScene(&mirror, true), b_scene = GlassScene(&glass, true);
  const rt::CameraDesc& c = a_scene.cameras[0];
  // Distance of the sphere's centre (the origin) from the camera ray through film point
  // (fx, fy), in radii.
  auto impact = [&](double fx, double fy) {
    Vec3d dir = rt::normalize(V(c.left + (c.right - c.left) * fx / c.width,
                                c.top - (c.top - c.bottom) * fy / c.height, -c.near_distance));
    return rt::length(rt::cross(c.position * -1.0, dir));
  };
  auto run = [&](Dev d) {
    Shots shots;
    rt::RenderOptions o;
    o.spp = 8;
    rt::RenderResult a = RenderOn(d, Flatten(a_scene, o), "ior_mirror");
    rt::RenderResult b = RenderOn(d, Flatten(b_scene, o), "ior_1e4");
    ExpectFinite(a, std::string("mirror sphere ") + Name(d));
    ExpectFinite(b, std::string("IOR 1e4 ") + Name(d));
    std::vector<float> ra = a.rgb(), rb = b.rgb();
    double vmax = 0;
    for (float v : ra) vmax = std::max(vmax, static_cast<double>(v));
    size_t over = 0, grazing_values = 0, grazing_bad = 0;
    double worst = 0, worst_grazing = 0;
    for (int y = 0; y < c.height; ++y)
      for (int x = 0; x < c.width; ++x) {
        double lo = 2, hi = 0;
        for (int k = 0; k < 4; ++k) {
          double bb = impact(x + (k & 1), y + (k >> 1));
          lo = std::min(lo, bb);
          hi = std::max(hi, bb);
        }
        bool grazing = lo < 1 && hi > 0.995;
        for (int ch = 0; ch < 3; ++ch) {
          size_t i = (static_cast<size_t>(y) * c.width + x) * 3 + ch;
          // Up to 4e-4 of the light inside may leave through the surface: 5e-4 of the
          // image's maximum on top of the relative tolerance.
          double rel = (static_cast<double>(rb[i]) - ra[i]) / (std::fabs(ra[i]) + 0.5 * vmax);
          if (grazing) {
            double g = (static_cast<double>(rb[i]) - ra[i]) / (std::fabs(ra[i]) + 1e-3);
            ++grazing_values;
            grazing_bad += rel > 1e-3 || g < -0.05;
            worst_grazing = std::min(worst_grazing, g);
          } else {
            over += std::fabs(rel) > 1e-3;
            worst = std::max(worst, std::fabs(rel));
          }
        }
      }
    std::printf(
        "[ ior 1e4 ] %-3s %zu values differ from the mirror by > 1e-3 relative (worst "
        "%.2e); grazing band: %zu values, %zu outside [-5%%, +1e-3] (darkest %.3f)\n",
        Name(d), over, worst, grazing_values, grazing_bad, worst_grazing);
    EXPECT_EQ(over, 0u) << Name(d);
    EXPECT_EQ(grazing_bad, 0u) << Name(d);
    shots.push_back({"ior mirror", std::move(a)});
    shots.push_back({"ior 1e4", std::move(b)});
    return shots;
  };
  RUN_BOTH_DEVICES(run);
}

TEST(StabilityRefraction, TotalInternalReflectionCreatesNoEnergy) {
  const double L = 100;
  Builder b;
  b.scene().background = Gray(L);
  b.scene().max_depth = 12;
  b.box(V(-2, -0.5, -2), V(2, 0.5, 2), b.material(Dielectric(1.5)));
  b.camera(V(0.3, 3, 4.5), V(0, 0, 0), V(0, 1, 0), 0.6, 0.6, 1, 32, 32);
  b.camera(V(0.1, 0.05, -0.2), V(1, 0.2, 0.7), V(0, 1, 0), 0.8, 0.8, 1, 32, 32);
  b.camera(V(-1.5, 0.2, 1.2), V(0, -0.1, 0), V(0, 1, 0), 1.2, 1.2, 1, 32, 32);
  // Absorbing glass too: still never more than L.
  Builder b2 = b;
  b2.scene().materials[0].absorption = F3(V(0.3, 0.1, 0.02));
  auto run = [&](Dev d) {
    Shots shots;
    for (int absorbing = 0; absorbing < 2; ++absorbing)
      for (int cam = 0; cam < 3; ++cam) {
        rt::RenderOptions o;
        o.spp = 6;
        o.background_on_secondary_miss = true;
        std::string label =
            std::string("tir camera ") + std::to_string(cam) + (absorbing ? " absorbing" : "");
        rt::RenderResult r =
            RenderOn(d, Flatten(absorbing ? b2.scene() : b.scene(), o, cam), label);
        ExpectFinite(r, label + " " + Name(d));
        std::vector<float> rgb = r.rgb();
        size_t over = 0, trapped = 0;
        double vmax = 0, mean = 0;
        for (size_t i = 0; i < rgb.size(); ++i) {
          vmax = std::max(vmax, static_cast<double>(rgb[i]));
          over += rgb[i] > L * (1 + 1e-5);
          mean += rgb[i];
        }
        for (size_t i = 0; i < rgb.size() / 3; ++i) trapped += Luminance(rgb, i) < 0.5 * L;
        std::printf("[ tir ] %-28s %-3s max %.6g (L = %g), mean %.4g, %zu pixels below L/2\n",
                    label.c_str(), Name(d), vmax, L, mean / rgb.size(), trapped);
        EXPECT_EQ(over, 0u) << label << " (" << Name(d) << "): energy created, max " << vmax;
        if (cam == 1) {
          EXPECT_GT(trapped, 0u) << label << ": no ray was trapped";
        }
        shots.push_back({label, std::move(r)});
      }
    return shots;
  };
  RUN_BOTH_DEVICES(run);
}

}  // namespace
