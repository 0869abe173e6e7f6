// The frame the devices work in. The file's numbers are kept in double on the host; float
// only holds positions well near its origin (ulp(1e5) = 0.008), so the world is moved into
// the camera's frame (the camera at the origin) before anything becomes float: large-world
// coordinates, as game engines call it. Each mesh keeps its vertices relative to a point of
// its own (its frame origin) so its bottom-level BVH serves every camera unchanged; a new
// camera rebuilds only the top level, the instances' transforms and the lights.
#pragma once

#include "flat_scene.h"

namespace rt {

// The point a mesh's vertices are stored relative to: the centre of its bounds, rounded to
// a multiple of the power of two at or above its extent. A mesh lying across the world's
// origin keeps the origin (its float vertices are then exactly the file's), and meshes of
// a similar size next to each other tend to share a frame (their shared edges stay
// watertight, as both are intersected with the same ray).
Vec3d mesh_frame_origin(const MeshDesc& mesh);

// The object's transform from its mesh's frame (`mesh_origin`, zero for spheres) to the
// world frame whose origin is the world point `world_origin`, composed in double.
Mat4 object_to_frame(const ObjectDesc& object, Vec3d mesh_origin, Vec3d world_origin);

// Whether an object placed by `to_frame` sees rays in the world's direction: untransformed,
// or translated only (RT_INSTANCE_TRANSLATION: the inverse's linear part exactly the
// identity). The instances' flags and the feature bit RT_FEATURE_WORLD_MESHES both ask here.
bool keeps_world_direction(const Mat4& to_frame);

// The device's light array in the frame whose origin is the world point `origin`, in the
// order the direct light is summed: point lights, area lights, then the other types.
// Lights that draw random numbers are numbered in that order.
std::vector<Light> tagged_lights(const SceneDesc& scene, Vec3d origin);

// Builds, in the frame whose origin is the world point `origin`, what depends on it: the
// instances and the top-level BVH (over flat.meshes' bottom levels, which it keeps), and
// the lights. flatten_scene calls it with the world's origin, set_camera with the camera's.
void place_world(FlatScene& flat, const SceneDesc& scene, Vec3d origin,
                 const RenderOptions& options);

}  // namespace rt
