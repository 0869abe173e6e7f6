// Scene building for the stability tests (tests/stability/): scenes are assembled in code
// (no XML) from materials, quads, boxes, spheres, lights and cameras, and can be mapped by
// x -> s x + t to test scale and translation invariance.
#pragma once

#include <array>
#include <cmath>
#include <cstdint>
#include <string>
#include <vector>

#include "prepare/flat_scene.h"
#include "util/mat4.h"
#include "scene/scene.h"

namespace stab {

using rt::Mat4;
using rt::Vec3d;

inline float3 F3(Vec3d v) { return rt::to_float3(v); }
inline Vec3d V(double x, double y, double z) { return Vec3d{x, y, z}; }
inline Vec3d Gray(double g) { return Vec3d{g, g, g}; }

// Blinn-Phong surface: ka is multiplied by the scene's ambient light.
inline Material Plain(Vec3d kd, Vec3d ks = {}, double exponent = 1, Vec3d ka = {}) {
  Material m{};
  m.type = RT_MATERIAL_PLAIN;
  m.ambient = F3(ka);
  m.diffuse = F3(kd);
  m.specular = F3(ks);
  m.phong_exponent = static_cast<float>(exponent);
  m.refraction_index = 1;
  return m;
}

// A perfect mirror with no local shading of its own.
inline Material Mirror(Vec3d reflectance, double roughness = 0) {
  Material m = Plain({});
  m.type = RT_MATERIAL_MIRROR;
  m.mirror = F3(reflectance);
  m.roughness = static_cast<float>(roughness);
  return m;
}

inline Material Conductor(double eta, double k, double roughness = 0) {
  Material m = Plain({});
  m.type = RT_MATERIAL_CONDUCTOR;
  m.mirror = F3(Gray(1));
  m.refraction_index = static_cast<float>(eta);
  m.absorption_index = static_cast<float>(k);
  m.roughness = static_cast<float>(roughness);
  return m;
}

// Glass with no local shading (ambient, diffuse and specular all zero).
inline Material Dielectric(double ior, Vec3d absorption = {}, double roughness = 0) {
  Material m = Plain({});
  m.type = RT_MATERIAL_DIELECTRIC;
  m.refraction_index = static_cast<float>(ior);
  m.absorption = F3(absorption);
  m.roughness = static_cast<float>(roughness);
  return m;
}

class Builder {
 public:
  Builder() {
    s_.shadow_epsilon = 1e-3;
    s_.intersection_epsilon = 1e-6;
    s_.max_depth = 6;
  }

  rt::SceneDesc& scene() { return s_; }
  const rt::SceneDesc& scene() const { return s_; }

  int material(const Material& m) {
    s_.materials.push_back(m);
    return static_cast<int>(s_.materials.size()) - 1;
  }

  // A mesh object with identity transform (vertices are stored in world space).
  int mesh(std::vector<Vec3d> positions, std::vector<std::array<int, 3>> triangles, int material,
           bool smooth = false, Vec3d motion = {}) {
    rt::MeshDesc m;
    m.element = "Mesh " + std::to_string(s_.meshes.size());
    m.positions = std::move(positions);
    m.triangles = std::move(triangles);
    m.smooth = smooth;
    s_.meshes.push_back(std::move(m));
    rt::ObjectDesc o;
    o.kind = rt::ObjectDesc::kMesh;
    o.element = s_.meshes.back().element;
    o.mesh = static_cast<int>(s_.meshes.size()) - 1;
    o.material = material;
    o.motion = motion;
    s_.objects.push_back(o);
    return static_cast<int>(s_.objects.size()) - 1;
  }

  // Quad a-b-c-d, counter-clockwise seen from the side its normal points to.
  int quad(Vec3d a, Vec3d b, Vec3d c, Vec3d d, int material) {
    return mesh({a, b, c, d}, {{{0, 1, 2}}, {{0, 2, 3}}}, material);
  }

  // Axis-aligned box as a closed mesh with outward normals.
  int box(Vec3d lo, Vec3d hi, int material) {
    std::vector<Vec3d> p;
    for (int i = 0; i < 8; ++i)
      p.push_back({(i & 1) ? hi.x : lo.x, (i & 2) ? hi.y : lo.y, (i & 4) ? hi.z : lo.z});
    std::vector<std::array<int, 3>> t = {
        {{0, 2, 3}}, {{0, 3, 1}},  // z = lo (normal -z)
        {{4, 5, 7}}, {{4, 7, 6}},  // z = hi
        {{0, 1, 5}}, {{0, 5, 4}},  // y = lo
        {{2, 6, 7}}, {{2, 7, 3}},  // y = hi
        {{0, 4, 6}}, {{0, 6, 2}},  // x = lo
        {{1, 3, 7}}, {{1, 7, 5}},  // x = hi
    };
    return mesh(p, t, material);
  }

  int sphere(Vec3d centre, double radius, int material, Vec3d motion = {}) {
    rt::ObjectDesc o;
    o.kind = rt::ObjectDesc::kSphere;
    o.element = "Sphere " + std::to_string(s_.objects.size());
    o.material = material;
    o.transform = Mat4::translation(centre) * Mat4::scaling({radius, radius, radius});
    o.motion = motion;
    s_.objects.push_back(o);
    return static_cast<int>(s_.objects.size()) - 1;
  }

  void point_light(Vec3d position, Vec3d intensity) {
    PointLight l{};
    l.position = position;
    l.intensity = F3(intensity);
    s_.point_lights.push_back(l);
  }

  // Parallelogram corner + s e1 + t e2 emitting `radiance` from both faces.
  void area_light(Vec3d corner, Vec3d e1, Vec3d e2, Vec3d radiance) {
    AreaLight a{};
    Vec3d n = rt::cross(e1, e2);
    a.corner = corner;
    a.edge1 = F3(e1);
    a.edge2 = F3(e2);
    a.normal = F3(rt::normalize(n));
    a.area = static_cast<float>(rt::length(n));
    a.radiance = F3(radiance);
    s_.area_lights.push_back(a);
  }

  // Pinhole camera looking from `position` at `target`; the film spans +-half_w x +-half_h
  // at distance `near`.
  int camera(Vec3d position, Vec3d target, Vec3d up, double half_w, double half_h, double near,
             int width, int height) {
    rt::CameraDesc c;
    c.image_name = "cam" + std::to_string(s_.cameras.size()) + ".png";
    c.position = position;
    c.gaze = rt::normalize(target - position);
    c.up = up;
    c.left = -half_w;
    c.right = half_w;
    c.bottom = -half_h;
    c.top = half_h;
    c.near_distance = near;
    c.width = width;
    c.height = height;
    c.samples = 1;
    s_.cameras.push_back(c);
    return static_cast<int>(s_.cameras.size()) - 1;
  }

 private:
  rt::SceneDesc s_;
};

// The scene mapped by x -> s x + t: geometry, camera (near plane, film and lens too),
// lights (point intensities by s^2 so I / d^2 is unchanged, area lights by their edges so
// radiance is unchanged), motion by s and absorption by 1 / s. The scene's own epsilons
// stay as the file gives them: they are absolute lengths. Mesh transforms must be the
// identity (the vertices move).
inline rt::SceneDesc MapScene(const rt::SceneDesc& in, double s, Vec3d t) {
  auto p = [&](Vec3d v) { return v * s + t; };
  auto vf = [&](float3 v, double k) { return F3(Vec3d{v.x * k, v.y * k, v.z * k}); };
  rt::SceneDesc o = in;
  for (auto& m : o.meshes)
    for (auto& v : m.positions) v = p(v);
  Mat4 a = Mat4::translation(t) * Mat4::scaling({s, s, s});
  for (auto& ob : o.objects) {
    if (ob.kind == rt::ObjectDesc::kSphere) ob.transform = a * ob.transform;
    ob.motion = ob.motion * s;
  }
  for (auto& m : o.materials) m.absorption = vf(m.absorption, 1.0 / s);
  for (auto& l : o.point_lights) {
    l.position = p(l.position);
    l.intensity = vf(l.intensity, s * s);
  }
  for (auto& l : o.area_lights) {
    l.corner = p(l.corner);
    l.edge1 = vf(l.edge1, s);
    l.edge2 = vf(l.edge2, s);
    l.area = static_cast<float>(static_cast<double>(l.area) * s * s);
  }
  for (auto& c : o.cameras) {
    c.position = p(c.position);
    c.left *= s;
    c.right *= s;
    c.bottom *= s;
    c.top *= s;
    c.near_distance *= s;
    c.aperture *= s;
    c.focus_distance *= s;
  }
  return o;
}

// A small stage (about 12 units across) with every kind of secondary ray: shadows from a
// point light and an area light, a mirror sphere, a glass sphere with absorption, a thin
// panel 0.1 above the floor, a box standing on the floor and a moving sphere (the scale and
// the camera tests).

constexpr int kStageSize = 40;
constexpr int kStageSpp = 24;

inline rt::SceneDesc Stage() {
  Builder b;
  rt::SceneDesc& s = b.scene();
  s.background = V(12, 18, 30);
  s.ambient = Gray(6);
  int floor = b.material(Plain(Gray(0.7), Gray(0.1), 10, Gray(1)));
  int wall = b.material(Plain(V(0.5, 0.6, 0.8), {}, 1, Gray(1)));
  int red = b.material(Plain(V(0.8, 0.2, 0.2), Gray(0.4), 40, Gray(1)));
  int green = b.material(Plain(V(0.2, 0.8, 0.3), {}, 1, Gray(1)));
  int mirror = b.material(Mirror(Gray(0.85)));
  int glass = b.material(Dielectric(1.5, V(0.3, 0.1, 0.05)));
  b.quad(V(-6, 0, -4), V(-6, 0, 6), V(6, 0, 6), V(6, 0, -4), floor);
  b.quad(V(-6, 0, -4), V(6, 0, -4), V(6, 6, -4), V(-6, 6, -4), wall);
  b.sphere(V(-1.6, 1, -0.8), 1, red);
  b.sphere(V(1.9, 0.8, -1.8), 0.8, mirror);
  b.sphere(V(0.2, 0.55, 1.6), 0.55, glass);
  b.quad(V(1.2, 0.1, 0.6), V(1.2, 0.1, 2.4), V(3.0, 0.1, 2.4), V(3.0, 0.1, 0.6), green);
  b.box(V(-3.6, 0, 0.6), V(-2.9, 0.9, 1.3), green);
  b.sphere(V(-0.4, 0.3, 3.2), 0.3, red, V(0.8, 0, 0));
  b.point_light(V(2.5, 5.5, 4), V(14000, 13000, 12000));
  b.area_light(V(-2.6, 4.6, -0.4), V(1.2, 0, 0), V(0, 0, 1.2), V(700, 700, 650));
  b.camera(V(0, 3.2, 8.5), V(0, 0.7, 0), V(0, 1, 0), 0.55, 0.55, 1, kStageSize, kStageSize);
  return s;
}

// An ambient-only material under an ambient light of kAmbient: a sample that hits gives
// exactly kAmbient, one that slips through the black background (coverage tests).

constexpr double kAmbient = 100;

inline Material AmbientOnly() { return Plain({}, {}, 1, Gray(1)); }

// Mirror, conductor and glass spheres of one roughness over a floor, with a point and an
// area light, so random numbers matter (the roughness, lens and light-value tests).
inline rt::SceneDesc GlossyScene(double roughness) {
  Builder b;
  b.scene().ambient = Gray(4);
  b.scene().background = V(10, 12, 20);
  int floor = b.material(Plain(V(0.6, 0.6, 0.5), Gray(0.2), 15, Gray(1)));
  int mirror = b.material(Mirror(V(0.9, 0.8, 0.7), roughness));
  int conductor = b.material(Conductor(0.2, 3.0, roughness));
  int glass = b.material(Dielectric(1.5, V(0.2, 0.1, 0.05), roughness));
  b.quad(V(-5, 0, -5), V(-5, 0, 5), V(5, 0, 5), V(5, 0, -5), floor);
  b.sphere(V(-1.2, 0.6, 0), 0.6, mirror);
  b.sphere(V(0.2, 0.6, -0.8), 0.6, conductor);
  b.sphere(V(1.2, 0.6, 0.6), 0.6, glass);
  b.point_light(V(2, 4, 3), Gray(3000));
  b.area_light(V(-1, 3, -1), V(1, 0, 0), V(0, 0, 1), Gray(400));
  b.camera(V(0, 2, 5), V(0, 0.5, 0), V(0, 1, 0), 0.5, 0.4, 1, 40, 32);
  return b.scene();
}

}  // namespace stab
