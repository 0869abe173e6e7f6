// Glossy roughness at its extremes: zero roughness is bit-identical to the mirror, huge
// roughness stays finite.
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

// Roughness 0 is the ideal mirror: with the glossy code compiled in (the feature bit forced
// on, as when another material of the scene is rough) the image is bit-identical.
TEST(StabilityRoughness, ZeroRoughnessIsBitIdenticalToTheMirror) {
  rt::SceneDesc scene = GlossyScene(0);
  auto run = [&](Dev d) {
    Shots shots;
    rt::RenderOptions o;
    o.spp = 4;
    rt::FlatScene plain = Flatten(scene, o);
    EXPECT_FALSE(plain.header.features & RT_FEATURE_ROUGHNESS);
    rt::FlatScene forced = plain;
    forced.header.features |= RT_FEATURE_ROUGHNESS;
    rt::RenderResult a = RenderOn(d, plain, "roughness_off");
    rt::RenderResult b = RenderOn(d, forced, "roughness_0");
    ExpectFinite(a, std::string("mirror ") + Name(d));
    ExpectFinite(b, std::string("roughness 0 ") + Name(d));
    EXPECT_TRUE(BitIdentical(a, b)) << Name(d);
    shots.push_back({"roughness feature off", std::move(a)});
    shots.push_back({"roughness 0", std::move(b)});
    return shots;
  };
  RUN_BOTH_DEVICES(run);
}

// Roughness 1e6 (the lobe's square is a million times wider than the sphere of
// directions: directions are close to uniform in the tangent plane) and 1e20 (the
// perturbation's squared length overflows float): finite.
TEST(StabilityRoughness, HugeRoughnessStaysFinite) {
  auto run = [&](Dev d) {
    Shots shots;
    for (double rough : {1e6, 1e20}) {
      rt::RenderOptions o;
      o.spp = 6;
      std::string label = rough == 1e6 ? "roughness 1e6" : "roughness 1e20";
      rt::RenderResult r = RenderOn(d, Flatten(GlossyScene(rough), o), label);
      std::printf("[ roughness ] %-15s %-3s %llu non-finite samples of %llu\n", label.c_str(),
                  Name(d), static_cast<unsigned long long>(r.nonfinite()),
                  static_cast<unsigned long long>(r.samples));
      ExpectFinite(r, label + " " + Name(d));
      shots.push_back({label, std::move(r)});
    }
    return shots;
  };
  RUN_BOTH_DEVICES(run);
}

}  // namespace
