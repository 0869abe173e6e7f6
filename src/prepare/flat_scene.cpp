#include "flat_scene.h"

#include <chrono>
#include <exception>
#include <stdexcept>
#include <thread>

#include "bvh/bvh_wide.h"
#include "bvh/triangle_blocks.h"
#include "prepare_stages.h"
#include "util/parallel_for.h"

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

FlatScene prepare_scene(const SceneDesc& scene, const RenderOptions& options) {
  auto start = std::chrono::steady_clock::now();
  FlatScene f;
  const int width = node_width(options.bvh);
  if (!valid_bvh_width(width))
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
  // one padding element (together the two take more bytes per triangle than the triangle).
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
    WideNodes nodes(f.nodes, width);
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
  build_triangle_blocks(f.nodes, f.blas_nodes, width, f.triangles, f.triangle_blocks);
  flatten_textures(scene, f);
  flatten_environment(scene, f);
  f.stats.triangles = f.triangles.size();
  f.stats.bvh_build_ms =
      std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - start).count();
  return f;
}

StopRule camera_stop_rule(const StopRule& options, const CameraDesc& camera) {
  StopRule rule = options;
  rule.tonemap_key = camera.tonemap ? camera.tonemap_params.key : 0.0;
  return rule;
}

}  // namespace rt
