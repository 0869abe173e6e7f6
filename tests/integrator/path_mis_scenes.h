// Scenes for the tests of the path tracer's --path-estimator mis (cl/integrator/mis.h):
// quads, normalized Lambertian floors and boxes, square mesh lights, sphere lights and a
// constant sky, built in memory.
#pragma once

#include <cmath>

#include "cl/features.h"
#include "cl/light/environment_map.h"
#include "scene/scene.h"
#include "support/pixel_estimate.h"
#include "support/test_scene.h"

namespace rt::test::mis {

const int kNee = RT_FLAG_NEXT_EVENT, kImportance = RT_FLAG_IMPORTANCE_SAMPLING,
          kRoulette = RT_FLAG_RUSSIAN_ROULETTE;

// A quad (face) a b c d whose front (the side (b - a) x (c - a) points to, the side a LightMesh
// emits from) faces `front`.
inline MeshDesc Face(Vec3d a, Vec3d b, Vec3d c, Vec3d d, Vec3d front) {
  Vec3d e1{b.x - a.x, b.y - a.y, b.z - a.z}, e2{c.x - a.x, c.y - a.y, c.z - a.z};
  Vec3d n{e1.y * e2.z - e1.z * e2.y, e1.z * e2.x - e1.x * e2.z, e1.x * e2.y - e1.y * e2.x};
  MeshDesc m;
  m.positions = {a, b, c, d};
  if (n.x * front.x + n.y * front.y + n.z * front.z >= 0)
    m.triangles = {{0, 1, 2}, {0, 2, 3}};
  else
    m.triangles = {{0, 2, 1}, {0, 3, 2}};
  return m;
}

// A horizontal square of half-side a at height z, its front facing +z (up > 0) or -z.
inline MeshDesc Square(double a, double z, double up) {
  return Face({-a, -a, z}, {a, -a, z}, {a, a, z}, {-a, a, z}, {0, 0, up});
}

// Adds `mesh` as an object of material `material`; radiance le > 0 makes it a LightMesh.
inline void AddMesh(SceneDesc* s, const MeshDesc& mesh, int material, double le = 0) {
  s->meshes.push_back(mesh);
  ObjectDesc o;
  o.mesh = static_cast<int>(s->meshes.size()) - 1;
  o.material = material;
  if (le > 0) {
    o.emits = true;
    o.radiance = {le, le, le};
  }
  s->objects.push_back(o);
}

// A sphere of radius r at c of material `material`, a LightSphere of radiance le > 0.
inline void AddSphere(SceneDesc* s, Vec3d c, double r, int material, double le = 0) {
  ObjectDesc o;
  o.kind = ObjectDesc::kSphere;
  o.transform = Mat4::translation(c) * Mat4::scaling({r, r, r});
  o.material = material;
  if (le > 0) {
    o.emits = true;
    o.radiance = {le, le, le};
  }
  s->objects.push_back(o);
}

// A latitude-longitude sky of radiance `sky` (8 x 4 texels), plus `band` in its top row
// (directions within 45 degrees of +y), drawn by `sampler`.
inline void AddSky(SceneDesc* s, double sky, int sampler, double band = 0) {
  s->environment_map.width = 8;
  s->environment_map.height = 4;
  s->environment_map.channels = 3;
  s->environment_map.max_value = 0;
  s->environment_map.pixels.assign(8 * 4 * 3, static_cast<float>(sky));
  for (int i = 0; i < 8 * 3; ++i) s->environment_map.pixels[i] += static_cast<float>(band);
  Light l{};
  l.type = RT_LIGHT_ENVIRONMENT;
  RT_ENV_MAPPING(&l) = RT_ENV_LATLONG;
  RT_ENV_SAMPLING(&l) = sampler;
  s->lights.push_back(l);
}

// A path-traced point camera at eye looking down -z, MaxRecursionDepth `depth`.
inline SceneDesc Looking(Vec3d eye, int depth, int samples, int path_flags) {
  SceneDesc s;
  s.max_depth = depth;
  CameraDesc c = PointCamera(eye, samples);
  c.path_tracing = true;
  c.path_flags = path_flags;
  s.cameras.push_back(c);
  return s;
}

inline RenderOptions Mis(bool on = true) {
  RenderOptions o;
  o.mis = on;
  return o;
}

}  // namespace rt::test::mis
