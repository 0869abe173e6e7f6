// The camera far from the origin: the stage moved 1e5 and 1e6 away must give the same first
// hits as at the origin.
//
// Each case renders on the CPU reference, checks its property, then renders the same scenes
// on the OpenCL kernel when there is one and requires the devices to agree
// (tests/support/stability_harness.h).
#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <string>
#include <utility>

#include "exact.h"
#include "support/stability_harness.h"

namespace {

using namespace stab;

TEST(StabilityCamera, FarFromTheOriginTheCameraShootsTheSameRays) {
  rt::SceneDesc base = Stage();
  auto run = [&](Dev d) {
    Shots shots;
    rt::RenderOptions o;
    o.spp = 1;
    rt::RenderResult a = RenderOn(d, Flatten(base, o), "camera_origin");
    rt::MomentImage ma = Moments(a, "origin");
    for (double dist : {1e5, 1e6}) {
      char label[40];
      std::snprintf(label, sizeof label, "camera at %g", dist);
      Vec3d t = V(dist / std::sqrt(3.0), -dist / std::sqrt(3.0), dist / std::sqrt(3.0));
      rt::RenderResult b = RenderOn(d, Flatten(MapScene(base, 1, t), o), label);
      ExpectFinite(b, std::string(label) + " " + Name(d));
      rt::MomentImage mb = Moments(b, "far");
      // Positions far out carry errors of a few ulps of `dist`: 16 of them over the
      // nearest hit (6 units away) is the distance tolerance, 4 over the smallest sphere's
      // radius (0.3; its normal comes from the object-space hit) the normal's. The geometry
      // itself moves by half an ulp, 2% (1e5) / 15% (1e6) of a pixel's footprint, so that
      // share of the pixels next to an edge may see the other primitive: 2% / 8%.
      double ulp = std::nextafter(static_cast<float>(dist), 1e30f) - static_cast<float>(dist);
      cmp::ExactOptions eo;
      eo.t_tol = 16 * ulp / 6;
      eo.n_tol = 4 * ulp / 0.3;
      eo.max_fraction = dist < 5e5 ? 0.02 : 0.08;
      cmp::ExactReport rep = cmp::exact_test(ma, mb, eo);
      std::printf(
          "[ camera ] %-14s %-3s exact %s: %zu of %zu pixels differ (%zu hit/miss, %zu "
          "other primitive, %zu distance, %zu normal), max relative t difference "
          "%.2e, max normal difference %.2e\n",
          label, Name(d), rep.pass ? "PASS" : "FAIL", rep.failing, rep.pixels, rep.hit_mismatch,
          rep.id_mismatch, rep.t_over, rep.n_over, rep.max_t_rel, rep.max_n);
      EXPECT_TRUE(rep.pass) << label << " (" << Name(d) << "): " << rep.failing << " of "
                            << rep.pixels << " first hits differ";
      shots.push_back({label, std::move(b)});
    }
    shots.push_back({"camera at origin", std::move(a)});
    return shots;
  };
  RUN_BOTH_DEVICES(run);
}

}  // namespace
