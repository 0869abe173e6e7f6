// Small, deliberate errors planted in a scene to measure how often `compare` notices
// them: the kinds of bias a kernel bug would cause.
#pragma once

#include <string>

#include "scene/scene.h"

namespace cmp {

struct PlantedBias {
  enum Kind { kNone, kLight, kRoughness, kShift };
  Kind kind = kNone;
  double amount = 0;

  // "none", "light:F" (the first area light, else the first point light, F times as
  // bright), "roughness:F" (every rough material's roughness times F), "shift:P" (the
  // camera's image window moved P pixels to the right). Throws std::invalid_argument.
  static PlantedBias parse(const std::string& spec);
  std::string label() const;
};

// Applies the bias to camera `camera` of `scene` (whose width is already final). Throws
// std::invalid_argument when the scene has nothing to bias (no light, no rough material).
void apply_bias(const PlantedBias& b, int camera, rt::SceneDesc* scene);

}  // namespace cmp
