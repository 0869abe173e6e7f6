// The scene flattened into the arrays both devices read (layouts in cl/scene_types.h).
#pragma once

#include <cstdint>
#include <vector>

#include "bvh/bvh_build.h"
#include "device/precision.h"
#include "scene/scene.h"
#include "util/page_aligned.h"
#include "world_frame.h"

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

// --sampler: where a sample's random numbers come from (cl/sampling/sampler.h). kAuto is
// sobol for path-traced cameras under --path-estimator mis, else the independent sampler
// (sobol_sampler in prepare_camera.cpp).
enum class SamplerChoice { kAuto, kIndependent, kSobol };

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
  bool mis = false;                     // Path tracing: --path-estimator mis (RT_FLAG_MIS).
  bool exact_ellipsoid_lights = false;  // Not the course's object-space solid angle.
  bool facing_reflection = false;       // Not the course's reflection offset (mirror.h).
  bool robust_offset = false;      // Spawned rays: scene epsilon plus ulps (cl/geometry/ray.h).
  bool exact_camera_rays = false;  // Not the course's float camera rays (camera.h).
  bool geometric_offset = false;   // Shadow rays leave along ng, not the course's n.
  bool ray_hit_point = true;       // Hit point o + t d, as the course; off: the primitive.
  SamplerChoice sampler = SamplerChoice::kAuto;
  bool fast_math = false;          // OpenCL: -cl-fast-relaxed-math (the CPU stays precise).
  // The devices work in the camera's frame (src/prepare/world_frame.h). Off: in the world's, for
  // tests that trace rays given in world coordinates.
  bool camera_frame = true;
  // Computation in double or float (cl/util/real.h); storage stays float. kAuto must be
  // resolved against the device (resolve_precision) before prepare_scene.
  Precision precision = Precision::kFloat;
  StopRule stop;
  BvhOptions bvh;
};

struct FlatStats {
  double bvh_build_ms = 0;  // prepare_scene: the bottom levels and every per-scene array.
  double place_ms = 0;      // The last prepare_camera: the top level and lights for a camera.
  size_t nodes = 0, triangles = 0, instances = 0;
  int tlas_depth = 0, max_blas_depth = 0;
  int top_levels_built = 0;  // Top levels built so far, one per prepare_camera.
};

// Page-aligned, so an OpenCL device on the host's CPU renders from them without a copy.
#define RT_FLAT_SCENE_VECTOR(Type, name) PageAlignedVector<Type> name;
struct FlatScene {
  SceneHeader header{};
  RT_DATA_ARRAYS(RT_FLAT_SCENE_VECTOR)  // The device arrays of cl/data_arrays.h.
  FlatStats stats;
  // Host-side only: what prepare_camera keeps and where the frame is.
  std::vector<FlatMesh> meshes;  // Per SceneDesc::meshes.
  size_t blas_nodes = 0;         // nodes[0, blas_nodes) are the bottom levels.
  Vec3d world_origin;            // The world point at the devices' origin.
  float env_power = 0;           // The environment map's mean importance (flatten_environment).

  // Pointers into the arrays above, for the CPU reference.
  SceneData view() const;
};
#undef RT_FLAT_SCENE_VECTOR

// The element count of every device array (cl/data_arrays.h), for the memory check.
#define RT_ARRAY_COUNT(Type, name) uint64_t name = 0;
struct ArrayCounts {
  RT_DATA_ARRAYS(RT_ARRAY_COUNT)
};
#undef RT_ARRAY_COUNT

// The preparation of a scene for the devices, in two steps run in this order:
//
// 1. prepare_scene, once per scene file: what no camera changes (materials, every mesh's
//    bottom-level BVH in its own frame, the triangles and their blocks, textures, the
//    environment map's tables). `options` must be resolved (precision not kAuto; a BVH
//    width of 0 takes this build's RT_BVH_WIDTH).
FlatScene prepare_scene(const SceneDesc& scene, const RenderOptions& options);

// 2. prepare_camera, once per rendered camera, with the same options: the camera and its
//    frame (src/prepare/world_frame.h), the instances and the top level over them, the
//    lights, the environment's entry, the header and its feature bits (cl/features.h),
//    derived from what was just placed; every empty array then gets its padding element.
//    Throws std::invalid_argument when something lies beyond float range of the frame.
void prepare_camera(FlatScene& flat, const SceneDesc& scene, int camera,
                    const RenderOptions& options);

// The array sizes `flat` (from prepare_scene) will have once any camera of `scene` is
// prepared, at most: the instances, lights and light areas are the same for every camera,
// and a top level holds at most one node per instance. The memory check runs on it before
// any camera is placed.
ArrayCounts camera_array_counts(const FlatScene& flat, const SceneDesc& scene,
                                const RenderOptions& options);
// The array sizes as they stand.
ArrayCounts array_counts(const FlatScene& flat);

// The normals of shadingMode="smooth": per vertex, the normalized sum of the unnormalized
// cross products of its faces (area-weighted). Exporters write the same normals.
std::vector<Vec3d> vertex_normals(const MeshDesc& mesh);

// The function importance sampling follows over `map`'s texels (row-major): luminance times
// the solid angle per unit map area at the texel's centre (cl/light/environment_map.h).
std::vector<double> environment_importance(const ImageF& map, int mapping);

}  // namespace rt
