// The scene flattened into the arrays both devices read (layouts in cl/scene_types.h).
#pragma once

#include <cstdint>
#include <vector>

#include "bvh_build.h"
#include "scene.h"

namespace rt {

struct RenderOptions {
  uint32_t seed = 0;
  int spp = 0;  // Overrides the camera's NumSamples when > 0.
  bool cull_back_faces = false;
  bool background_on_secondary_miss = false;
  int filter = RT_FILTER_BOX;
  float filter_sigma = 0.5f;
  int lens = RT_LENS_SQUARE;
  bool use_scene_epsilon = true;  // Off: rely on the scale-aware offset alone.
  BvhOptions bvh;
};

struct FlatStats {
  double bvh_build_ms = 0;
  size_t nodes = 0, triangles = 0, instances = 0;
  int tlas_depth = 0, max_blas_depth = 0;
};

struct FlatScene {
  SceneHeader header{};
  std::vector<Material> materials;
  std::vector<Instance> instances;
  std::vector<BvhNode> nodes;
  std::vector<Triangle> triangles;
  std::vector<TriangleNormals> normals;
  std::vector<PointLight> point_lights;
  std::vector<AreaLight> area_lights;
  FlatStats stats;

  // Pointers into the arrays above, for the CPU reference.
  SceneData view() const;
};

// Builds the BVHs and arrays; the camera is set separately (geometry is shared by every
// camera of a file).
FlatScene flatten_scene(const SceneDesc& scene, const RenderOptions& options);
void set_camera(FlatScene& flat, const SceneDesc& scene, int camera, const RenderOptions& options);

// The feature bits the scene needs for `camera` (cl/features.h).
int scene_features(const SceneDesc& scene, int camera, const RenderOptions& options);

}  // namespace rt
