#include "world_frame.h"

#include <algorithm>
#include <cmath>
#include <cstring>
#include <stdexcept>
#include <string>

namespace rt {

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

// Whether the rows' linear part is exactly the identity, bit for bit: a -0 off the diagonal
// would give some directions another sign of zero than +0 gives (RT_INSTANCE_TRANSLATION).
bool identity_linear_part(const float4 rows[3]) {
  for (int r = 0; r < 3; ++r) {
    const float linear[3] = {rows[r].x, rows[r].y, rows[r].z};
    for (int c = 0; c < 3; ++c) {
      const float want = r == c ? 1.0f : 0.0f;
      if (std::memcmp(&linear[c], &want, sizeof want) != 0) return false;
    }
  }
  return true;
}

}  // namespace

bool keeps_world_direction(const Mat4& to_frame) {
  if (to_frame.is_identity()) return true;
  bool ok;
  const Mat4 inv = to_frame.affine_inverse(&ok);
  float4 rows[3];
  set_rows(rows, inv);
  return ok && identity_linear_part(rows);
}

namespace {

bool finite_rows(const float4 rows[3]) {
  for (int r = 0; r < 3; ++r)
    if (!std::isfinite(rows[r].x) || !std::isfinite(rows[r].y) || !std::isfinite(rows[r].z) ||
        !std::isfinite(rows[r].w))
      return false;
  return true;
}

// The position of a light stored in float by the loader, moved into the frame in double.
float3 to_frame(float3 p, Vec3d origin) {
  return to_float3(Vec3d{p.x - origin.x, p.y - origin.y, p.z - origin.z});
}

}  // namespace

std::vector<Light> frame_lights(const SceneDesc& scene, Vec3d origin) {
  std::vector<Light> out;
  for (const PointLight& p : scene.point_lights) {
    Light l{};
    l.type = RT_LIGHT_POINT;
    l.position = to_float3(p.position - origin);
    l.emission = p.intensity;
    out.push_back(l);
  }
  for (const AreaLight& a : scene.area_lights) {
    Light l{};
    l.type = RT_LIGHT_AREA;
    l.position = to_float3(a.corner - origin);
    l.edge1 = a.edge1;
    l.edge2 = a.edge2;
    l.normal = a.normal;
    l.emission = a.radiance;
    RT_LIGHT_SURFACE_AREA(&l) = a.area;
    out.push_back(l);
  }
  for (Light l : scene.lights) {
    // Directional lights have no position; spot lights carry the loader's float one.
    if (l.type == RT_LIGHT_SPOT) l.position = to_frame(l.position, origin);
    out.push_back(l);
  }
  for (size_t i = 0; i < out.size(); ++i) {
    const float3 p = out[i].position;
    if (!std::isfinite(p.x) || !std::isfinite(p.y) || !std::isfinite(p.z))
      throw std::invalid_argument("Lights: light " + std::to_string(i + 1) +
                                  " lies beyond float range from the camera");
  }
  return out;
}

Vec3d mesh_frame_origin(const MeshDesc& mesh) {
  if (mesh.positions.empty()) return {};
  Vec3d lo = mesh.positions[0], hi = lo;
  for (const Vec3d& p : mesh.positions) {
    lo = {std::min(lo.x, p.x), std::min(lo.y, p.y), std::min(lo.z, p.z)};
    hi = {std::max(hi.x, p.x), std::max(hi.y, p.y), std::max(hi.z, p.z)};
  }
  const double extent = std::max({hi.x - lo.x, hi.y - lo.y, hi.z - lo.z});
  if (!(extent > 0) || !std::isfinite(extent)) return {};
  const double grid = std::exp2(std::ceil(std::log2(extent)));
  auto snap = [&](double lo_a, double hi_a) {
    return std::round((0.5 * lo_a + 0.5 * hi_a) / grid) * grid + 0.0;  // + 0.0: no -0.
  };
  return {snap(lo.x, hi.x), snap(lo.y, hi.y), snap(lo.z, hi.z)};
}

Mat4 object_to_frame(const ObjectDesc& object, Vec3d mesh_origin, Vec3d world_origin) {
  Mat4 m = object.transform;
  if (!is_zero(mesh_origin)) m = m * Mat4::translation(mesh_origin);
  if (!is_zero(world_origin)) m = Mat4::translation(world_origin * -1.0) * m;
  return m;
}

FramedInstances frame_instances(const SceneDesc& scene, const std::vector<FlatMesh>& meshes,
                                Vec3d origin) {
  FramedInstances out;
  Aabb unit;
  unit.grow(-1, -1, -1);
  unit.grow(1, 1, 1);
  for (const ObjectDesc& o : scene.objects) {
    if (!is_placed(o, meshes)) continue;  // Nothing left after degenerates.
    bool sphere = o.kind == ObjectDesc::kSphere;
    const FlatMesh* mesh = sphere ? nullptr : &meshes[o.mesh];
    Instance inst{};
    const Mat4 to_frame = object_to_frame(o, sphere ? Vec3d{} : mesh->origin, origin);
    bool ok;
    Mat4 inv = to_frame.affine_inverse(&ok);
    // The loader rejects singular transforms; a caller building scenes in code must too.
    if (!ok) throw std::invalid_argument(o.element + ": singular transform");
    set_rows(inst.world_to_object, inv);
    set_rows(inst.object_to_world, to_frame);
    // Each position fits float alone (the loader's check), but two far apart need not fit
    // as a difference: an object 3e38 on one side of the camera and the camera 3e38 on the
    // other.
    if (!finite_rows(inst.object_to_world) || !finite_rows(inst.world_to_object))
      throw std::invalid_argument(o.element + ": lies beyond float range from the camera");
    inst.motion = to_float3(o.motion);
    inst.texture_origin = to_float3(sphere ? origin : mesh->origin);
    inst.kind = sphere ? RT_INSTANCE_SPHERE : RT_INSTANCE_MESH;
    inst.blas_root = sphere ? -1 : mesh->blas_root;
    inst.material = o.material;
    const bool transformed = !to_frame.is_identity();
    inst.flags = (transformed ? RT_INSTANCE_TRANSFORMED : 0) |
                 (transformed && keeps_world_direction(to_frame) ? RT_INSTANCE_TRANSLATION : 0) |
                 (!sphere && scene.meshes[o.mesh].smooth ? RT_INSTANCE_SMOOTH : 0) |
                 (is_zero(o.motion) ? 0 : RT_INSTANCE_MOVING);
    out.instances.push_back(inst);
    out.object.push_back(static_cast<int>(&o - scene.objects.data()));
    InstanceTextures it;
    for (int k = 0; k < RT_MAX_OBJECT_TEXTURES; ++k)
      it.ids[k] = k < static_cast<int>(o.textures.size()) ? o.textures[k] : -1;
    out.textures.push_back(it);
    out.boxes.push_back(transformed_box(sphere ? unit : mesh->box, to_frame, o.motion));
  }
  return out;
}

void set_directional_distance(const std::vector<Aabb>& boxes, PageAlignedVector<Light>& lights) {
  Aabb world;
  for (const Aabb& b : boxes) world.grow(b);
  double diagonal = 0;
  for (int a = 0; a < 3 && !world.empty(); ++a)
    diagonal += (double(world.hi[a]) - world.lo[a]) * (double(world.hi[a]) - world.lo[a]);
  float distance = static_cast<float>(std::max(1.0, 2.0 * std::sqrt(diagonal)));
  for (Light& l : lights)
    if (l.type == RT_LIGHT_DIRECTIONAL || l.type == RT_LIGHT_ENVIRONMENT)
      RT_LIGHT_REACH(&l) = distance;
}

}  // namespace rt
