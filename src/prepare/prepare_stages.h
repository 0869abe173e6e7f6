// The stages the two steps of flat_scene.h run, each in a file of its own. They fill
// FlatScene's arrays from the scene and call nothing of the preparation back.
#pragma once

#include <vector>

#include "flat_scene.h"

namespace rt {

// prepare_scene's stages.
// Appends the scene's images to flat.texels and a descriptor per TextureMap to
// flat.textures (flat_textures.cpp).
void flatten_textures(const SceneDesc& scene, FlatScene& flat);
// The environment light's map and its sampling distributions, and its power
// (flat_environment.cpp).
void flatten_environment(const SceneDesc& scene, FlatScene& flat);

// prepare_camera's stages, on flat.lights as frame_lights (world_frame.h) made them.
// Appends a light for every emitting object (LightMesh, LightSphere) and fills
// flat.instance_lights and flat.light_cdf (flat_object_lights.cpp). instance_of_object[i]
// is object i's index in flat.instances (-1: not placed, an empty mesh).
void append_object_lights(const SceneDesc& scene, const std::vector<int>& instance_of_object,
                          FlatScene& flat);
// Numbers the lights that draw random numbers (every type but point, directional and spot
// lights) in their order in `lights` (flat_object_lights.cpp).
void number_lights(PageAlignedVector<Light>& lights);
// Gives the environment's entry of flat.lights the map's size and power, and sets the
// header's index to it (flat_environment.cpp).
void place_environment(const SceneDesc& scene, FlatScene& flat);

}  // namespace rt
