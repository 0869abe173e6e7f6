// Object lights (LightMesh, LightSphere) in the device's tagged light array, and the one
// numbering of the lights that draw random numbers. Each emitting object becomes a Light
// naming its instance, after every light of the Lights block, and
// the instance names its light back (instance_lights) so a ray that hits it finds its
// radiance. A mesh light also gets the cumulative world-space areas of its triangles, in
// the order they lie in the triangle array, for sampling by area (cl/light/mesh_light.h).
#include <cmath>

#include "prepare_stages.h"

namespace rt {
namespace {

double determinant3(const Mat4& m) {
  return m(0, 0) * (m(1, 1) * m(2, 2) - m(1, 2) * m(2, 1)) -
         m(0, 1) * (m(1, 0) * m(2, 2) - m(1, 2) * m(2, 0)) +
         m(0, 2) * (m(1, 0) * m(2, 1) - m(1, 1) * m(2, 0));
}

Vec3d to_vec3d(float3 v) { return {v.x, v.y, v.z}; }

// Appends the mesh light's normalized cumulative areas (the last exactly 1) and returns its
// total world-space area. The areas are those of the float triangles the devices hold.
double append_area_cdf(const Triangle* tris, int count, const Mat4& transform,
                       PageAlignedVector<float>& cdf) {
  std::vector<double> sum(count);
  double total = 0;
  for (int k = 0; k < count; ++k) {
    Vec3d a = transform.point(to_vec3d(tris[k].v0));
    Vec3d b = transform.point(to_vec3d(tris[k].v1));
    Vec3d c = transform.point(to_vec3d(tris[k].v2));
    total += 0.5 * length(cross(b - a, c - a));
    sum[k] = total;
  }
  for (int k = 0; k < count; ++k)
    cdf.push_back(k + 1 == count ? 1.0f : static_cast<float>(sum[k] / total));
  return total;
}

}  // namespace

void append_object_lights(const SceneDesc& scene, const std::vector<int>& instance_of_object,
                          FlatScene& flat) {
  // Every instance has an entry (-1 for most), so a kernel compiled with every feature
  // reads valid data in scenes without object lights too.
  flat.instance_lights.assign(flat.instances.size(), -1);
  flat.light_cdf.clear();
  for (size_t i = 0; i < scene.objects.size(); ++i) {
    const ObjectDesc& o = scene.objects[i];
    if (!o.emits || instance_of_object[i] < 0) continue;
    Light l{};
    RT_LIGHT_INSTANCE(&l) = instance_of_object[i];
    l.emission = to_float3(o.radiance);
    if (o.kind == ObjectDesc::kSphere) {
      l.type = RT_LIGHT_SPHERE;
      RT_SPHERE_VOLUME_SCALE(&l) = static_cast<float>(std::fabs(determinant3(o.transform)));
    } else {
      l.type = RT_LIGHT_MESH;
      RT_MESH_FIRST(&l) = flat.meshes[o.mesh].first_triangle;
      RT_MESH_COUNT(&l) = static_cast<int>(scene.meshes[o.mesh].triangles.size());
      RT_MESH_CDF(&l) = static_cast<int>(flat.light_cdf.size());
      RT_LIGHT_SURFACE_AREA(&l) = static_cast<float>(append_area_cdf(
          &flat.triangles[RT_MESH_FIRST(&l)], RT_MESH_COUNT(&l), o.transform, flat.light_cdf));
    }
    flat.instance_lights[RT_LIGHT_INSTANCE(&l)] = static_cast<int>(flat.lights.size());
    flat.lights.push_back(l);
  }
}

void number_lights(PageAlignedVector<Light>& lights) {
  int sampled = 0;
  for (Light& l : lights)
    if (l.type != RT_LIGHT_POINT && l.type != RT_LIGHT_DIRECTIONAL && l.type != RT_LIGHT_SPOT)
      l.sample_index = sampled++;
}

}  // namespace rt
