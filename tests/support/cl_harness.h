// The OpenCL host tests' shared pieces (tests/device/cl/): the one OpenCL device of the test
// binary, a course scene loaded at a given image size, renders on either device, and the
// byte comparison of two renders. Tests that need a device skip when none is usable, and
// tests that need a course scene skip when ../shared is not beside the clone.
#pragma once

#include <gtest/gtest.h>

#include <filesystem>
#include <memory>
#include <string>

#include "device/device.h"
#include "integrator/render.h"
#include "prepare/flat_scene.h"
#include "scene/scene.h"

namespace rt::test {

// The course's scenes (../shared/scenes).
extern const std::string kCourseScenes;

// One device for the whole binary (building programs is the slow part); no disk cache so
// each run exercises the compiler. Null, with the reason in *why, when none is usable.
RenderDevice* shared_cl(std::string* why, bool generic = false);

// A new directory under the system's temporary directory, named after `tag`.
std::filesystem::path make_temp_dir(const std::string& tag);

struct Loaded {
  SceneDesc scene;
  FlatScene flat;
  KernelConfig kernel;
};

// Camera 0 of the course scene `rel` (relative to kCourseScenes) at `spp` samples (0: the
// scene's), `size` x `size` pixels over the same film, BVH nodes `bvh_width` wide (0: the
// build's).
Loaded load(const std::string& rel, int spp, int size, int bvh_width = 0);

// Renders on the shared device with the specialized or the generic kernel.
RenderResult render_on_cl(const FlatScene& flat, bool generic, DeviceLoadInfo* info = nullptr,
                          const KernelConfig& kernel = {});

// A new device with the disk cache on, as the executable opens it.
std::unique_ptr<RenderDevice> open_cl(const std::string& selector, std::string* why);

// Whether two renders have the same per-pixel sums, byte for byte.
bool identical(const RenderResult& a, const RenderResult& b);

}  // namespace rt::test

#define REQUIRE_DEVICE(r)                           \
  std::string why_;                                 \
  rt::RenderDevice* r = rt::test::shared_cl(&why_); \
  if (!r) GTEST_SKIP() << "no OpenCL device: " << why_

// The course's scenes live beside the clone (../shared); a clone elsewhere skips the tests
// that render them instead of failing on a missing file.
#define SKIP_WITHOUT_SCENE(rel)                                  \
  if (!std::filesystem::exists(rt::test::kCourseScenes + (rel))) \
  GTEST_SKIP() << rt::test::kCourseScenes + (rel) << " is not here (the course's scenes, ../shared)"
