// The harness of the numerical-stability tests (tests/stability/): every case renders on the
// CPU reference first and checks its property there; then, when an OpenCL device exists, it
// renders the same flattened scenes with the kernel, checks the same property, and requires
// the kernel to agree with the reference (ExpectDevicesAgree: same seed, so the per-pixel
// sums must match). Without a device the CL half is skipped with the reason. On every render
// of both devices no sample may be NaN or infinite (RenderResult::nonfinite() counts the
// samples the film left out).
//
// Set RT_STAB_DUMP=<dir> to write every CPU render as a PNG for inspection.
#pragma once

#include <gtest/gtest.h>

#include <string>
#include <vector>

#include "family.h"
#include "io/moments.h"
#include "support/device_harness.h"
#include "support/stability_scenes.h"

namespace stab {

using Dev = rt::Device;  // kCpu or kOpenCl, through the shared device harness.
const char* Name(Dev d);

// Runs the CL half of a test only where a device exists: the CPU half has already run.
#define REQUIRE_CL()                                                           \
  do {                                                                         \
    std::string why_;                                                          \
    if (!rt::test::shared_device(Dev::kOpenCl, &why_))                         \
      GTEST_SKIP() << "CPU half passed or failed above; no OpenCL device for " \
                      "the CL half: "                                          \
                   << why_;                                                    \
  } while (0)

// Flattens `s` and sets its camera number `camera`.
rt::FlatScene Flatten(const rt::SceneDesc& s, const rt::RenderOptions& o, int camera = 0);

// Renders on device `d`; a CPU render with a label is also dumped under RT_STAB_DUMP.
rt::RenderResult RenderOn(Dev d, const rt::FlatScene& f, const std::string& label = "");

// A render with its name, so the two devices' lists can be matched. `statistical` marks a
// render where the devices cannot agree sample by sample (see ExpectDevicesAgree).
struct Shot {
  std::string label;
  rt::RenderResult r;
  bool statistical = false;
};
using Shots = std::vector<Shot>;

// No sample of the render was NaN or infinite, and every reconstructed value is finite.
void ExpectFinite(const rt::RenderResult& r, const std::string& label);

rt::MomentImage Moments(const rt::RenderResult& r, const std::string& device);

// One line: pass or fail, the counts of tests, equal cells, failures and the smallest p.
std::string Describe(const cmp::Verdict& v);

// The compare tool's Welch verdict (per pixel, family-wise alpha 1e-3) on two renders of the
// same image. Samples must be independent within a pixel: use a non-square spp.
cmp::Verdict WelchVerdict(const rt::MomentImage& a, const rt::MomentImage& b, int tile = 1);
cmp::Verdict WelchVerdict(const rt::RenderResult& a, const rt::RenderResult& b, int tile = 1);
// The first few failing cells of the last WelchVerdict, " (x,y)c:diff", for messages.
extern std::string g_last_failing_cells;

// CL against CPU on equal seeds (the rules are stated at the definition).
void ExpectDevicesAgree(const Shots& cpu, const Shots& cl);

// Runs `run` on the CPU, then on the kernel when there is one, and compares the two.
// `run` checks the case's own property on each device's renders (labels carry the device).
#define RUN_BOTH_DEVICES(run)      \
  do {                             \
    Shots cpu_ = run(Dev::kCpu);   \
    REQUIRE_CL();                  \
    Shots cl_ = run(Dev::kOpenCl); \
    ExpectDevicesAgree(cpu_, cl_); \
  } while (0)

// The mean of pixel i's three channels.
double Luminance(const std::vector<float>& rgb, size_t i);

// The same per-pixel sums, bit for bit.
bool BitIdentical(const rt::RenderResult& a, const rt::RenderResult& b);

}  // namespace stab
