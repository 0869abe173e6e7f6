// The course's path-traced Cornell box (hw6/pathTracing, cornellbox_jaroslav_path_diffuse)
// at a small size, for tests of what is built on the path tracer: stop rules, compare.
#pragma once

#include <string>

#include "prepare/flat_scene.h"
#include "scene/scene.h"

namespace rt::test {

// Cameras of that file: 0 next-event estimation (uniform sampling), 4 neither (uniform).
constexpr int kPathNextEventCamera = 0;
constexpr int kPathUniformCamera = 4;

// Loads the scene with every camera `size` pixels square; returns false (with *why) when
// ../shared/scenes is not there.
bool load_path_scene(int size, SceneDesc* scene, std::string* why);

// The scene flattened for `camera` with `spp` samples and `seed`.
FlatScene flatten_path_camera(const SceneDesc& scene, int camera, int spp, uint32_t seed);

}  // namespace rt::test
