#include "flat_scene.h"

#include "course_camera.h"

#include <chrono>
#include <cmath>
#include <exception>
#include <stdexcept>
#include <thread>

#include "bvh/bvh_wide.h"
#include "cl/features.h"
#include "cl/material/brdf.h"
#include "bvh/triangle_blocks.h"
#include "util/parallel_for.h"
#include "world_frame.h"

namespace rt {

// C++ and OpenCL C must agree on every byte of the shared structs.
static_assert(sizeof(float3) == 16 && alignof(float3) == 16, "float3 must match OpenCL");
static_assert(sizeof(Material) == 112, "Material layout");
static_assert(sizeof(Light) == 128, "Light layout");
static_assert(sizeof(Camera) == 176, "Camera layout");
static_assert(sizeof(Instance) == 144, "Instance layout");
static_assert(sizeof(SceneHeader) == 272, "SceneHeader layout");
static_assert(sizeof(TextureDesc) == 96, "TextureDesc layout");
static_assert(sizeof(InstanceTextures) == 16, "InstanceTextures layout");
static_assert(sizeof(TriangleUV) == 32, "TriangleUV layout");

namespace {

bool is_zero(Vec3d v) { return v.x == 0 && v.y == 0 && v.z == 0; }

// The boxes of a mesh's triangles in its frame (vertices relative to `origin`, subtracted
// in double and rounded to float, as they are stored), for the BVH build.
std::vector<BvhPrimitive> triangle_primitives(const MeshDesc& mesh, Vec3d origin, int threads) {
  std::vector<BvhPrimitive> prims(mesh.triangles.size());
  parallel_ranges(prims.size(), 1 << 16, resolve_threads(threads),
                  [&](size_t, size_t from, size_t to) {
                    for (size_t i = from; i < to; ++i) {
                      Aabb box;
                      for (int k = 0; k < 3; ++k) {
                        float3 p = to_float3(mesh.positions[mesh.triangles[i][k]] - origin);
                        box.grow(p.x, p.y, p.z);
                      }
                      BvhPrimitive& prim = prims[i];
                      for (int k = 0; k < 3; ++k) prim.lo[k] = box.lo[k], prim.hi[k] = box.hi[k];
                      prim.index = static_cast<int>(i);
                      prim.unused = 0;
                    }
                  });
  return prims;
}

}  // namespace

std::vector<Vec3d> vertex_normals(const MeshDesc& mesh) {
  std::vector<Vec3d> n(mesh.positions.size());
  for (auto& t : mesh.triangles) {
    Vec3d a = mesh.positions[t[0]], b = mesh.positions[t[1]], c = mesh.positions[t[2]];
    Vec3d f = cross(b - a, c - a);
    for (int k = 0; k < 3; ++k) n[t[k]] = n[t[k]] + f;
  }
  for (auto& v : n)
    if (length(v) > 0) v = normalize(v);
  return n;
}

SceneData FlatScene::view() const {
  SceneData sd;
  sd.header = &header;
#define RT_VIEW_ARRAY(Type, name) sd.name = name.data();
  RT_DATA_ARRAYS(RT_VIEW_ARRAY)
#undef RT_VIEW_ARRAY
  return sd;
}

FlatScene flatten_scene(const SceneDesc& scene, const RenderOptions& options) {
  auto start = std::chrono::steady_clock::now();
  FlatScene f;
  f.bvh_width = options.bvh.width != 0 ? options.bvh.width : RT_BVH_WIDTH;
  if (!valid_bvh_width(f.bvh_width))
    throw std::invalid_argument("--bvh-width " + std::to_string(options.bvh.width) +
                                ": this build makes nodes of 4 or 8 children, a multiple of " +
                                std::to_string(RT_BVH_WIDTH));
  f.materials.assign(scene.materials.begin(), scene.materials.end());
  // Bottom level: one BVH per mesh, whatever the number of its instances, in the mesh's
  // frame: its vertices relative to its frame origin, subtracted in double.
  f.meshes.resize(scene.meshes.size());
  // Reserved at their final size: growing by doubling would hold a half-size copy of the
  // largest arrays beside the full one, raising the peak memory of large meshes.
  size_t triangle_count = 0;
  for (const MeshDesc& mesh : scene.meshes) triangle_count += mesh.triangles.size();
  // Per-triangle normals and texture coordinates are stored only where something reads
  // them: normals for smooth meshes (cl/geometry/surface.h), coordinates for textured objects
  // (cl/texture/texturing.h). A scene of flat, untextured meshes keeps both arrays at their
  // one padding element (at 4 M triangles, 320 MB of the 558 MB the arrays held).
  bool any_smooth = false, any_textured = false;
  for (const MeshDesc& mesh : scene.meshes) any_smooth = any_smooth || mesh.smooth;
  for (const ObjectDesc& o : scene.objects) any_textured = any_textured || !o.textures.empty();
  f.triangles.reserve(triangle_count);
  if (any_smooth) f.normals.reserve(triangle_count);
  if (any_textured) f.triangle_uvs.reserve(triangle_count);
  for (size_t mi = 0; mi < scene.meshes.size(); ++mi) {
    const MeshDesc& mesh = scene.meshes[mi];
    if (mesh.triangles.empty()) continue;
    FlatMesh& fm = f.meshes[mi];
    fm.origin = mesh_frame_origin(mesh);
    auto local = [&](int v) { return to_float3(mesh.positions[v] - fm.origin); };
    std::vector<BvhPrimitive> prims = triangle_primitives(mesh, fm.origin, options.bvh.threads);
    int offset = static_cast<int>(f.triangles.size());
    fm.first_triangle = offset;
    std::vector<BinaryBvhNode> binary;
    BvhBuildResult r = build_bvh(prims, options.bvh, options.bvh.max_leaf, offset, binary);
    // Room for the wide nodes, at most one per interior binary node (and the root), so that
    // the collapse does not copy the array as it grows; the pages past its end stay untouched.
    WideNodes nodes(f.nodes, f.bvh_width);
    const size_t most_nodes = nodes.size() + binary.size() / 2 + 1;
    if (nodes.capacity() < most_nodes) nodes.reserve(std::max(most_nodes, 2 * nodes.size()));
    fm.box.grow(binary[r.root].lo[0], binary[r.root].lo[1], binary[r.root].lo[2]);
    fm.box.grow(binary[r.root].hi[0], binary[r.root].hi[1], binary[r.root].hi[2]);
    // The collapse (serial) runs beside the copies below, which need only the order; the
    // binary tree is freed as soon as it is done with, for peak memory.
    const int threads = resolve_threads(options.bvh.threads);
    WideBvhResult w;
    std::exception_ptr collapse_error;
    auto collapse = [&] {
      try {
        w = collapse_bvh(binary, r.root, nodes, /*merge_leaves=*/true);
      } catch (...) {
        collapse_error = std::current_exception();
      }
      std::vector<BinaryBvhNode>().swap(binary);
    };
    std::thread collapser;
    struct JoinOnExit {  // Also when a copy below throws: a joinable thread must not die.
      std::thread& t;
      ~JoinOnExit() {
        if (t.joinable()) t.join();
      }
    } join_on_exit{collapser};
    if (threads > 1)
      collapser = std::thread(collapse);
    else
      collapse();
    std::vector<Vec3d> vn;
    if (mesh.smooth) vn = vertex_normals(mesh);
    // The triangles in leaf order, in parallel: each position is written once, from its
    // own primitive, so the bytes do not depend on the threads.
    const size_t base = f.triangles.size();
    f.triangles.resize(base + prims.size());
    if (any_smooth) f.normals.resize(base + prims.size());
    if (any_textured) f.triangle_uvs.resize(base + prims.size());
    auto copy = [&](size_t, size_t from, size_t to) {
      for (size_t i = from; i < to; ++i) {
        const auto& t = mesh.triangles[prims[i].index];
        Triangle& tri = f.triangles[base + i];
        tri.v0 = local(t[0]);
        tri.v1 = local(t[1]);
        tri.v2 = local(t[2]);
        if (mesh.smooth) {
          TriangleNormals& tn = f.normals[base + i];
          tn.n0 = to_float3(vn[t[0]]);
          tn.n1 = to_float3(vn[t[1]]);
          tn.n2 = to_float3(vn[t[2]]);
        }
        if (any_textured && !mesh.uvs.empty()) {
          auto at = [&](int k) {
            return make_float2(static_cast<float>(mesh.uvs[t[k]][0]),
                               static_cast<float>(mesh.uvs[t[k]][1]));
          };
          TriangleUV& uv = f.triangle_uvs[base + i];
          uv.uv0 = at(0);
          uv.uv1 = at(1);
          uv.uv2 = at(2);
        }
      }
    };
    parallel_ranges(prims.size(), 1 << 16, std::max(1, threads - 1), copy);
    if (collapser.joinable()) collapser.join();
    if (collapse_error) std::rethrow_exception(collapse_error);
    fm.blas_root = w.root;
    f.stats.max_blas_depth = std::max(f.stats.max_blas_depth, w.depth);
  }
  f.blas_nodes = f.nodes.size();
  build_triangle_blocks(f);
  flatten_textures(scene, f);
  flatten_environment(scene, f);
  f.stats.triangles = f.triangles.size();
  // OpenCL cannot allocate empty buffers; a zeroed element keeps every array non-empty.
#define RT_PAD_ARRAY(Type, name) \
  if (f.name.empty()) f.name.emplace_back();
  RT_DATA_ARRAYS(RT_PAD_ARRAY)
#undef RT_PAD_ARRAY
  f.triangle_blocks.resize(std::max(f.triangle_blocks.size(), wide_units(f.bvh_width)));
  // The top level and the lights, in the world's frame until a camera is set.
  place_world(f, scene, Vec3d{}, options);
  SceneHeader& h = f.header;
  h.background = to_float3(scene.background);
  h.ambient_light = to_float3(scene.ambient);
  h.shadow_epsilon = options.use_scene_epsilon ? static_cast<float>(scene.shadow_epsilon) : 0.0f;
  h.intersection_epsilon = static_cast<float>(scene.intersection_epsilon);
  h.max_depth = scene.max_depth;
  h.background_texture = scene.background_texture;
  h.seed = options.seed;
  h.filter = options.filter;
  h.filter_sigma = options.filter_sigma;
  h.flags = (options.cull_back_faces ? RT_FLAG_CULL_BACK_FACES : 0) |
            (options.background_on_secondary_miss ? RT_FLAG_BACKGROUND_ON_SECONDARY_MISS : 0) |
            (options.fresnel_choice ? RT_FLAG_FRESNEL_CHOICE : 0) |
            (options.unbiased_roulette ? RT_FLAG_UNBIASED_ROULETTE : 0) |
            (options.exact_ellipsoid_lights ? RT_FLAG_EXACT_ELLIPSOID_LIGHTS : 0) |
            (options.facing_reflection ? RT_FLAG_FACING_REFLECTION : 0) |
            (options.robust_offset ? RT_FLAG_ROBUST_OFFSET : 0) |
            (options.geometric_offset ? RT_FLAG_GEOMETRIC_OFFSET : 0) |
            (options.ray_hit_point ? RT_FLAG_RAY_HIT_POINT : 0);
  f.fast_math = options.fast_math;
  if (options.precision == Precision::kAuto)
    throw std::logic_error("--precision auto reached flatten_scene unresolved (resolve_precision)");
  f.double_precision = options.precision == Precision::kDouble;
  f.stats.bvh_build_ms =
      std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - start).count();
  return f;
}

StopRule camera_stop_rule(const StopRule& options, const CameraDesc& camera) {
  StopRule rule = options;
  rule.tonemap_key = camera.tonemap ? camera.tonemap_params.key : 0.0;
  return rule;
}

void set_camera(FlatScene& flat, const SceneDesc& scene, int camera, const RenderOptions& options) {
  const CameraDesc& c = scene.cameras[camera];
  const auto start = std::chrono::steady_clock::now();
  const Vec3d origin = options.camera_frame ? c.position : Vec3d{};
  place_world(flat, scene, origin, options);
  flat.stats.place_ms =
      std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - start).count();
  Camera& cam = flat.header.camera;
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
  const bool course_camera = !options.exact_camera_rays && course_camera_is_faithful(cam, c);
  flat.header.flags = (flat.header.flags & ~(RT_FLAG_PATH_MASK | RT_FLAG_COURSE_CAMERA)) |
                      (c.path_tracing ? RT_FLAG_PATH_TRACING | c.path_flags : 0) |
                      (course_camera ? RT_FLAG_COURSE_CAMERA : 0);
  flat.header.features = scene_features(scene, camera, options);
}

int scene_features(const SceneDesc& scene, int camera, const RenderOptions& options) {
  int f = 0;
  std::vector<bool> used(scene.materials.size());
  const Vec3d eye = options.camera_frame ? scene.cameras[camera].position : Vec3d{};
  for (const ObjectDesc& o : scene.objects) {
    const bool sphere = o.kind == ObjectDesc::kSphere;
    f |= sphere ? RT_FEATURE_SPHERES : RT_FEATURE_TRIANGLES;
    // In the camera's frame (src/prepare/world_frame.h).
    const Vec3d mesh_origin = sphere ? Vec3d{} : mesh_frame_origin(scene.meshes[o.mesh]);
    const Mat4 to_frame = object_to_frame(o, mesh_origin, eye);
    if (!to_frame.is_identity()) f |= RT_FEATURE_TRANSFORMS;
    if (!sphere && keeps_world_direction(to_frame)) f |= RT_FEATURE_WORLD_MESHES;
    if (o.kind == ObjectDesc::kMesh && scene.meshes[o.mesh].smooth) f |= RT_FEATURE_SMOOTH;
    if (!is_zero(o.motion)) f |= RT_FEATURE_MOTION_BLUR;
    used[o.material] = true;
  }
  for (size_t i = 0; i < used.size(); ++i) {
    if (!used[i]) continue;
    const Material& m = scene.materials[i];
    f |= m.type;  // Type tags are feature bits (cl/features.h).
    if (m.type != RT_MATERIAL_PLAIN && m.roughness > 0) f |= RT_FEATURE_ROUGHNESS;
    if (m.brdf != RT_BRDF_ORIGINAL_BLINN_PHONG) f |= RT_FEATURE_BRDF;
  }
  for (const Light& l : tagged_lights(scene, Vec3d{})) f |= l.type;
  for (const ObjectDesc& o : scene.objects)
    if (o.emits) f |= o.kind == ObjectDesc::kSphere ? RT_LIGHT_SPHERE : RT_LIGHT_MESH;
  bool textured = scene.background_texture >= 0;
  for (const ObjectDesc& o : scene.objects) textured = textured || !o.textures.empty();
  if (textured) f |= RT_FEATURE_TEXTURES;
  const CameraDesc& c = scene.cameras[camera];
  if (c.aperture > 0) f |= RT_FEATURE_DEPTH_OF_FIELD;
  if ((options.spp > 0 ? options.spp : c.samples) > 1) f |= RT_FEATURE_MULTISAMPLE;
  if (c.path_tracing) f |= RT_FEATURE_PATH_TRACING;
  return f;
}

}  // namespace rt
