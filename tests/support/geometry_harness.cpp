#include "support/geometry_harness.h"

#include <gtest/gtest.h>

#include <sstream>

namespace rt::test {

float3 F3(double x, double y, double z) {
  return make_float3(static_cast<float>(x), static_cast<float>(y), static_cast<float>(z));
}
float3 F3(Vec3d v) { return F3(v.x, v.y, v.z); }
Vec3d D3(float3 v) { return {v.x, v.y, v.z}; }
Vec3d RoundToFloat(Vec3d v) { return D3(F3(v)); }

std::string Str(float3 v) {
  std::ostringstream s;
  s.precision(9);
  s << "(" << v.x << ", " << v.y << ", " << v.z << ")";
  return s.str();
}

void ExpectVecNear(Vec3d a, Vec3d b, double tol) {
  EXPECT_NEAR(a.x, b.x, tol);
  EXPECT_NEAR(a.y, b.y, tol);
  EXPECT_NEAR(a.z, b.z, tol);
}

SceneDesc BaseScene() {
  SceneDesc s;
  CameraDesc cam;
  cam.position = {0, 0, 10};
  cam.gaze = {0, 0, -1};
  cam.up = {0, 1, 0};
  cam.width = cam.height = 1;
  s.cameras.push_back(cam);
  s.materials.push_back(Material{});
  return s;
}

int AddMesh(SceneDesc& s, const std::vector<Vec3d>& positions,
            const std::vector<std::array<int, 3>>& triangles) {
  MeshDesc m;
  m.element = "test mesh";
  m.positions = positions;
  m.triangles = triangles;
  s.meshes.push_back(m);
  return static_cast<int>(s.meshes.size()) - 1;
}

void AddMeshObject(SceneDesc& s, int mesh, const Mat4& transform) {
  ObjectDesc o;
  o.kind = ObjectDesc::kMesh;
  o.element = "test object";
  o.mesh = mesh;
  o.transform = transform;
  s.objects.push_back(o);
}

void AddSphere(SceneDesc& s, const Mat4& transform) {
  ObjectDesc o;
  o.kind = ObjectDesc::kSphere;
  o.element = "test sphere";
  o.transform = transform;
  s.objects.push_back(o);
}

FlatScene Flatten(const SceneDesc& s, int bins, int max_leaf) {
  RenderOptions opt;
  opt.bvh.bins = bins;
  opt.bvh.max_leaf = max_leaf;
  opt.camera_frame = false;  // The tests trace rays given in world coordinates.
  FlatScene f = prepare_scene(s, opt);
  prepare_camera(f, s, 0, opt);
  return f;
}

bool Trace(const FlatScene& f, float3 o, float3 d, float tmax, int cull, Hit* hit, int any_hit) {
  SceneData sd = f.view();
  Ray ray = MakeRay(o, d, tmax, 0.0f);
  return IntersectScene(&sd, &ray, any_hit, cull, hit) != 0;
}

TriHit HitTriangle(float3 o, float3 d, float3 p0, float3 p1, float3 p2, float tmax, int cull) {
  TriangleRay tr = MakeTriangleRay(o, d);
  TriHit h{0, -1.0f, -1.0f, -1.0f};
  h.hit = IntersectTriangle(&tr, p0, p1, p2, tmax, cull, &h.t, &h.b1, &h.b2);
  return h;
}

}  // namespace rt::test
