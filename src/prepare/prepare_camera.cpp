// The per-camera step of the preparation (flat_scene.h), read top to bottom: the frame, the
// instances and the top level, the lights, the header, the feature bits of what was placed,
// and the padding of empty arrays.
#include <chrono>
#include <cmath>
#include <type_traits>

#include "bvh/bvh_wide.h"
#include "cl/features.h"
#include "cl/material/brdf.h"
#include "course_camera.h"
#include "prepare_stages.h"

namespace rt {

namespace {

// Builds the top level over `placed` (one leaf per instance) after the bottom levels, and
// stores the instances in its leaf order. Returns each object's index in flat.instances
// (-1: not placed).
std::vector<int> place_top_level(FlatScene& f, const FramedInstances& placed, size_t objects,
                                 const BvhOptions& bvh) {
  f.nodes.resize(f.blas_nodes);  // The bottom levels stay; the top level is rebuilt.
  std::vector<int> order;
  std::vector<BinaryBvhNode> binary;
  BvhBuildResult top = build_bvh(placed.boxes, bvh, 1, 0, binary, order);
  WideBvhResult wide = collapse_bvh(binary, top.root, WideNodes(f.nodes, node_width(bvh)));
  ++f.stats.top_levels_built;
  f.header.tlas_root = wide.root;
  f.stats.tlas_depth = wide.depth;
  f.instances.clear();
  f.instance_textures.clear();
  std::vector<int> instance_of_object(objects, -1);
  for (int i : order) {
    instance_of_object[placed.object[i]] = static_cast<int>(f.instances.size());
    f.instances.push_back(placed.instances[i]);
    f.instance_textures.push_back(placed.textures[i]);
  }
  return instance_of_object;
}

void set_camera(Camera& cam, const CameraDesc& c, Vec3d origin, const RenderOptions& options) {
  Vec3d w = normalize(c.gaze) * -1.0;
  Vec3d u = normalize(cross(c.up, w));
  Vec3d v = cross(w, u);
  // A left-handed camera (the two public CENG795 renderers that read the attribute agree)
  // keeps v and w and reverses u: the same rays, mirrored left to right on the film.
  if (c.left_handed) u = u * -1.0;
  cam.position = to_float3(c.position - origin);  // The frame's origin by default.
  cam.u = to_float3(u);
  cam.v = to_float3(v);
  cam.w = to_float3(w);
  set_course_camera(cam, c);
  cam.left = static_cast<float>(c.left);
  cam.right = static_cast<float>(c.right);
  cam.bottom = static_cast<float>(c.bottom);
  cam.top = static_cast<float>(c.top);
  cam.near_distance = static_cast<float>(c.near_distance);
  cam.aperture = static_cast<float>(c.aperture);
  cam.focus_distance = static_cast<float>(c.focus_distance);
  cam.lens = options.lens;
  cam.width = c.width;
  cam.height = c.height;
  cam.samples = options.spp > 0 ? options.spp : c.samples;
  int root = static_cast<int>(std::lround(std::sqrt(static_cast<double>(cam.samples))));
  cam.strata = root * root == cam.samples ? root : 0;
}

// Whether camera `c` draws its numbers from the scrambled Sobol sequence (RT_FLAG_SOBOL_SAMPLER):
// --sampler sobol, or auto for a path-traced camera under --path-estimator mis (the estimator
// meant for converging soonest); elsewhere auto keeps the independent sampler, whose images
// the course's references and every earlier render match.
bool sobol_sampler(const RenderOptions& options, const CameraDesc& c) {
  if (options.sampler == SamplerChoice::kAuto) return c.path_tracing && options.mis;
  return options.sampler == SamplerChoice::kSobol;
}

// The header's settings from the scene, the options and the camera (set_camera's).
void set_header(SceneHeader& h, const SceneDesc& scene, const CameraDesc& c,
                const RenderOptions& options) {
  h.background = to_float3(scene.background);
  h.ambient_light = to_float3(scene.ambient);
  h.shadow_epsilon = options.use_scene_epsilon ? static_cast<float>(scene.shadow_epsilon) : 0.0f;
  h.intersection_epsilon = static_cast<float>(scene.intersection_epsilon);
  h.max_depth = scene.max_depth;
  h.background_texture = scene.background_texture;
  h.seed = options.seed;
  h.filter = options.filter;
  h.filter_sigma = options.filter_sigma;
  const bool course_camera = !options.exact_camera_rays && course_camera_is_faithful(h.camera, c);
  h.flags = (options.cull_back_faces ? RT_FLAG_CULL_BACK_FACES : 0) |
            (options.background_on_secondary_miss ? RT_FLAG_BACKGROUND_ON_SECONDARY_MISS : 0) |
            (options.fresnel_choice ? RT_FLAG_FRESNEL_CHOICE : 0) |
            (options.unbiased_roulette ? RT_FLAG_UNBIASED_ROULETTE : 0) |
            (options.exact_ellipsoid_lights ? RT_FLAG_EXACT_ELLIPSOID_LIGHTS : 0) |
            (options.facing_reflection ? RT_FLAG_FACING_REFLECTION : 0) |
            (options.robust_offset ? RT_FLAG_ROBUST_OFFSET : 0) |
            (options.geometric_offset ? RT_FLAG_GEOMETRIC_OFFSET : 0) |
            (options.ray_hit_point ? RT_FLAG_RAY_HIT_POINT : 0) |
            (c.path_tracing ? RT_FLAG_PATH_TRACING | c.path_flags : 0) |
            // The weights need the light samples' true densities: exact ellipsoid lights.
            (c.path_tracing && options.mis ? RT_FLAG_MIS | RT_FLAG_EXACT_ELLIPSOID_LIGHTS : 0) |
            (course_camera ? RT_FLAG_COURSE_CAMERA : 0) |
            (sobol_sampler(options, c) ? RT_FLAG_SOBOL_SAMPLER : 0);
}

// The feature bits (cl/features.h) of what `f` holds: its placed instances, their
// materials and textures, its lights and its camera.
int placed_features(const FlatScene& f) {
  const SceneHeader& h = f.header;
  int bits = 0;
  std::vector<bool> used(f.materials.size());
  bool textured = h.background_texture >= 0;
  for (int i = 0; i < h.num_instances; ++i) {
    const Instance& inst = f.instances[i];
    const bool mesh = inst.kind == RT_INSTANCE_MESH;
    const bool transformed = inst.flags & RT_INSTANCE_TRANSFORMED;
    bits |= mesh ? RT_FEATURE_TRIANGLES : RT_FEATURE_SPHERES;
    if (transformed) bits |= RT_FEATURE_TRANSFORMS;
    if (mesh && (!transformed || (inst.flags & RT_INSTANCE_TRANSLATION)))
      bits |= RT_FEATURE_WORLD_MESHES;
    if (inst.flags & RT_INSTANCE_SMOOTH) bits |= RT_FEATURE_SMOOTH;
    if (inst.flags & RT_INSTANCE_MOVING) bits |= RT_FEATURE_MOTION_BLUR;
    used[inst.material] = true;
    textured = textured || f.instance_textures[i].ids[0] >= 0;
  }
  for (size_t i = 0; i < used.size(); ++i) {
    if (!used[i]) continue;
    const Material& m = f.materials[i];
    bits |= m.type;  // Type tags are feature bits (cl/features.h).
    if (m.type != RT_MATERIAL_PLAIN && m.roughness > 0) bits |= RT_FEATURE_ROUGHNESS;
    if (m.brdf != RT_BRDF_ORIGINAL_BLINN_PHONG) bits |= RT_FEATURE_BRDF;
  }
  for (int i = 0; i < h.num_lights; ++i) bits |= f.lights[i].type;
  if (textured) bits |= RT_FEATURE_TEXTURES;
  if (h.camera.aperture > 0) bits |= RT_FEATURE_DEPTH_OF_FIELD;
  if (h.camera.samples > 1) bits |= RT_FEATURE_MULTISAMPLE;
  if (h.flags & RT_FLAG_PATH_TRACING) bits |= RT_FEATURE_PATH_TRACING;
  return bits;
}

// OpenCL cannot allocate empty buffers: every array holds at least one zeroed item, a node
// or a triangle block spanning wide_units elements.
template <typename T>
uint64_t least_elements(int width) {
  return std::is_same_v<T, BvhNode> || std::is_same_v<T, TriangleBlock> ? wide_units(width) : 1;
}

void pad_arrays(FlatScene& f, int width) {
#define RT_PAD_ARRAY(Type, name) \
  if (f.name.size() < least_elements<Type>(width)) f.name.resize(least_elements<Type>(width));
  RT_DATA_ARRAYS(RT_PAD_ARRAY)
#undef RT_PAD_ARRAY
}

void pad_counts(ArrayCounts& c, int width) {
#define RT_PAD_COUNT(Type, name) c.name = std::max(c.name, least_elements<Type>(width));
  RT_DATA_ARRAYS(RT_PAD_COUNT)
#undef RT_PAD_COUNT
}

}  // namespace

void prepare_camera(FlatScene& f, const SceneDesc& scene, int camera,
                    const RenderOptions& options) {
  const auto start = std::chrono::steady_clock::now();
  const CameraDesc& c = scene.cameras[camera];
  const int width = node_width(options.bvh);
  // The frame: the camera at the origin (src/prepare/world_frame.h).
  const Vec3d origin = options.camera_frame ? c.position : Vec3d{};
  f.world_origin = origin;
  f.header = SceneHeader{};
  const std::vector<Light> lights = frame_lights(scene, origin);
  const FramedInstances placed = frame_instances(scene, f.meshes, origin);
  // The instances and the top level over them.
  const std::vector<int> instance_of_object =
      place_top_level(f, placed, scene.objects.size(), options.bvh);
  // The lights: the file's, then the emitting objects', numbered once.
  f.lights.assign(lights.begin(), lights.end());
  append_object_lights(scene, instance_of_object, f);
  number_lights(f.lights);
  place_environment(scene, f);
  set_directional_distance(placed.boxes, f.lights);
  // The header, and the feature bits of what was placed.
  set_camera(f.header.camera, c, origin, options);
  set_header(f.header, scene, c, options);
  f.header.num_instances = static_cast<int>(f.instances.size());
  f.header.num_lights = static_cast<int>(f.lights.size());
  f.header.features = placed_features(f);
  f.stats.nodes = f.nodes.size() / wide_units(width);
  f.stats.instances = f.instances.size();
  pad_arrays(f, width);
  f.stats.place_ms =
      std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - start).count();
}

ArrayCounts array_counts(const FlatScene& f) {
  ArrayCounts c;
#define RT_COUNT_ARRAY(Type, name) c.name = f.name.size();
  RT_DATA_ARRAYS(RT_COUNT_ARRAY)
#undef RT_COUNT_ARRAY
  return c;
}

ArrayCounts camera_array_counts(const FlatScene& f, const SceneDesc& scene,
                                const RenderOptions& options) {
  const int width = node_width(options.bvh);
  ArrayCounts c = array_counts(f);
  uint64_t instances = 0, object_lights = 0, light_areas = 0;
  for (const ObjectDesc& o : scene.objects) {
    if (!is_placed(o, f.meshes)) continue;
    ++instances;
    object_lights += o.emits;
    if (o.emits && o.kind == ObjectDesc::kMesh)
      light_areas += scene.meshes[o.mesh].triangles.size();
  }
  c.instances = c.instance_textures = c.instance_lights = instances;
  c.nodes = f.blas_nodes + std::max<uint64_t>(instances, 1) * wide_units(width);
  c.lights =
      scene.point_lights.size() + scene.area_lights.size() + scene.lights.size() + object_lights;
  c.light_cdf = light_areas;
  pad_counts(c, width);
  return c;
}

}  // namespace rt
