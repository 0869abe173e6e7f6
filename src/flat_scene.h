// The scene flattened into the arrays both devices read (layouts in cl/scene_types.h).
#pragma once

#include <cstdint>
#include <vector>

#include "bvh_build.h"
#include "scene.h"

namespace rt {

// When to stop sampling before the camera's sample count is reached. Renders stop only
// between passes, so every pixel always has the same number of samples.
struct StopRule {
  double time_limit_s = 0;  // Wall-clock budget of the render; 0: none.
  double noise_target = 0;  // Stop once relative_noise() falls below this; 0: never.
};

struct RenderOptions {
  uint32_t seed = 0;
  int spp = 0;  // Overrides the camera's NumSamples when > 0.
  bool cull_back_faces = false;
  bool background_on_secondary_miss = false;
  int filter = RT_FILTER_BOX;
  float filter_sigma = 0.5f;
  int lens = RT_LENS_SQUARE;
  bool use_scene_epsilon = true;  // Off: rely on the scale-aware offset alone.
  bool fresnel_choice = false;    // Dielectrics: pick one ray by Fresnel instead of both.
  bool exact_ellipsoid_lights = false;  // Not the course's object-space solid angle.
  bool fast_math = false;         // OpenCL: -cl-fast-relaxed-math (the CPU stays precise).
  bool double_precision = false;  // Computation in double (cl/util/real.h); storage stays float.
  StopRule stop;
  BvhOptions bvh;
};

struct FlatStats {
  double bvh_build_ms = 0;
  size_t nodes = 0, triangles = 0, instances = 0;
  int tlas_depth = 0, max_blas_depth = 0;
};

#define RT_FLAT_SCENE_VECTOR(Type, name) std::vector<Type> name;
struct FlatScene {
  SceneHeader header{};
  RT_DATA_ARRAYS(RT_FLAT_SCENE_VECTOR)  // The device arrays of cl/data_arrays.h.
  FlatStats stats;
  bool fast_math = false;  // Host-side only: how the OpenCL program is built.
  // Host-side only: which build of the shared math runs (both devices; cl/util/real.h).
  bool double_precision = false;

  // Pointers into the arrays above, for the CPU reference.
  SceneData view() const;
};
#undef RT_FLAT_SCENE_VECTOR

// Builds the BVHs and arrays; the camera is set separately (geometry is shared by every
// camera of a file).
FlatScene flatten_scene(const SceneDesc& scene, const RenderOptions& options);

// The normals of shadingMode="smooth": per vertex, the normalized sum of the unnormalized
// cross products of its faces (area-weighted). Exporters write the same normals.
std::vector<Vec3d> vertex_normals(const MeshDesc& mesh);
void set_camera(FlatScene& flat, const SceneDesc& scene, int camera, const RenderOptions& options);

// Appends the scene's images to flat.texels and a descriptor per TextureMap to
// flat.textures (src/flat_textures.cpp).
void flatten_textures(const SceneDesc& scene, FlatScene& flat);

// Appends a light to flat.lights for every emitting object (LightMesh, LightSphere) and
// fills flat.instance_lights and flat.light_cdf (src/flat_object_lights.cpp).
// instance_of_object[i] is object i's index in flat.instances (-1: no instance, an empty
// mesh); mesh_first[m] is the index of mesh m's first triangle in flat.triangles.
void flatten_object_lights(const SceneDesc& scene, const std::vector<int>& instance_of_object,
                           const std::vector<int>& mesh_first, FlatScene& flat);

// The feature bits the scene needs for `camera` (cl/features.h).
int scene_features(const SceneDesc& scene, int camera, const RenderOptions& options);

}  // namespace rt
