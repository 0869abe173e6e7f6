// Helpers of the geometry tests (triangle, sphere, watertightness, transforms, ray offsets,
// BVH): conversions between float3 and double vectors, small scenes built in code, and
// tracing through the full scene path (SceneDesc -> prepare_scene, prepare_camera ->
// IntersectScene).
//
// Tolerances in those tests: cases whose operands are small dyadic numbers are exact in float
// and are compared with ==. Everything else is compared with a double-precision reference and
// a tolerance stated next to the check, derived from float's 2^-24 relative rounding.
#pragma once

#include <array>
#include <string>
#include <vector>

#include "cl/bvh/bvh.h"
#include "cl/geometry/surface.h"
#include "prepare/flat_scene.h"
#include "util/mat4.h"

namespace rt::test {

constexpr float kInf = RT_INFINITY;

float3 F3(double x, double y, double z);
float3 F3(Vec3d v);
Vec3d D3(float3 v);
// `v` rounded to float, back in double.
Vec3d RoundToFloat(Vec3d v);
// "(x, y, z)" with 9 significant digits, for failure messages.
std::string Str(float3 v);
void ExpectVecNear(Vec3d a, Vec3d b, double tol);

// One 1 x 1 pixel camera at (0, 0, 10) looking down -z, one default material, no objects.
SceneDesc BaseScene();
// Adds a mesh (not yet an object) and returns its index.
int AddMesh(SceneDesc& s, const std::vector<Vec3d>& positions,
            const std::vector<std::array<int, 3>>& triangles);
void AddMeshObject(SceneDesc& s, int mesh, const Mat4& transform);
void AddSphere(SceneDesc& s, const Mat4& transform);
// Flattens `s` with the given BVH settings and sets its first camera.
FlatScene Flatten(const SceneDesc& s, int bins = 16, int max_leaf = 4);

// IntersectScene on the flattened scene; true on a hit.
bool Trace(const FlatScene& f, float3 o, float3 d, float tmax, int cull, Hit* hit, int any_hit = 0);

struct TriHit {
  int hit;
  float t, b1, b2;
};
// IntersectTriangle on one triangle.
TriHit HitTriangle(float3 o, float3 d, float3 p0, float3 p1, float3 p2, float tmax, int cull);

}  // namespace rt::test
