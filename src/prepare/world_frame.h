// The frame the devices work in. The file's numbers are kept in double on the host; float
// only holds positions well near its origin (ulp(1e5) = 0.008), so the world is moved into
// the camera's frame (the camera at the origin) before anything becomes float: large-world
// coordinates, as game engines call it. Each mesh keeps its vertices relative to a point of
// its own (its frame origin) so its bottom-level BVH serves every camera unchanged; a new
// camera makes only the instances' transforms, their boxes and the lights anew.
//
// Everything here is a function of the scene and a frame origin alone: the preparation
// (src/prepare/flat_scene.h) calls it and stores what it returns.
#pragma once

#include <vector>

#include "bvh/bvh_build.h"
#include "scene/scene.h"
#include "util/page_aligned.h"

namespace rt {

// A mesh's bottom level, built once in the mesh's own frame.
struct FlatMesh {
  int blas_root = -1;       // -1: no triangle left after degenerates.
  Aabb box;                 // Of its float vertices, in its frame.
  Vec3d origin;             // The object-space point its frame is centred on.
  int first_triangle = -1;  // Index of its first triangle in FlatScene::triangles.
};

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
// identity).
bool keeps_world_direction(const Mat4& to_frame);

// Whether `object` gets an instance: a sphere, or a mesh that kept a triangle.
inline bool is_placed(const ObjectDesc& object, const std::vector<FlatMesh>& meshes) {
  return object.kind == ObjectDesc::kSphere || meshes[object.mesh].blas_root >= 0;
}

// The scene's objects placed in the frame whose origin is the world point `origin`, in the
// objects' order, leaving out those whose mesh kept no triangle (`meshes` per
// SceneDesc::meshes): entry i of each vector belongs to object `object[i]`.
struct FramedInstances {
  std::vector<Instance> instances;
  std::vector<InstanceTextures> textures;
  std::vector<Aabb> boxes;  // In the frame, covering the whole shutter interval.
  std::vector<int> object;
};
// Throws std::invalid_argument (naming the object) for a singular transform or an object
// beyond float range from `origin`.
FramedInstances frame_instances(const SceneDesc& scene, const std::vector<FlatMesh>& meshes,
                                Vec3d origin);

// The lights of the file (point lights, area lights, then the Lights block's other types,
// the order the direct light sums them) in the frame whose origin is the world point
// `origin`; their sample_index is left for the preparation to number. Throws
// std::invalid_argument for a light beyond float range from `origin`.
std::vector<Light> frame_lights(const SceneDesc& scene, Vec3d origin);

// A directional (or environment) light's shadow segment runs from the shading point towards
// the light for its param0: twice the diagonal of the box around every object (at least 1)
// leaves the box from any point inside it.
void set_directional_distance(const std::vector<Aabb>& boxes, PageAlignedVector<Light>& lights);

}  // namespace rt
