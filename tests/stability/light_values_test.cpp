// Light values from 1e-6 to 1e9: the radiance is linear in them to within float rounding.
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

TEST(StabilityLightValues, RadianceIsLinearFrom1em6To1e9) {
  auto scene_with = [&](double k) {
    rt::SceneDesc s = GlossyScene(0.1);
    s.background = {};
    s.ambient = s.ambient * k;
    for (auto& l : s.point_lights)
      l.intensity = F3(Vec3d{l.intensity.x * k, l.intensity.y * k, l.intensity.z * k});
    for (auto& l : s.area_lights)
      l.radiance = F3(Vec3d{l.radiance.x * k, l.radiance.y * k, l.radiance.z * k});
    return s;
  };
  const double scales[] = {1e-6, 1e-3, 1, 1e3, 1e6, 1e9};
  auto run = [&](Dev d) {
    Shots shots;
    rt::RenderOptions o;
    o.spp = 6;
    rt::RenderResult ref = RenderOn(d, Flatten(scene_with(1), o), "light_1");
    std::vector<float> base = ref.rgb();
    for (double k : scales) {
      char label[32];
      std::snprintf(label, sizeof label, "light x%g", k);
      rt::RenderResult r = RenderOn(d, Flatten(scene_with(k), o), label);
      ExpectFinite(r, std::string(label) + " " + Name(d));
      std::vector<float> rgb = r.rgb();
      size_t off = 0;
      double worst = 0;
      for (size_t i = 0; i < rgb.size(); ++i) {
        if (base[i] == 0) {
          off += rgb[i] != 0;
          continue;
        }
        double rel = std::fabs(rgb[i] / k / base[i] - 1);
        worst = std::max(worst, rel);
        off += rel > 1e-5;
      }
      std::printf(
          "[ light ] %-12s %-3s max |pixel / I - reference| %.2e relative, %zu values "
          "off\n",
          label, Name(d), worst, off);
      EXPECT_EQ(off, 0u) << label << " (" << Name(d) << "), worst " << worst;
      shots.push_back({label, std::move(r)});
    }
    return shots;
  };
  RUN_BOTH_DEVICES(run);
}

}  // namespace
