// The thin lens at its extremes: zero aperture is bit-identical to the pinhole camera, huge
// apertures and focus distances stay finite.
//
// Each case renders on the CPU reference, checks its property, then renders the same scenes
// on the OpenCL kernel when there is one and requires the devices to agree
// (tests/support/stability_harness.h).
#include <gtest/gtest.h>

#include <string>
#include <utility>

#include "support/stability_harness.h"

namespace {

using namespace stab;

rt::SceneDesc LensScene(double aperture, double focus) {
  rt::SceneDesc s = GlossyScene(0);
  s.cameras[0].aperture = aperture;
  s.cameras[0].focus_distance = focus;
  return s;
}

// Aperture 0 is the pinhole: bit-identical with the depth-of-field code compiled in (the
// lens sample is drawn but not used), for both lens shapes.
TEST(StabilityLens, ZeroApertureIsBitIdenticalToThePinhole) {
  auto run = [&](Dev d) {
    Shots shots;
    for (int lens : {RT_LENS_SQUARE, RT_LENS_DISK}) {
      rt::RenderOptions o;
      o.spp = 4;
      o.lens = lens;
      rt::FlatScene pinhole = Flatten(LensScene(0, 5), o);
      EXPECT_FALSE(pinhole.header.features & RT_FEATURE_DEPTH_OF_FIELD);
      rt::FlatScene forced = pinhole;
      forced.header.features |= RT_FEATURE_DEPTH_OF_FIELD;
      std::string label = lens == RT_LENS_DISK ? "aperture 0 disk" : "aperture 0 square";
      rt::RenderResult a = RenderOn(d, pinhole, "pinhole");
      rt::RenderResult b = RenderOn(d, forced, label);
      ExpectFinite(b, label + " " + Name(d));
      EXPECT_TRUE(BitIdentical(a, b)) << label << " (" << Name(d) << ")";
      shots.push_back({label, std::move(b)});
    }
    return shots;
  };
  RUN_BOTH_DEVICES(run);
}

// Aperture 1e6 with the focal plane at 5; focus distances 1e-6 and 1e9 with aperture 0.3:
// every sample finite. (With focus 1e-6 the rays leave the lens almost parallel to it.)
TEST(StabilityLens, ExtremeApertureAndFocusStayFinite) {
  struct Case {
    const char* label;
    double aperture, focus;
  };
  const Case cases[] = {{"aperture 1e6", 1e6, 5},
                        {"focus 1e-6", 0.3, 1e-6},
                        {"focus 1e9", 0.3, 1e9},
                        {"aperture 1e6 focus 1e-6", 1e6, 1e-6},
                        {"aperture 1e-30", 1e-30, 5}};
  auto run = [&](Dev d) {
    Shots shots;
    for (const Case& c : cases)
      for (int lens : {RT_LENS_SQUARE, RT_LENS_DISK}) {
        rt::RenderOptions o;
        o.spp = 4;
        o.lens = lens;
        std::string label = std::string(c.label) + (lens == RT_LENS_DISK ? " disk" : " square");
        rt::RenderResult r = RenderOn(d, Flatten(LensScene(c.aperture, c.focus), o), label);
        ExpectFinite(r, label + " " + Name(d));
        // The disk lens goes through sin/cos: with an aperture of 1e6 their last bits decide.
        shots.push_back({label, std::move(r), lens == RT_LENS_DISK && c.aperture > 1});
      }
    return shots;
  };
  RUN_BOTH_DEVICES(run);
}

}  // namespace
