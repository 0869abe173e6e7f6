// The scene flattened into the arrays both devices read (layouts in cl/scene_types.h).
#pragma once

#include <cstdint>
#include <vector>

#include "bvh/bvh_build.h"
#include "device/precision.h"
#include "scene/scene.h"
#include "util/page_aligned.h"

namespace rt {

// When to stop sampling before the camera's sample count is reached. Renders stop only
// between passes, so every pixel always has the same number of samples.
struct StopRule {
  double time_limit_s = 0;  // Wall-clock budget of one image's sampling; 0: none.
  double noise_target = 0;  // Stop once relative_noise() falls below this; 0: never.
  // > 0: the film is HDR, tone mapped with this key; sets the noise's floor (noise_floor).
  double tonemap_key = 0;
};

// The rule for one camera: the options' rule, with the floor of its film's noise.
StopRule camera_stop_rule(const StopRule& options, const CameraDesc& camera);

struct RenderOptions {
  uint32_t seed = 0;
  int spp = 0;  // Overrides the camera's NumSamples when > 0.
  bool cull_back_faces = false;
  bool background_on_secondary_miss = false;
  int filter = RT_FILTER_BOX;
  float filter_sigma = 0.5f;
  int lens = RT_LENS_SQUARE;
  bool use_scene_epsilon = true;        // Off: rely on the scale-aware offset alone.
  bool fresnel_choice = false;          // Dielectrics: pick one ray by Fresnel instead of both.
  bool unbiased_roulette = false;       // Path tracing: RussianRoulette without the course's bias.
  bool exact_ellipsoid_lights = false;  // Not the course's object-space solid angle.
  bool facing_reflection = false;       // Not the course's reflection offset (mirror.h).
  bool robust_offset = false;           // Spawned rays: scene epsilon plus ulps (cl/geometry/ray.h).
  bool exact_camera_rays = false;       // Not the course's float camera rays (camera.h).
  bool geometric_offset = false;        // Shadow rays leave along ng, not the course's n.
  bool ray_hit_point = true;            // Hit point o + t d, as the course; off: the primitive.
  bool fast_math = false;               // OpenCL: -cl-fast-relaxed-math (the CPU stays precise).
  // The devices work in the camera's frame (src/prepare/world_frame.h). Off: in the world's, for
  // tests that trace rays given in world coordinates.
  bool camera_frame = true;
  // Computation in double or float (cl/util/real.h); storage stays float. kAuto must be
  // resolved against the device (resolve_precision) before flatten_scene.
  Precision precision = Precision::kFloat;
  StopRule stop;
  BvhOptions bvh;
};

struct FlatStats {
  double bvh_build_ms = 0;
  double place_ms = 0;  // The last place_world: the top level and lights for a camera.
  size_t nodes = 0, triangles = 0, instances = 0;
  int tlas_depth = 0, max_blas_depth = 0;
};

// A mesh's bottom level, built once in the mesh's own frame (src/prepare/world_frame.h).
struct FlatMesh {
  int blas_root = -1;       // -1: no triangle left after degenerates.
  Aabb box;                 // Of its float vertices, in its frame.
  Vec3d origin;             // The object-space point its frame is centred on.
  int first_triangle = -1;  // Index of its first triangle in FlatScene::triangles.
};

// Page-aligned, so an OpenCL device on the host's CPU renders from them without a copy.
#define RT_FLAT_SCENE_VECTOR(Type, name) PageAlignedVector<Type> name;
struct FlatScene {
  SceneHeader header{};
  RT_DATA_ARRAYS(RT_FLAT_SCENE_VECTOR)  // The device arrays of cl/data_arrays.h.
  FlatStats stats;
  bool fast_math = false;  // Host-side only: how the OpenCL program is built.
  // Host-side only: what a change of frame (place_world) keeps and where the frame is.
  std::vector<FlatMesh> meshes;  // Per SceneDesc::meshes.
  size_t blas_nodes = 0;         // nodes[0, blas_nodes) are the bottom levels.
  // Host-side only: children per node and triangles per block (src/bvh/bvh_lanes.h); the
  // arrays hold bvh_width / RT_BVH_WIDTH elements per node and per block.
  int bvh_width = RT_BVH_WIDTH;
  Vec3d world_origin;   // The world point at the devices' origin.
  float env_power = 0;  // The environment map's mean importance (flatten_environment).
  // Host-side only: which build of the shared math runs (both devices; cl/util/real.h).
  bool double_precision = false;

  // Pointers into the arrays above, for the CPU reference.
  SceneData view() const;
};
#undef RT_FLAT_SCENE_VECTOR

// Builds the BVHs and arrays in the world's frame; set_camera moves them into a camera's
// (the bottom levels, most of the work, are shared by every camera of a file).
FlatScene flatten_scene(const SceneDesc& scene, const RenderOptions& options);

// The normals of shadingMode="smooth": per vertex, the normalized sum of the unnormalized
// cross products of its faces (area-weighted). Exporters write the same normals.
std::vector<Vec3d> vertex_normals(const MeshDesc& mesh);
// Sets the camera and moves the world into its frame (the camera at the origin).
void set_camera(FlatScene& flat, const SceneDesc& scene, int camera, const RenderOptions& options);

// Appends the scene's images to flat.texels and a descriptor per TextureMap to
// flat.textures (src/prepare/flat_textures.cpp).
void flatten_textures(const SceneDesc& scene, FlatScene& flat);

// Places the environment light's map and its sampling distributions in flat's arrays, once
// per scene: they do not depend on the frame (src/prepare/flat_environment.cpp).
void flatten_environment(const SceneDesc& scene, FlatScene& flat);
// Gives the environment's entry of flat.lights, made anew for each frame, the map's size and
// power, and sets the header's index to it.
void place_environment(const SceneDesc& scene, FlatScene& flat);

// The function importance sampling follows over `map`'s texels (row-major): luminance times
// the solid angle per unit map area at the texel's centre (cl/light/environment_map.h).
std::vector<double> environment_importance(const ImageF& map, int mapping);

// Appends a light to flat.lights for every emitting object (LightMesh, LightSphere) and
// fills flat.instance_lights and flat.light_cdf (src/prepare/flat_object_lights.cpp).
// instance_of_object[i] is object i's index in flat.instances (-1: no instance, an empty
// mesh); mesh_first[m] is the index of mesh m's first triangle in flat.triangles.
void flatten_object_lights(const SceneDesc& scene, const std::vector<int>& instance_of_object,
                           const std::vector<int>& mesh_first, FlatScene& flat);

// The feature bits the scene needs for `camera` (cl/features.h).
int scene_features(const SceneDesc& scene, int camera, const RenderOptions& options);

}  // namespace rt
