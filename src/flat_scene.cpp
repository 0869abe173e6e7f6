#include "flat_scene.h"

#include <chrono>
#include <cmath>
#include <stdexcept>

#include "bvh_wide.h"
#include "cl/features.h"
#include "cl/material/brdf.h"

namespace rt {

// C++ and OpenCL C must agree on every byte of the shared structs.
static_assert(sizeof(float3) == 16 && alignof(float3) == 16, "float3 must match OpenCL");
static_assert(sizeof(Material) == 112, "Material layout");
static_assert(sizeof(Light) == 128, "Light layout");
static_assert(sizeof(Camera) == 112, "Camera layout");
static_assert(sizeof(Instance) == 128, "Instance layout");
static_assert(sizeof(BvhNode) == 32 * RT_BVH_WIDTH, "BvhNode layout");
static_assert(sizeof(SceneHeader) == 192, "SceneHeader layout");
static_assert(sizeof(TextureDesc) == 80, "TextureDesc layout");
static_assert(sizeof(InstanceTextures) == 16, "InstanceTextures layout");
static_assert(sizeof(TriangleUV) == 32, "TriangleUV layout");

namespace {

void set_rows(float4 rows[3], const Mat4& m) {
  for (int r = 0; r < 3; ++r)
    rows[r] = float4{static_cast<float>(m(r, 0)), static_cast<float>(m(r, 1)),
                     static_cast<float>(m(r, 2)), static_cast<float>(m(r, 3))};
}

Aabb transformed_box(const Aabb& b, const Mat4& m, Vec3d motion) {
  Aabb out;
  for (int c = 0; c < 8; ++c) {
    Vec3d p = m.point(
        {(c & 1) ? b.hi[0] : b.lo[0], (c & 2) ? b.hi[1] : b.lo[1], (c & 4) ? b.hi[2] : b.lo[2]});
    for (int t = 0; t < 2; ++t) {
      Vec3d q = p + motion * t;
      // Widen by a relative ulp so float rounding of the transform cannot shrink the box.
      out.grow(std::nextafter(static_cast<float>(q.x), -3.4e38f),
               std::nextafter(static_cast<float>(q.y), -3.4e38f),
               std::nextafter(static_cast<float>(q.z), -3.4e38f));
      out.grow(std::nextafter(static_cast<float>(q.x), 3.4e38f),
               std::nextafter(static_cast<float>(q.y), 3.4e38f),
               std::nextafter(static_cast<float>(q.z), 3.4e38f));
    }
  }
  return out;
}

bool is_zero(Vec3d v) { return v.x == 0 && v.y == 0 && v.z == 0; }

// The tagged array, in the order the direct light is summed: point lights, area lights,
// then the other types. Lights that draw random numbers are numbered in that order.
std::vector<Light> tagged_lights(const SceneDesc& scene) {
  std::vector<Light> out;
  for (const PointLight& p : scene.point_lights) {
    Light l{};
    l.type = RT_LIGHT_POINT;
    l.position = p.position;
    l.emission = p.intensity;
    out.push_back(l);
  }
  int sampled = 0;
  for (const AreaLight& a : scene.area_lights) {
    Light l{};
    l.type = RT_LIGHT_AREA;
    l.position = a.corner;
    l.edge1 = a.edge1;
    l.edge2 = a.edge2;
    l.normal = a.normal;
    l.emission = a.radiance;
    l.area = a.area;
    l.sample_index = sampled++;
    out.push_back(l);
  }
  for (Light l : scene.lights) {
    // Directional and spot lights draw no random numbers.
    if (l.type != RT_LIGHT_DIRECTIONAL && l.type != RT_LIGHT_SPOT) l.sample_index = sampled++;
    out.push_back(l);
  }
  return out;
}

// A directional light's shadow segment runs from the shading point towards the light for
// `distance`: twice the diagonal of the box around every object (at least 1) leaves the box
// from any point inside it.
void set_directional_distance(const std::vector<Aabb>& boxes, std::vector<Light>& lights) {
  Aabb world;
  for (const Aabb& b : boxes) world.grow(b);
  double diagonal = 0;
  for (int a = 0; a < 3 && !world.empty(); ++a)
    diagonal += (double(world.hi[a]) - world.lo[a]) * (double(world.hi[a]) - world.lo[a]);
  float distance = static_cast<float>(std::max(1.0, 2.0 * std::sqrt(diagonal)));
  for (Light& l : lights)
    if (l.type == RT_LIGHT_DIRECTIONAL) l.param0 = distance;
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
  f.materials = scene.materials;
  f.lights = tagged_lights(scene);
  // Bottom level: one BVH per mesh, whatever the number of its instances.
  std::vector<int> blas_root(scene.meshes.size(), -1);
  std::vector<int> mesh_first(scene.meshes.size(), -1);
  std::vector<Aabb> blas_box(scene.meshes.size());
  for (size_t mi = 0; mi < scene.meshes.size(); ++mi) {
    const MeshDesc& mesh = scene.meshes[mi];
    if (mesh.triangles.empty()) continue;
    std::vector<Aabb> boxes(mesh.triangles.size());
    for (size_t i = 0; i < mesh.triangles.size(); ++i)
      for (int k = 0; k < 3; ++k) {
        Vec3d p = mesh.positions[mesh.triangles[i][k]];
        boxes[i].grow(static_cast<float>(p.x), static_cast<float>(p.y), static_cast<float>(p.z));
      }
    std::vector<int> order;
    int offset = static_cast<int>(f.triangles.size());
    mesh_first[mi] = offset;
    std::vector<BinaryBvhNode> binary;
    BvhBuildResult r = build_bvh(boxes, options.bvh, options.bvh.max_leaf, offset, binary, order);
    WideBvhResult w = collapse_bvh(binary, r.root, f.nodes);
    blas_root[mi] = w.root;
    f.stats.max_blas_depth = std::max(f.stats.max_blas_depth, w.depth);
    for (auto& b : boxes) blas_box[mi].grow(b);
    std::vector<Vec3d> vn;
    if (mesh.smooth) vn = vertex_normals(mesh);
    for (int i : order) {
      const auto& t = mesh.triangles[i];
      Triangle tri;
      tri.v0 = to_float3(mesh.positions[t[0]]);
      tri.v1 = to_float3(mesh.positions[t[1]]);
      tri.v2 = to_float3(mesh.positions[t[2]]);
      f.triangles.push_back(tri);
      TriangleNormals tn{};
      if (mesh.smooth) {
        tn.n0 = to_float3(vn[t[0]]);
        tn.n1 = to_float3(vn[t[1]]);
        tn.n2 = to_float3(vn[t[2]]);
      }
      f.normals.push_back(tn);
      TriangleUV uv{};
      if (!mesh.uvs.empty()) {
        auto at = [&](int k) {
          return make_float2(static_cast<float>(mesh.uvs[t[k]][0]),
                             static_cast<float>(mesh.uvs[t[k]][1]));
        };
        uv.uv0 = at(0);
        uv.uv1 = at(1);
        uv.uv2 = at(2);
      }
      f.triangle_uvs.push_back(uv);
    }
  }
  // Top level: one leaf per instance, boxes covering the whole shutter interval.
  std::vector<Instance> unordered;
  std::vector<InstanceTextures> unordered_textures;
  std::vector<Aabb> boxes;
  std::vector<int> object_of;  // The object each entry of `unordered` was made from.
  Aabb unit;
  unit.grow(-1, -1, -1);
  unit.grow(1, 1, 1);
  for (const ObjectDesc& o : scene.objects) {
    bool sphere = o.kind == ObjectDesc::kSphere;
    if (!sphere && blas_root[o.mesh] < 0) continue;  // Nothing left after degenerates.
    Instance inst{};
    bool ok;
    Mat4 inv = o.transform.affine_inverse(&ok);
    // The loader rejects singular transforms; a caller building scenes in code must too.
    if (!ok) throw std::invalid_argument(o.element + ": singular transform");
    set_rows(inst.world_to_object, inv);
    set_rows(inst.object_to_world, o.transform);
    inst.motion = to_float3(o.motion);
    inst.kind = sphere ? RT_INSTANCE_SPHERE : RT_INSTANCE_MESH;
    inst.blas_root = sphere ? -1 : blas_root[o.mesh];
    inst.material = o.material;
    inst.flags = (o.transform.is_identity() ? 0 : RT_INSTANCE_TRANSFORMED) |
                 (!sphere && scene.meshes[o.mesh].smooth ? RT_INSTANCE_SMOOTH : 0) |
                 (is_zero(o.motion) ? 0 : RT_INSTANCE_MOVING);
    unordered.push_back(inst);
    object_of.push_back(static_cast<int>(&o - scene.objects.data()));
    InstanceTextures it;
    for (int k = 0; k < RT_MAX_OBJECT_TEXTURES; ++k)
      it.ids[k] = k < static_cast<int>(o.textures.size()) ? o.textures[k] : -1;
    unordered_textures.push_back(it);
    boxes.push_back(transformed_box(sphere ? unit : blas_box[o.mesh], o.transform, o.motion));
  }
  std::vector<int> order;
  std::vector<BinaryBvhNode> binary;
  BvhBuildResult top = build_bvh(boxes, options.bvh, 1, 0, binary, order);
  WideBvhResult wide_top = collapse_bvh(binary, top.root, f.nodes);
  std::vector<int> instance_of_object(scene.objects.size(), -1);
  for (int i : order) {
    instance_of_object[object_of[i]] = static_cast<int>(f.instances.size());
    f.instances.push_back(unordered[i]);
    f.instance_textures.push_back(unordered_textures[i]);
  }
  flatten_textures(scene, f);
  flatten_object_lights(scene, instance_of_object, mesh_first, f);
  f.header.tlas_root = wide_top.root;
  f.stats.tlas_depth = wide_top.depth;
  f.stats.nodes = f.nodes.size();
  f.stats.triangles = f.triangles.size();
  f.stats.instances = f.instances.size();
  f.header.num_lights = static_cast<int>(f.lights.size());
  set_directional_distance(boxes, f.lights);
  // OpenCL cannot allocate empty buffers; a zeroed element keeps every array non-empty.
#define RT_PAD_ARRAY(Type, name) \
  if (f.name.empty()) f.name.emplace_back();
  RT_DATA_ARRAYS(RT_PAD_ARRAY)
#undef RT_PAD_ARRAY
  SceneHeader& h = f.header;
  h.background = to_float3(scene.background);
  h.ambient_light = to_float3(scene.ambient);
  h.shadow_epsilon = options.use_scene_epsilon ? static_cast<float>(scene.shadow_epsilon) : 0.0f;
  h.intersection_epsilon = static_cast<float>(scene.intersection_epsilon);
  h.max_depth = scene.max_depth;
  h.background_texture = scene.background_texture;
  h.num_instances = static_cast<int>(f.stats.instances);
  h.seed = options.seed;
  h.filter = options.filter;
  h.filter_sigma = options.filter_sigma;
  h.flags = (options.cull_back_faces ? RT_FLAG_CULL_BACK_FACES : 0) |
            (options.background_on_secondary_miss ? RT_FLAG_BACKGROUND_ON_SECONDARY_MISS : 0) |
            (options.fresnel_choice ? RT_FLAG_FRESNEL_CHOICE : 0) |
            (options.exact_ellipsoid_lights ? RT_FLAG_EXACT_ELLIPSOID_LIGHTS : 0);
  f.fast_math = options.fast_math;
  f.double_precision = options.double_precision;
  f.stats.bvh_build_ms =
      std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - start).count();
  return f;
}

void set_camera(FlatScene& flat, const SceneDesc& scene, int camera, const RenderOptions& options) {
  const CameraDesc& c = scene.cameras[camera];
  Camera& cam = flat.header.camera;
  Vec3d w = normalize(c.gaze) * -1.0;
  Vec3d u = normalize(cross(c.up, w));
  Vec3d v = cross(w, u);
  cam.position = to_float3(c.position);
  cam.u = to_float3(u);
  cam.v = to_float3(v);
  cam.w = to_float3(w);
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
  flat.header.features = scene_features(scene, camera, options);
}

int scene_features(const SceneDesc& scene, int camera, const RenderOptions& options) {
  int f = 0;
  std::vector<bool> used(scene.materials.size());
  for (const ObjectDesc& o : scene.objects) {
    f |= o.kind == ObjectDesc::kSphere ? RT_FEATURE_SPHERES : RT_FEATURE_TRIANGLES;
    if (!o.transform.is_identity()) f |= RT_FEATURE_TRANSFORMS;
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
  for (const Light& l : tagged_lights(scene)) f |= l.type;
  for (const ObjectDesc& o : scene.objects)
    if (o.emits) f |= o.kind == ObjectDesc::kSphere ? RT_LIGHT_SPHERE : RT_LIGHT_MESH;
  bool textured = scene.background_texture >= 0;
  for (const ObjectDesc& o : scene.objects) textured = textured || !o.textures.empty();
  if (textured) f |= RT_FEATURE_TEXTURES;
  const CameraDesc& c = scene.cameras[camera];
  if (c.aperture > 0) f |= RT_FEATURE_DEPTH_OF_FIELD;
  if ((options.spp > 0 ? options.spp : c.samples) > 1) f |= RT_FEATURE_MULTISAMPLE;
  return f;
}

}  // namespace rt
