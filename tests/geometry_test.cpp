// Tests for the shared geometry code: the watertight ray-triangle test, the unit-sphere test,
// transforms, robust ray origins, BVH construction, and two-level traversal through the full
// scene path (SceneDesc -> flatten_scene -> IntersectScene / ComputeSurface).
//
// Tolerances: cases whose operands are small dyadic numbers are exact in float and are
// compared with ==. Everything else is compared with a double-precision reference and a
// tolerance stated next to the check, derived from float's 2^-24 relative rounding.
#include <gtest/gtest.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdint>
#include <limits>
#include <map>
#include <numeric>
#include <random>
#include <sstream>
#include <string>
#include <utility>
#include <vector>

#include "bvh_build.h"
#include "cl/bvh.h"
#include "cl/surface.h"
#include "flat_scene.h"
#include "mat4.h"

namespace rt {
namespace {

constexpr float kInf = RT_INFINITY;

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

// ------------------------------------------------------------------------------------------
// Scene plumbing
// ------------------------------------------------------------------------------------------

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

FlatScene Flatten(const SceneDesc& s, int bins = 16, int max_leaf = 4) {
  RenderOptions opt;
  opt.bvh.bins = bins;
  opt.bvh.max_leaf = max_leaf;
  opt.camera_frame = false;  // The tests trace rays given in world coordinates.
  FlatScene f = flatten_scene(s, opt);
  set_camera(f, s, 0, opt);
  return f;
}

bool Trace(const FlatScene& f, float3 o, float3 d, float tmax, int cull, Hit* hit,
           int any_hit = 0) {
  SceneData sd = f.view();
  return IntersectScene(&sd, MakeRay(o, d, tmax, 0.0f), any_hit, cull, hit) != 0;
}

struct TriHit {
  int hit;
  float t, b1, b2;
};

TriHit HitTriangle(float3 o, float3 d, float3 p0, float3 p1, float3 p2, float tmax, int cull) {
  TriangleRay tr = MakeTriangleRay(o, d);
  TriHit h{0, -1.0f, -1.0f, -1.0f};
  h.hit = IntersectTriangle(&tr, p0, p1, p2, tmax, cull, &h.t, &h.b1, &h.b2);
  return h;
}

// ------------------------------------------------------------------------------------------
// IntersectTriangle
// ------------------------------------------------------------------------------------------

// The triangle (-1,-1), (1,-1), (-1,1) in the plane of axes (a, b) = (k+1, k+2) at
// coordinate `plane` along axis k. Its geometric normal cross(v1-v0, v2-v0) is 4 e_k.
std::array<float3, 3> AxisTriangle(int k, float plane) {
  std::array<float3, 3> out;
  const float ab[3][2] = {{-1, -1}, {1, -1}, {-1, 1}};
  for (int i = 0; i < 3; ++i) {
    float c[3];
    c[k] = plane;
    c[(k + 1) % 3] = ab[i][0];
    c[(k + 2) % 3] = ab[i][1];
    out[i] = make_float3(c[0], c[1], c[2]);
  }
  return out;
}

float3 AxisPoint(int k, float along, float a, float b) {
  float c[3];
  c[k] = along;
  c[(k + 1) % 3] = a;
  c[(k + 2) % 3] = b;
  return make_float3(c[0], c[1], c[2]);
}

TEST(GeometryTriangle, AxisAlignedInteriorHitIsExactForEveryAxisAndDirection) {
  for (int k = 0; k < 3; ++k)
    for (float sign : {-1.0f, 1.0f}) {
      SCOPED_TRACE("axis " + std::to_string(k) + " sign " + std::to_string(sign));
      auto v = AxisTriangle(k, 2.0f * sign);
      // From in-plane position (-0.5, -0.25): b1 = 0.25, b2 = 0.375, distance 2. All inputs
      // are dyadic, so every intermediate of the sheared test is exact.
      float3 o = AxisPoint(k, 0.0f, -0.5f, -0.25f);
      float3 d = AxisPoint(k, sign, 0.0f, 0.0f);
      TriHit h = HitTriangle(o, d, v[0], v[1], v[2], kInf, 0);
      ASSERT_EQ(h.hit, 1);
      EXPECT_EQ(h.t, 2.0f);
      EXPECT_EQ(h.b1, 0.25f);
      EXPECT_EQ(h.b2, 0.375f);
      // t is measured in units of the (non-unit) direction.
      h = HitTriangle(o, d * 4.0f, v[0], v[1], v[2], kInf, 0);
      ASSERT_EQ(h.hit, 1);
      EXPECT_EQ(h.t, 0.5f);
      EXPECT_EQ(h.b1, 0.25f);
      EXPECT_EQ(h.b2, 0.375f);
      // Another interior point: (0.25, -0.5) -> b1 = 0.625, b2 = 0.25.
      h = HitTriangle(AxisPoint(k, 0.0f, 0.25f, -0.5f), d, v[0], v[1], v[2], kInf, 0);
      ASSERT_EQ(h.hit, 1);
      EXPECT_EQ(h.t, 2.0f);
      EXPECT_EQ(h.b1, 0.625f);
      EXPECT_EQ(h.b2, 0.25f);
    }
}

TEST(GeometryTriangle, MissesOutsideAndCountsExactEdgesAsInside) {
  auto v = AxisTriangle(2, -2.0f);  // Plane z = -2, ray along -z.
  const float3 d = make_float3(0, 0, -1);
  auto hit_at = [&](float x, float y) {
    return HitTriangle(make_float3(x, y, 0), d, v[0], v[1], v[2], kInf, 0).hit;
  };
  // The hypotenuse is x + y = 0; one 1/128 step either side of it.
  EXPECT_EQ(hit_at(0.0078125f, 0.0f), 0);
  EXPECT_EQ(hit_at(-0.0078125f, 0.0f), 1);
  EXPECT_EQ(hit_at(0.25f, -0.25f), 1);  // Exactly on the hypotenuse.
  EXPECT_EQ(hit_at(-1.0f, 0.0f), 1);    // Exactly on the edge x = -1.
  EXPECT_EQ(hit_at(-1.0f, -1.0f), 1);   // Exactly on vertex v0.
  EXPECT_EQ(hit_at(-1.0078125f, 0.0f), 0);
  EXPECT_EQ(hit_at(0.0f, -1.0078125f), 0);
  EXPECT_EQ(hit_at(1.5f, 0.0f), 0);
  EXPECT_EQ(hit_at(-0.5f, 3.0f), 0);
  EXPECT_EQ(hit_at(5.0f, 5.0f), 0);
  // The edge hit reports barycentrics on the edge: (0.25, -0.25) -> b1 = 0.625, b2 = 0.375.
  TriHit h = HitTriangle(make_float3(0.25f, -0.25f, 0), d, v[0], v[1], v[2], kInf, 0);
  EXPECT_EQ(h.b1 + h.b2, 1.0f);
  EXPECT_EQ(h.b1, 0.625f);
}

TEST(GeometryTriangle, DistanceMustLieStrictlyBetweenZeroAndTmax) {
  auto v = AxisTriangle(2, -2.0f);
  const float3 o = make_float3(-0.5f, -0.25f, 0.0f);
  const float3 down = make_float3(0, 0, -1), up = make_float3(0, 0, 1);
  EXPECT_EQ(HitTriangle(o, up, v[0], v[1], v[2], kInf, 0).hit, 0);    // Behind the origin.
  EXPECT_EQ(HitTriangle(o, down, v[0], v[1], v[2], 2.0f, 0).hit, 0);  // t == tmax.
  EXPECT_EQ(HitTriangle(o, down, v[0], v[1], v[2], 1.0f, 0).hit, 0);
  TriHit h = HitTriangle(o, down, v[0], v[1], v[2], std::nextafter(2.0f, 3.0f), 0);
  EXPECT_EQ(h.hit, 1);
  EXPECT_EQ(h.t, 2.0f);
  // Origin on the plane: t == 0 is not a hit, in either direction.
  const float3 on = make_float3(-0.5f, -0.25f, -2.0f);
  EXPECT_EQ(HitTriangle(on, down, v[0], v[1], v[2], kInf, 0).hit, 0);
  EXPECT_EQ(HitTriangle(on, up, v[0], v[1], v[2], kInf, 0).hit, 0);
  // Back-facing side, same rules (det < 0 branch).
  const float3 below = make_float3(-0.5f, -0.25f, -4.0f);
  h = HitTriangle(below, up, v[0], v[1], v[2], kInf, 0);
  EXPECT_EQ(h.hit, 1);
  EXPECT_EQ(h.t, 2.0f);
  EXPECT_EQ(HitTriangle(below, up, v[0], v[1], v[2], 2.0f, 0).hit, 0);
  EXPECT_EQ(HitTriangle(below, down, v[0], v[1], v[2], kInf, 0).hit, 0);
}

TEST(GeometryTriangle, ParallelRaysMiss) {
  auto v = AxisTriangle(2, -2.0f);
  // In the plane of the triangle, crossing its interior: every edge function is zero.
  const float3 dirs[] = {make_float3(1, 0, 0), make_float3(0, -1, 0), make_float3(0.6f, 0.8f, 0),
                         make_float3(-3, 1, 0)};
  for (float3 d : dirs) {
    SCOPED_TRACE(Str(d));
    float3 o = make_float3(-0.5f, -0.25f, -2.0f) - d * 4.0f;
    EXPECT_EQ(HitTriangle(o, d, v[0], v[1], v[2], kInf, 0).hit, 0);
    // Parallel above and below the plane.
    EXPECT_EQ(HitTriangle(o + make_float3(0, 0, 0.5f), d, v[0], v[1], v[2], kInf, 0).hit, 0);
    EXPECT_EQ(HitTriangle(o - make_float3(0, 0, 0.5f), d, v[0], v[1], v[2], kInf, 0).hit, 0);
  }
}

TEST(GeometryTriangle, CullSkipsOnlyBackFacesForAxisRays) {
  for (int k = 0; k < 3; ++k)
    for (float plane : {-2.0f, 2.0f})
      for (float sign : {-1.0f, 1.0f}) {
        SCOPED_TRACE("axis " + std::to_string(k) + " plane " + std::to_string(plane) + " sign " +
                     std::to_string(sign));
        // The normal is +e_k; the ray origin sits on the side of the normal when the plane
        // is at -2 and the ray comes from 0, or when it is at +2 and the ray comes from 4.
        auto v = AxisTriangle(k, plane);
        float start = plane - 2.0f * sign;  // Two units before the plane, moving by sign.
        float3 o = AxisPoint(k, start, -0.5f, -0.25f);
        float3 d = AxisPoint(k, sign, 0.0f, 0.0f);
        bool front = start > plane;  // Origin on the side the normal points to.
        EXPECT_EQ(HitTriangle(o, d, v[0], v[1], v[2], kInf, 0).hit, 1);
        EXPECT_EQ(HitTriangle(o, d, v[0], v[1], v[2], kInf, 1).hit, front ? 1 : 0);
      }
}

// Double-precision Möller-Trumbore for reference.
struct RefHit {
  bool valid;  // False when the ray is (nearly) parallel to the plane.
  double t, b1, b2;
};
RefHit ReferenceTriangle(Vec3d o, Vec3d d, Vec3d p0, Vec3d p1, Vec3d p2) {
  Vec3d e1 = p1 - p0, e2 = p2 - p0;
  Vec3d pv = cross(d, e2);
  double det = dot(e1, pv);
  if (std::fabs(det) < 1e-12) return {false, 0, 0, 0};
  Vec3d tv = o - p0;
  double b1 = dot(tv, pv) / det;
  Vec3d qv = cross(tv, e1);
  double b2 = dot(d, qv) / det;
  double t = dot(e2, qv) / det;
  return {true, t, b1, b2};
}

TEST(GeometryTriangle, AgreesWithDoublePrecisionReferenceInGeneralPosition) {
  std::mt19937 rng(12345);
  std::uniform_real_distribution<double> u(-1.0, 1.0);
  int hits = 0, misses = 0;
  for (int i = 0; i < 20000; ++i) {
    Vec3d p[3];
    for (auto& q : p) q = RoundToFloat({u(rng), u(rng), u(rng)});
    Vec3d o = RoundToFloat({3 * u(rng), 3 * u(rng), 3 * u(rng)});
    // Aim at a point of the plane with barycentrics in [-0.5, 1.5]: about half inside.
    double c1 = 0.5 + u(rng), c2 = 0.5 + u(rng);
    Vec3d target = p[0] + (p[1] - p[0]) * c1 + (p[2] - p[0]) * c2;
    Vec3d d = RoundToFloat((target - o) * (0.25 + 2 * std::fabs(u(rng))));
    RefHit r = ReferenceTriangle(o, d, p[0], p[1], p[2]);
    Vec3d n = cross(p[1] - p[0], p[2] - p[0]);
    double cosang = std::fabs(dot(n, d)) / (length(n) * length(d));
    if (!r.valid || cosang < 1e-2 || length(n) < 1e-3) continue;
    TriHit h = HitTriangle(F3(o), F3(d), F3(p[0]), F3(p[1]), F3(p[2]), kInf, 0);
    double bmin = std::min({1 - r.b1 - r.b2, r.b1, r.b2});
    // Away from the edges (1e-4 in barycentrics, far above float rounding) the answer is
    // unambiguous; t and the barycentrics must match to float accuracy (relative 1e-5
    // leaves room for the ~10 roundings of the sheared test on ill-conditioned rays).
    if (bmin > 1e-4 && r.t > 1e-3) {
      ++hits;
      ASSERT_EQ(h.hit, 1) << "ray " << i;
      EXPECT_NEAR(h.t, r.t, 1e-5 * r.t + 1e-6) << "ray " << i;
      EXPECT_NEAR(h.b1, r.b1, 1e-4) << "ray " << i;
      EXPECT_NEAR(h.b2, r.b2, 1e-4) << "ray " << i;
    } else if (bmin < -1e-4 || r.t < -1e-3) {
      ++misses;
      ASSERT_EQ(h.hit, 0) << "ray " << i << " ref t " << r.t << " bmin " << bmin;
    }
  }
  EXPECT_GT(hits, 1500);
  EXPECT_GT(misses, 5000);
}

TEST(GeometryTriangle, CullMatchesGeometricNormalInGeneralPosition) {
  // Front face: the geometric normal cross(v1-v0, v2-v0) points to the ray origin.
  std::mt19937 rng(777);
  std::uniform_real_distribution<double> u(-1.0, 1.0);
  int front = 0, back = 0;
  for (int i = 0; i < 5000; ++i) {
    Vec3d p[3];
    for (auto& q : p) q = RoundToFloat({u(rng), u(rng), u(rng)});
    Vec3d n = cross(p[1] - p[0], p[2] - p[0]);
    if (length(n) < 0.05) continue;
    Vec3d c = (p[0] + p[1] + p[2]) * (1.0 / 3.0);
    Vec3d o = RoundToFloat({3 * u(rng), 3 * u(rng), 3 * u(rng)});
    Vec3d d = c - o;
    double side = dot(n, o - p[0]);
    if (std::fabs(side) < 0.05 * length(n)) continue;
    TriHit h0 = HitTriangle(F3(o), F3(d), F3(p[0]), F3(p[1]), F3(p[2]), kInf, 0);
    TriHit h1 = HitTriangle(F3(o), F3(d), F3(p[0]), F3(p[1]), F3(p[2]), kInf, 1);
    ASSERT_EQ(h0.hit, 1) << "ray " << i;
    EXPECT_NEAR(h0.t, 1.0, 1e-5) << "ray " << i;
    if (side > 0) {
      ++front;
      EXPECT_EQ(h1.hit, 1) << "front face culled, ray " << i;
    } else {
      ++back;
      EXPECT_EQ(h1.hit, 0) << "back face not culled, ray " << i;
    }
  }
  EXPECT_GT(front, 1000);
  EXPECT_GT(back, 1000);
}

// ------------------------------------------------------------------------------------------
// Watertightness through the full scene path
// ------------------------------------------------------------------------------------------

struct TestMesh {
  std::vector<Vec3d> v;  // Float-representable positions.
  std::vector<std::array<int, 3>> f;
};

// Makes every face's geometric normal point away from the centroid (the meshes are convex).
void OrientOutward(TestMesh& m) {
  Vec3d c;
  for (auto& p : m.v) c = c + p;
  c = c * (1.0 / m.v.size());
  for (auto& t : m.f) {
    Vec3d n = cross(m.v[t[1]] - m.v[t[0]], m.v[t[2]] - m.v[t[0]]);
    Vec3d mid = (m.v[t[0]] + m.v[t[1]] + m.v[t[2]]) * (1.0 / 3.0);
    if (dot(n, mid - c) < 0) std::swap(t[1], t[2]);
  }
}

TestMesh Cube() {
  TestMesh m;
  for (int i = 0; i < 8; ++i)
    m.v.push_back({(i & 1) ? 1.0 : -1.0, (i & 2) ? 1.0 : -1.0, (i & 4) ? 1.0 : -1.0});
  for (int k = 0; k < 3; ++k)
    for (int s = 0; s < 2; ++s) {
      int a = (k + 1) % 3, b = (k + 2) % 3;
      auto corner = [&](int ia, int ib) { return (s << k) | (ia << a) | (ib << b); };
      int c0 = corner(0, 0), c1 = corner(1, 0), c2 = corner(1, 1), c3 = corner(0, 1);
      // Alternate the diagonal so both diagonal orientations occur.
      if ((k + s) % 2 == 0) {
        m.f.push_back({c0, c1, c2});
        m.f.push_back({c0, c2, c3});
      } else {
        m.f.push_back({c0, c1, c3});
        m.f.push_back({c1, c2, c3});
      }
    }
  OrientOutward(m);
  return m;
}

TestMesh Icosahedron() {
  const double phi = (1 + std::sqrt(5.0)) / 2;
  std::vector<Vec3d> v;
  for (double s1 : {-1.0, 1.0})
    for (double s2 : {-phi, phi}) {
      v.push_back({0, s1, s2});
      v.push_back({s1, s2, 0});
      v.push_back({s2, 0, s1});
    }
  TestMesh m;
  for (auto& p : v) m.v.push_back(p);
  int n = static_cast<int>(v.size());
  for (int i = 0; i < n; ++i)
    for (int j = i + 1; j < n; ++j)
      for (int k = j + 1; k < n; ++k) {
        auto edge = [&](int a, int b) {
          return std::fabs(dot(v[a] - v[b], v[a] - v[b]) - 4) < 1e-9;
        };
        if (edge(i, j) && edge(j, k) && edge(i, k)) m.f.push_back({i, j, k});
      }
  return m;
}

// Loop-style 1-to-4 split with the new vertices pushed onto the unit sphere; positions are
// rounded to float at the end so the test's double geometry is exactly the renderer's.
TestMesh IcoSphere(int levels) {
  TestMesh m = Icosahedron();
  for (auto& p : m.v) p = normalize(p);
  for (int l = 0; l < levels; ++l) {
    std::map<std::pair<int, int>, int> mid;
    auto midpoint = [&](int a, int b) {
      auto key = std::make_pair(std::min(a, b), std::max(a, b));
      auto it = mid.find(key);
      if (it != mid.end()) return it->second;
      m.v.push_back(normalize((m.v[a] + m.v[b]) * 0.5));
      return mid[key] = static_cast<int>(m.v.size()) - 1;
    };
    std::vector<std::array<int, 3>> faces;
    for (auto t : m.f) {
      int ab = midpoint(t[0], t[1]), bc = midpoint(t[1], t[2]), ca = midpoint(t[2], t[0]);
      faces.push_back({t[0], ab, ca});
      faces.push_back({t[1], bc, ab});
      faces.push_back({t[2], ca, bc});
      faces.push_back({ab, bc, ca});
    }
    m.f = faces;
  }
  for (auto& p : m.v) p = RoundToFloat(p);
  OrientOutward(m);
  return m;
}

TestMesh Rounded(TestMesh m) {
  for (auto& p : m.v) p = RoundToFloat(p);
  OrientOutward(m);
  return m;
}

Vec3d FaceNormal(const TestMesh& m, int f) {
  const auto& t = m.f[f];
  return normalize(cross(m.v[t[1]] - m.v[t[0]], m.v[t[2]] - m.v[t[0]]));
}

// Closed (every edge used once in each direction) and convex (no vertex above a face plane).
void CheckClosedConvex(const TestMesh& m) {
  std::map<std::pair<int, int>, int> directed;
  for (auto& t : m.f)
    for (int e = 0; e < 3; ++e) ++directed[{t[e], t[(e + 1) % 3]}];
  for (auto& [e, count] : directed) {
    ASSERT_EQ(count, 1);
    ASSERT_EQ(directed.count({e.second, e.first}), 1u) << "open edge";
  }
  for (size_t f = 0; f < m.f.size(); ++f) {
    Vec3d n = FaceNormal(m, static_cast<int>(f));
    for (auto& p : m.v) ASSERT_LE(dot(n, p - m.v[m.f[f][0]]), 1e-12) << "not convex";
  }
}

// A point exactly on a vertex or (to float rounding) on an edge, with the faces containing it.
struct Target {
  Vec3d p;  // Float-representable.
  std::vector<int> faces;
};

std::vector<Target> Targets(const TestMesh& m) {
  std::vector<Target> out;
  std::map<std::pair<int, int>, std::vector<int>> edges;
  std::vector<std::vector<int>> vertex_faces(m.v.size());
  for (size_t f = 0; f < m.f.size(); ++f)
    for (int e = 0; e < 3; ++e) {
      int a = m.f[f][e], b = m.f[f][(e + 1) % 3];
      edges[{std::min(a, b), std::max(a, b)}].push_back(static_cast<int>(f));
      vertex_faces[a].push_back(static_cast<int>(f));
    }
  for (size_t i = 0; i < m.v.size(); ++i) out.push_back({m.v[i], vertex_faces[i]});
  for (auto& [e, faces] : edges)
    for (double frac : {0.5, 0.25, 0.75}) {
      Vec3d p = RoundToFloat(m.v[e.first] + (m.v[e.second] - m.v[e.first]) * frac);
      out.push_back({p, faces});
    }
  return out;
}

std::vector<Vec3d> GlobalDirections() {
  std::vector<Vec3d> dirs;
  for (int x = -1; x <= 1; ++x)
    for (int y = -1; y <= 1; ++y)
      for (int z = -1; z <= 1; ++z)
        if (x || y || z) dirs.push_back(normalize(Vec3d{double(x), double(y), double(z)}));
  dirs.push_back(normalize(Vec3d{1, 2, 3}));
  dirs.push_back(normalize(Vec3d{-3, 1, 2}));
  dirs.push_back(normalize(Vec3d{2, -3, -1}));
  std::mt19937 rng(99);
  std::normal_distribution<double> g;
  for (int i = 0; i < 12; ++i) dirs.push_back(normalize(Vec3d{g(rng), g(rng), g(rng)}));
  return dirs;
}

// Directions lying in the planes of faces around the target (edge vectors of every face
// that shares a vertex with a face containing the target): rays parallel to a face.
std::vector<Vec3d> FacePlaneDirections(const TestMesh& m, const Target& tg) {
  std::vector<int> verts;
  for (int f : tg.faces)
    for (int k = 0; k < 3; ++k) verts.push_back(m.f[f][k]);
  std::vector<Vec3d> dirs;
  for (size_t f = 0; f < m.f.size(); ++f) {
    const auto& t = m.f[f];
    bool near = false;
    for (int k = 0; k < 3; ++k) near |= std::find(verts.begin(), verts.end(), t[k]) != verts.end();
    if (!near) continue;
    for (int e = 0; e < 3; ++e) {
      Vec3d d = normalize(m.v[t[(e + 1) % 3]] - m.v[t[e]]);
      dirs.push_back(d);
      dirs.push_back(d * -1.0);
    }
  }
  return dirs;
}

// A float origin o with the ray (o, p - o) passing exactly through p at t = 1: o is the
// rounding of p + offset, and p - o must be exact in float.
bool ExactAim(Vec3d p, Vec3d offset, float3* o, float3* d) {
  float3 pf = F3(p);
  *o = F3(p + offset);
  *d = pf - *o;
  // Differences of floats of similar magnitude are exact in double.
  Vec3d pd = D3(pf), od = D3(*o), dd = D3(*d);
  return pd.x - od.x == dd.x && pd.y - od.y == dd.y && pd.z - od.z == dd.z;
}

struct WatertightResult {
  int lines = 0, inexact = 0, failures = 0;
};

// For every target and every direction whose line passes through the interior of the solid
// at the target (strictly inside the cone of every face containing it), shoots
//  - from outside at the target (cull off and on): the first hit must be at the target
//    (t = 1), not on the far side, which is where a ray slipping through would end;
//  - from inside through the target: it must hit at t = 1; slipping through means no hit.
// `to_world` places the mesh; the rays are aimed at the float rounding of the world point.
WatertightResult ShootAtEdgesAndVertices(const TestMesh& m, const FlatScene& scene,
                                         const Mat4& to_world, double tol) {
  const double kCone = 0.02;  // Cosine margin against grazing lines.
  WatertightResult r;
  std::vector<Vec3d> normals;
  for (size_t f = 0; f < m.f.size(); ++f) normals.push_back(FaceNormal(m, static_cast<int>(f)));
  const std::vector<Vec3d> global = GlobalDirections();
  for (const Target& tg : Targets(m)) {
    std::vector<Vec3d> dirs = global;
    std::vector<Vec3d> plane_dirs = FacePlaneDirections(m, tg);
    dirs.insert(dirs.end(), plane_dirs.begin(), plane_dirs.end());
    for (Vec3d dir : dirs) {
      double lo = 1, hi = -1;
      for (int f : tg.faces) {
        double c = dot(normals[f], dir);
        lo = std::min(lo, c);
        hi = std::max(hi, c);
      }
      if (hi < -kCone) {
        // Entering at the target along dir.
      } else if (lo > kCone) {
        dir = dir * -1.0;
      } else {
        continue;  // Tangent or grazing: the line need not enter the solid here.
      }
      // Length of the chord from the target along dir (convex: first exit plane).
      double chord = 1e300;
      for (size_t f = 0; f < m.f.size(); ++f) {
        double c = dot(normals[f], dir);
        if (c > 1e-12) chord = std::min(chord, dot(normals[f], m.v[m.f[f][0]] - tg.p) / c);
      }
      EXPECT_GT(chord, 1e-3);
      if (!(chord > 1e-3)) continue;
      ++r.lines;
      Vec3d P = to_world.point(tg.p), D = to_world.vector(dir);
      float3 oo{}, od{}, io{}, id{};
      bool exact = false;
      double s = std::min(0.25 * chord, 0.5);
      for (int attempt = 0; attempt < 6 && !exact; ++attempt, s *= 0.5)
        exact = ExactAim(P, D * -s, &oo, &od) && ExactAim(P, D * s, &io, &id);
      if (!exact) {
        ++r.inexact;
        continue;
      }
      Hit h;
      for (int cull = 0; cull < 2; ++cull) {
        bool ok = Trace(scene, oo, od, kInf, cull, &h) && std::fabs(h.t - 1.0) <= tol;
        if (!ok && ++r.failures <= 10)
          ADD_FAILURE() << "outside ray slipped through at " << Str(F3(P)) << " origin " << Str(oo)
                        << " dir " << Str(od) << " cull " << cull << " t "
                        << (h.instance >= 0 ? h.t : -1.0f);
      }
      bool ok = Trace(scene, io, id, kInf, 0, &h) && std::fabs(h.t - 1.0) <= tol;
      if (!ok && ++r.failures <= 10)
        ADD_FAILURE() << "inside ray slipped through at " << Str(F3(P)) << " origin " << Str(io)
                      << " dir " << Str(id) << " t " << (h.instance >= 0 ? h.t : -1.0f);
    }
  }
  return r;
}

void RunWatertight(const TestMesh& m, int min_lines) {
  CheckClosedConvex(m);
  // Identity instance: the rays pass exactly through the float target points.
  for (int max_leaf : {1, 4}) {
    SCOPED_TRACE("identity, max_leaf " + std::to_string(max_leaf));
    SceneDesc s = BaseScene();
    AddMeshObject(s, AddMesh(s, m.v, m.f), Mat4());
    FlatScene scene = Flatten(s, 16, max_leaf);
    // t = 1 at the target; float error of the sheared test is ~1e-6.
    WatertightResult r = ShootAtEdgesAndVertices(m, scene, Mat4(), 1e-4);
    EXPECT_EQ(r.failures, 0);
    EXPECT_GE(r.lines, min_lines);
    EXPECT_LE(r.inexact, r.lines / 20) << "too few exactly aimed rays";
  }
  // Rotation, non-uniform scale and translation: the world->object transform rounds, so the
  // object-space ray only passes within ~1e-5 of the edge; with the 0.02 cone margin the hit
  // moves by at most ~1e-3 in t, far from a slip-through (t >= 5 or no hit).
  {
    SCOPED_TRACE("transformed instance");
    Mat4 M = Mat4::translation({10, -20, 30}) * Mat4::rotation(37, {1, 2, 3}) *
             Mat4::scaling({1.5, 0.75, 2.25}) * Mat4::rotation(-20, {0, 1, 1});
    SceneDesc s = BaseScene();
    AddMeshObject(s, AddMesh(s, m.v, m.f), M);
    FlatScene scene = Flatten(s);
    WatertightResult r = ShootAtEdgesAndVertices(m, scene, M, 1e-2);
    EXPECT_EQ(r.failures, 0);
    EXPECT_GE(r.lines, min_lines);
    EXPECT_LE(r.inexact, r.lines / 20) << "too few exactly aimed rays";
  }
}

TEST(GeometryWatertight, CubeEdgesAndVertices) { RunWatertight(Cube(), 1500); }

TEST(GeometryWatertight, IcosahedronEdgesAndVertices) {
  RunWatertight(Rounded(Icosahedron()), 1000);
}

TEST(GeometryWatertight, IcoSphereEdgesAndVertices) { RunWatertight(IcoSphere(2), 20000); }

// ------------------------------------------------------------------------------------------
// IntersectUnitSphere
// ------------------------------------------------------------------------------------------

TEST(GeometrySphere, AxisRaysGiveExactDistances) {
  float t = -1;
  ASSERT_EQ(IntersectUnitSphere(make_float3(0, 0, 5), make_float3(0, 0, -1), kInf, &t), 1);
  EXPECT_EQ(t, 4.0f);
  // Non-unit direction: t in units of the direction.
  ASSERT_EQ(IntersectUnitSphere(make_float3(0, 0, 5), make_float3(0, 0, -2), kInf, &t), 1);
  EXPECT_EQ(t, 2.0f);
  ASSERT_EQ(IntersectUnitSphere(make_float3(-3, 0, 0), make_float3(1, 0, 0), kInf, &t), 1);
  EXPECT_EQ(t, 2.0f);
  ASSERT_EQ(IntersectUnitSphere(make_float3(0, 9, 0), make_float3(0, -0.5f, 0), kInf, &t), 1);
  EXPECT_EQ(t, 16.0f);
  // Off-axis but exact: from (0.6, 0, 5) along -z the surface is at z = 0.8.
  ASSERT_EQ(IntersectUnitSphere(make_float3(0.6f, 0, 5), make_float3(0, 0, -1), kInf, &t), 1);
  EXPECT_NEAR(t, 4.2f, 4.2e-7);  // 0.8 is not dyadic: one rounding of sqrt.
}

TEST(GeometrySphere, OriginInsideGivesTheFarRoot) {
  float t = -1;
  ASSERT_EQ(IntersectUnitSphere(make_float3(0, 0, 0.5f), make_float3(0, 0, 1), kInf, &t), 1);
  EXPECT_EQ(t, 0.5f);
  ASSERT_EQ(IntersectUnitSphere(make_float3(0, 0, 0.5f), make_float3(0, 0, -1), kInf, &t), 1);
  EXPECT_EQ(t, 1.5f);
  ASSERT_EQ(IntersectUnitSphere(make_float3(0, 0, 0), make_float3(0, 0.25f, 0), kInf, &t), 1);
  EXPECT_EQ(t, 4.0f);
  ASSERT_EQ(IntersectUnitSphere(make_float3(0, 0, 0), make_float3(-1, 0, 0), kInf, &t), 1);
  EXPECT_EQ(t, 1.0f);
}

TEST(GeometrySphere, TangentMissBehindAndTmax) {
  float t = -1;
  // Tangent at (1, 0, 0): the discriminant is exactly 0, a single touching hit at t = 5.
  ASSERT_EQ(IntersectUnitSphere(make_float3(1, 0, 5), make_float3(0, 0, -1), kInf, &t), 1);
  EXPECT_EQ(t, 5.0f);
  EXPECT_EQ(IntersectUnitSphere(make_float3(std::nextafter(1.0f, 2.0f), 0, 5),
                                make_float3(0, 0, -1), kInf, &t),
            0);
  EXPECT_EQ(IntersectUnitSphere(make_float3(1.5f, 0, 5), make_float3(0, 0, -1), kInf, &t), 0);
  EXPECT_EQ(IntersectUnitSphere(make_float3(0, 0.75f, -3), make_float3(1, 0, 0), kInf, &t), 0);
  // Sphere behind the origin.
  EXPECT_EQ(IntersectUnitSphere(make_float3(0, 0, 5), make_float3(0, 0, 1), kInf, &t), 0);
  // tmax: the near root 4 must be < tmax; tmax = 4 rejects both roots (the far one is 6).
  EXPECT_EQ(IntersectUnitSphere(make_float3(0, 0, 5), make_float3(0, 0, -1), 4.0f, &t), 0);
  ASSERT_EQ(IntersectUnitSphere(make_float3(0, 0, 5), make_float3(0, 0, -1), 5.0f, &t), 1);
  EXPECT_EQ(t, 4.0f);
}

// Distance along (o, d) to the sphere |x - c| = r in double, nearest positive root.
double ReferenceSphere(Vec3d o, Vec3d d, Vec3d c, double r);

TEST(GeometrySphere, FarAwayUnitSphereStaysAccurateInRadiusUnits) {
  // From 1e3 and 1e4 radii away, b^2 - ac cancels all but a few bits (a textbook solver is
  // off by ~0.5 radii at 1e3 and misses grazing rays); the distance-to-line form stays
  // within a few ulps of the origin's magnitude: measured 2.3e-4 and 2.8e-3 radii.
  SceneDesc s = BaseScene();
  AddSphere(s, Mat4());
  FlatScene scene = Flatten(s);
  std::mt19937 rng(17);
  std::normal_distribution<double> g;
  for (double dist : {1e3, 1e4}) {
    const double tol = dist * 2e-6;  // 2e-3 and 2e-2 radii.
    for (int i = 0; i < 1000; ++i) {
      Vec3d eye = normalize({g(rng), g(rng), g(rng)});
      Vec3d side = normalize(cross(eye, {g(rng), g(rng), g(rng)}));
      float3 o = F3(eye * dist);
      Vec3d aim = side * ((i % 100) / 100.0);
      float3 d = F3(normalize(aim - D3(o)));
      double expect = ReferenceSphere(D3(o), D3(d), {0, 0, 0}, 1.0);
      if (expect < 0) continue;
      float t = -1;
      ASSERT_EQ(IntersectUnitSphere(o, d, kInf, &t), 1) << "distance " << dist << " ray " << i;
      EXPECT_NEAR(t, expect, tol) << "distance " << dist << " ray " << i;
      // Through the scene path the surface point is projected back onto the sphere, so its
      // error does not grow with the distance travelled (o + t d alone is ~1e-3 off at 1e4).
      Hit hit;
      ASSERT_TRUE(Trace(scene, o, d, kInf, 0, &hit));
      SceneData sd = scene.view();
      SurfacePoint sp = ComputeSurface(&sd, MakeRay(o, d, kInf, 0), hit);
      EXPECT_NEAR(length(D3(sp.p)), 1.0, 1e-6);
      ExpectVecNear(D3(sp.n), D3(sp.p), 1e-6);
    }
  }
}

double ReferenceSphere(Vec3d o, Vec3d d, Vec3d c, double r) {
  Vec3d oc = o - c;
  double a = dot(d, d);
  double tc = -dot(oc, d) / a;
  Vec3d l = oc + d * tc;
  double disc = (r * r - dot(l, l)) / a;
  if (disc < 0) return -1;
  double root = std::sqrt(disc);
  return tc - root > 0 ? tc - root : tc + root;
}

TEST(GeometrySphere, LargeDistantSphereThroughScenePath) {
  // Radius 1e4 seen from 1e5 away: the ray meets a unit sphere 10 radii away in object
  // space, with a direction of length 1e-4. Relative 1e-5 is what float inputs allow.
  const Vec3d centre{3e4, -2e4, 1e4};
  const double radius = 1e4;
  SceneDesc s = BaseScene();
  AddSphere(s, Mat4::translation(centre) * Mat4::scaling({radius, radius, radius}));
  FlatScene scene = Flatten(s);
  std::mt19937 rng(5);
  std::normal_distribution<double> g;
  int hits = 0;
  for (int i = 0; i < 200; ++i) {
    Vec3d eye = normalize({g(rng), g(rng), g(rng)});
    Vec3d o = centre + eye * 1e5;
    // Aim at closest-approach distance h * radius, h from 0 to 0.99.
    Vec3d side = normalize(cross(eye, {g(rng), g(rng), g(rng)}));
    double h = (i % 100) / 100.0;
    Vec3d aim = centre + side * (h * radius);
    float3 of = F3(o), df = F3(normalize(aim - o));
    double expect = ReferenceSphere(D3(of), D3(df), centre, radius);
    ASSERT_GT(expect, 0);
    Hit hit;
    ASSERT_TRUE(Trace(scene, of, df, kInf, 0, &hit)) << "ray " << i;
    EXPECT_EQ(hit.primitive, -1);
    EXPECT_NEAR(hit.t, expect, 1e-5 * expect) << "ray " << i << " h " << h;
    // The reconstructed point is on the sphere.
    SceneData sd = scene.view();
    SurfacePoint sp = ComputeSurface(&sd, MakeRay(of, df, kInf, 0), hit);
    EXPECT_NEAR(length(D3(sp.p) - centre), radius, 1e-5 * radius);
    ++hits;
  }
  EXPECT_EQ(hits, 200);
  // Closest approach 1.001 radii misses; 0.999 radii hits.
  Vec3d o = centre + Vec3d{0, 0, 1e5};
  for (double h : {1.001, 0.999}) {
    double sin_a = h * radius / 1e5;
    Hit hit;
    EXPECT_EQ(Trace(scene, F3(o), F3(sin_a, 0, -std::sqrt(1 - sin_a * sin_a)), kInf, 0, &hit),
              h < 1)
        << "closest approach " << h << " radii";
  }
}

// ------------------------------------------------------------------------------------------
// Transforms
// ------------------------------------------------------------------------------------------

TEST(GeometryTransform, RightHandedQuarterTurns) {
  // cos(90 degrees) in double is 6e-17; everything else is exact.
  ExpectVecNear(Mat4::rotation(90, {0, 0, 1}).point({1, 0, 0}), {0, 1, 0}, 1e-15);
  ExpectVecNear(Mat4::rotation(90, {0, 0, 1}).point({0, 1, 0}), {-1, 0, 0}, 1e-15);
  ExpectVecNear(Mat4::rotation(90, {0, 0, 7}).point({1, 0, 0}), {0, 1, 0}, 1e-15);
  ExpectVecNear(Mat4::rotation(90, {1, 0, 0}).point({0, 1, 0}), {0, 0, 1}, 1e-15);
  ExpectVecNear(Mat4::rotation(90, {0, 1, 0}).point({0, 0, 1}), {1, 0, 0}, 1e-15);
  ExpectVecNear(Mat4::rotation(-90, {0, 0, 1}).point({1, 0, 0}), {0, -1, 0}, 1e-15);
  // 120 degrees about (1,1,1) cycles the axes.
  ExpectVecNear(Mat4::rotation(120, {1, 1, 1}).point({1, 0, 0}), {0, 1, 0}, 1e-15);
}

TEST(GeometryTransform, TranslationAffectsPointsNotVectors) {
  Mat4 m = Mat4::translation({1, -2, 3}) * Mat4::scaling({2, 3, 4});
  ExpectVecNear(m.point({1, 1, 1}), {3, 1, 7}, 0);
  ExpectVecNear(m.vector({1, 1, 1}), {2, 3, 4}, 0);
  EXPECT_TRUE(Mat4().is_identity());
  EXPECT_FALSE(Mat4::translation({0, 0, 1e-300}).is_identity());
}

TEST(GeometryTransform, AffineInverseTimesMatrixIsIdentity) {
  std::mt19937 rng(3);
  std::uniform_real_distribution<double> u(-1, 1);
  for (int i = 0; i < 200; ++i) {
    Mat4 m = Mat4::translation({100 * u(rng), 100 * u(rng), 100 * u(rng)}) *
             Mat4::rotation(180 * u(rng), {u(rng), u(rng), u(rng) + 2}) *
             Mat4::scaling({0.1 + std::fabs(u(rng)), 0.5 + u(rng) * 0.4, 3 + u(rng)}) *
             Mat4::rotation(180 * u(rng), {u(rng) + 2, u(rng), u(rng)});
    bool ok = false;
    Mat4 inv = m.affine_inverse(&ok);
    ASSERT_TRUE(ok);
    Mat4 a = inv * m, b = m * inv;
    for (int r = 0; r < 4; ++r)
      for (int c = 0; c < 4; ++c) {
        // Translations up to 100 and scales down to 0.1: 1e-12 is ~1e4 ulps of headroom.
        EXPECT_NEAR(a(r, c), r == c ? 1.0 : 0.0, 1e-12) << "matrix " << i;
        EXPECT_NEAR(b(r, c), r == c ? 1.0 : 0.0, 1e-12) << "matrix " << i;
      }
  }
  bool ok = true;
  Mat4::scaling({1, 0, 1}).affine_inverse(&ok);
  EXPECT_FALSE(ok);
}

TEST(GeometryTransform, EllipsoidNormalsThroughScenePath) {
  // Unit sphere scaled by (a, b, c) = (2, 1, 1), then optionally rotated and moved: in the
  // ellipsoid's own frame the normal at x is normalize(x / a^2, y / b^2, z / c^2). The
  // rotated case also catches normals transformed by the inverse instead of its transpose.
  // Tolerance 1e-5: the point is rebuilt by normalizing in object space and the normal
  // goes through float matrix rows (a few float roundings of O(1) values).
  struct Case {
    Vec3d centre;
    Mat4 rotation;
  };
  const Case cases[] = {{{0, 0, 0}, Mat4()},
                        {{5, -3, 2}, Mat4()},
                        {{5, -3, 2}, Mat4::rotation(40, {1, 1, 0})},
                        {{-1, 2, 0.5}, Mat4::rotation(-75, {0.2, -1, 0.6})}};
  for (const Case& c : cases) {
    SceneDesc s = BaseScene();
    AddSphere(s, Mat4::translation(c.centre) * c.rotation * Mat4::scaling({2, 1, 1}));
    FlatScene scene = Flatten(s);
    SceneData sd = scene.view();
    bool ok = false;
    Mat4 unrotate = c.rotation.affine_inverse(&ok);
    ASSERT_TRUE(ok);
    std::mt19937 rng(11);
    std::normal_distribution<double> g;
    std::uniform_real_distribution<double> u(-1, 1);
    int hits = 0;
    for (int i = 0; i < 2000; ++i) {
      Vec3d o = c.centre + normalize({g(rng), g(rng), g(rng)}) * 6.0;
      Vec3d aim = c.centre + c.rotation.vector({1.9 * u(rng), 0.9 * u(rng), 0.9 * u(rng)});
      Ray ray = MakeRay(F3(o), F3(aim - o), kInf, 0);
      Hit hit;
      if (!IntersectScene(&sd, ray, 0, 0, &hit)) continue;
      ++hits;
      SurfacePoint sp = ComputeSurface(&sd, ray, hit);
      Vec3d x = unrotate.vector(D3(sp.p) - c.centre);  // In the ellipsoid's frame.
      EXPECT_NEAR(x.x * x.x / 4 + x.y * x.y + x.z * x.z, 1.0, 1e-5);
      Vec3d n = c.rotation.vector(normalize({x.x / 4, x.y, x.z}));
      ExpectVecNear(D3(sp.n), n, 1e-5);
      ExpectVecNear(D3(sp.ng), n, 1e-5);
      // The hit point also lies on the ray (|p| <= 8: 1e-5 relative).
      ExpectVecNear(D3(RayAt(ray, hit.t)), D3(sp.p), 8e-5);
    }
    EXPECT_GT(hits, 1500);
  }
}

// ------------------------------------------------------------------------------------------
// OffsetRayOrigin
// ------------------------------------------------------------------------------------------

struct OffsetCase {
  double magnitude;
  Vec3d centre_dir;  // The surface point is magnitude * centre_dir.
  Vec3d normal;
};

// Hits a triangle of the plane through magnitude * centre_dir with the given normal from the
// normal side, rebuilds the point as ComputeSurface does, offsets it, and checks that the
// new origin is strictly on the normal side of the triangle's actual plane and that rays
// leaving the surface do not hit it again.
void CheckOffset(const OffsetCase& c, float scene_epsilon, std::mt19937& rng, int* failures) {
  Vec3d n = normalize(c.normal);
  Vec3d t1 = normalize(cross(n, std::fabs(n.x) < 0.9 ? Vec3d{1, 0, 0} : Vec3d{0, 1, 0}));
  Vec3d t2 = cross(n, t1);
  Vec3d centre = c.centre_dir * c.magnitude;
  double size = std::max(c.magnitude, 1e-3) * 0.5;
  float3 v0 = F3(centre + (t1 * -1.0 + t2 * -1.0) * size);
  float3 v1 = F3(centre + (t1 * 2.0 + t2 * -1.0) * size);
  float3 v2 = F3(centre + (t1 * -1.0 + t2 * 2.0) * size);
  Vec3d pn = cross(D3(v1) - D3(v0), D3(v2) - D3(v0));
  if (dot(pn, n) < 0) std::swap(v1, v2), pn = pn * -1.0;
  pn = normalize(pn);
  std::uniform_real_distribution<double> u(-0.3, 0.3);
  std::normal_distribution<double> g;
  for (int i = 0; i < 50; ++i) {
    Vec3d target = centre + (t1 * u(rng) + t2 * u(rng)) * size;
    Vec3d from = target + normalize(n + Vec3d{u(rng), u(rng), u(rng)}) * (3 * size);
    float3 o = F3(from), d = F3(target - from);
    TriHit h = HitTriangle(o, d, v0, v1, v2, kInf, 0);
    ASSERT_EQ(h.hit, 1);
    float b0 = 1.0f - h.b1 - h.b2;
    float3 p = v0 * b0 + v1 * h.b1 + v2 * h.b2;
    float3 ng = Normalize(Cross(v1 - v0, v2 - v0));
    if (Dot(ng, d) > 0) ng = -ng;
    float scale =
        std::max({MaxComponent(Abs3(v0)), MaxComponent(Abs3(v1)), MaxComponent(Abs3(v2))});
    float3 q = OffsetRayOrigin(p, ng, scene_epsilon, scale);
    double along = dot(D3(q) - D3(p), D3(ng));
    double above = dot(D3(q) - D3(v0), pn);  // Signed distance to the true plane.
    bool ok = along > 0 && above > 0;
    // Leaving rays: along the normal, a mirror direction, and random ones at least 3
    // degrees above the plane.
    std::vector<float3> out = {ng, Reflect(Normalize(-d), ng)};
    for (int k = 0; k < 8; ++k) {
      Vec3d w = normalize({g(rng), g(rng), g(rng)});
      if (dot(w, D3(ng)) < 0) w = w * -1.0;
      if (dot(w, D3(ng)) < 0.05) w = normalize(w + D3(ng) * 0.1);
      out.push_back(F3(w));
    }
    int rehit = 0;
    for (float3 w : out) rehit += HitTriangle(q, w, v0, v1, v2, kInf, 0).hit;
    if ((!ok || rehit) && ++*failures <= 10)
      ADD_FAILURE() << "magnitude " << c.magnitude << " normal " << Str(F3(n)) << " eps "
                    << scene_epsilon << ": p " << Str(p) << " q " << Str(q) << " dot(q-p,n) "
                    << along << " distance to plane " << above << " re-hits " << rehit;
  }
}

TEST(GeometryOffset, OffsetOriginLeavesThePlaneAtEveryScale) {
  // Surface points at |p| = 1e-6 .. 1e8, on planes of several orientations, with and without
  // the scene epsilon. Centre (1, 0, 0) puts points whose coordinate along an axis-aligned
  // normal is ~0 far from the origin: the re-intersection test rounds at the scale of |p|,
  // so the offset must too, not only at the scale of the coordinate along n.
  std::vector<Vec3d> normals = {{0, 0, 1},        {0, -1, 0},       {1, 0, 0},       {1, 1, 1},
                                {-0.3, 0.8, 0.5}, {0.9, -0.1, 0.2}, {0.05, 0.05, -1}};
  std::vector<Vec3d> centres = {{0.6, -0.7, 0.4}, {-0.5, 0.5, 0.7}, {1, 0, 0}};
  std::mt19937 rng(21);
  int failures = 0;
  for (double mag : {1e-6, 1.0, 1e4, 1e8})
    for (Vec3d n : normals)
      for (Vec3d c : centres)
        for (float eps : {0.0f, 1e-3f}) CheckOffset({mag, c, n}, eps, rng, &failures);
  EXPECT_EQ(failures, 0);
}

TEST(GeometryOffset, MovesAlongTheNormalByEightUlpsOfTheLargerOfPointAndScale) {
  // Contract (scene epsilon 0): q = p + n * 8 * 2^-23 * max(max|p_i|, scale), up to float
  // rounding: half an ulp of each coordinate of q, plus a few ulps of the step itself.
  std::mt19937 rng(23);
  std::uniform_int_distribution<int> pick(0, 9);
  std::normal_distribution<float> g;
  const float mags[] = {0.0f, 1e-6f, 0.01f, 0.5f, 3.0f, 1e4f, 1e8f};
  for (int i = 0; i < 2000; ++i) {
    float c[3];
    for (float& x : c)
      x = mags[pick(rng) % 7] * (pick(rng) < 5 ? -1.0f : 1.0f) * (1 + 0.1f * g(rng));
    float3 n = Normalize(make_float3(g(rng), g(rng), g(rng)));
    float3 p = make_float3(c[0], c[1], c[2]);
    float scale = mags[pick(rng) % 7];
    float3 q = OffsetRayOrigin(p, n, 0.0f, scale);
    double m = std::max(
        {std::fabs(double(p.x)), std::fabs(double(p.y)), std::fabs(double(p.z)), double(scale)});
    double step = 8.0 / 8388608.0 * m;
    const float pc[3] = {p.x, p.y, p.z}, qc[3] = {q.x, q.y, q.z}, nc[3] = {n.x, n.y, n.z};
    for (int k = 0; k < 3; ++k) {
      double expected = double(pc[k]) + double(nc[k]) * step;
      double half_ulp = 0.5 * (double(std::nextafter(std::fabs(qc[k]), 1e38f)) - std::fabs(qc[k]));
      double step_rounding = 4.0 / 16777216.0 * std::fabs(double(nc[k]) * step);
      EXPECT_LE(std::fabs(qc[k] - expected), half_ulp * 1.0001 + step_rounding + 1e-45)
          << "p " << Str(p) << " n " << Str(n) << " scale " << scale << " axis " << k;
    }
    if (m > 0) {
      EXPECT_GT(dot(D3(q) - D3(p), D3(n)), 0) << "p " << Str(p) << " n " << Str(n);
    }
  }
}

TEST(GeometryOffset, TiltedPlaneFarAlongAnAxisItNearlyContains) {
  // A plane through points far out along x whose normal is almost +y (or +z): the surface
  // point's x carries rounding error of ~ulp(|x|), which n.x turns into distance from the
  // plane, and the re-intersection test rounds at the scale of |x|, while the offset along
  // the normal is scaled by the small y (or z) coordinate only.
  std::mt19937 rng(22);
  int failures = 0;
  for (double mag : {1e4, 1e6, 1e8})
    for (Vec3d n : {Vec3d{0.002, 1, 0}, Vec3d{-0.01, 1, 0.003}, Vec3d{0.02, 0.001, 1}})
      CheckOffset({mag, {1, 0, 0}, n}, 0.0f, rng, &failures);
  EXPECT_EQ(failures, 0);
}

// ------------------------------------------------------------------------------------------
// BVH construction
// ------------------------------------------------------------------------------------------

bool Contains(const BinaryBvhNode& n, const Aabb& b) {
  for (int k = 0; k < 3; ++k)
    if (b.lo[k] < n.lo[k] || b.hi[k] > n.hi[k]) return false;
  return true;
}
bool Contains(const BinaryBvhNode& n, const BinaryBvhNode& c) {
  for (int k = 0; k < 3; ++k)
    if (c.lo[k] < n.lo[k] || c.hi[k] > n.hi[k]) return false;
  return true;
}

void ValidateBvh(const std::vector<Aabb>& boxes, const std::vector<BinaryBvhNode>& nodes,
                 size_t first_node, const BvhBuildResult& r, const std::vector<int>& order,
                 int prim_offset, int max_leaf) {
  const int n = static_cast<int>(boxes.size());
  ASSERT_EQ(static_cast<int>(order.size()), n);
  std::vector<int> sorted = order;
  std::sort(sorted.begin(), sorted.end());
  for (int i = 0; i < n; ++i) ASSERT_EQ(sorted[i], i) << "order is not a permutation";
  ASSERT_EQ(r.root, static_cast<int>(first_node));
  std::vector<int> covered(n, 0), visits(nodes.size(), 0);
  std::vector<std::pair<int, int>> stack = {{r.root, 0}};
  int max_depth = 0;
  while (!stack.empty()) {
    auto [index, depth] = stack.back();
    stack.pop_back();
    ASSERT_GE(index, static_cast<int>(first_node));
    ASSERT_LT(index, static_cast<int>(nodes.size()));
    ASSERT_EQ(++visits[index], 1) << "node reached twice";
    max_depth = std::max(max_depth, depth);
    const BinaryBvhNode& node = nodes[index];
    if (node.count > 0) {
      ASSERT_LE(node.count, std::max(1, max_leaf));
      int begin = node.first - prim_offset;
      ASSERT_GE(begin, 0);
      ASSERT_LE(begin + node.count, n);
      for (int j = begin; j < begin + node.count; ++j) {
        ++covered[j];
        ASSERT_TRUE(Contains(node, boxes[order[j]])) << "leaf " << index << " prim " << order[j];
      }
    } else {
      ASSERT_LE(-node.count, 2) << "split axis";
      ASSERT_GT(node.first, index);
      ASSERT_LT(node.first + 1, static_cast<int>(nodes.size()));
      ASSERT_TRUE(Contains(node, nodes[node.first])) << "node " << index;
      ASSERT_TRUE(Contains(node, nodes[node.first + 1])) << "node " << index;
      stack.push_back({node.first, depth + 1});
      stack.push_back({node.first + 1, depth + 1});
    }
  }
  for (int i = 0; i < n; ++i) ASSERT_EQ(covered[i], 1) << "position " << i;
  for (size_t i = first_node; i < nodes.size(); ++i) EXPECT_EQ(visits[i], 1) << "orphan " << i;
  EXPECT_EQ(r.depth, max_depth);
  EXPECT_LE(max_depth, RT_BVH_MAX_DEPTH);
}

Aabb RandomBox(std::mt19937& rng, double spread, double max_size) {
  std::uniform_real_distribution<double> u(-spread, spread), sz(0, max_size);
  Aabb b;
  double c[3] = {u(rng), u(rng), u(rng)};
  b.grow(static_cast<float>(c[0]), static_cast<float>(c[1]), static_cast<float>(c[2]));
  b.grow(static_cast<float>(c[0] + sz(rng)), static_cast<float>(c[1] + sz(rng)),
         static_cast<float>(c[2] + sz(rng)));
  return b;
}

TEST(GeometryBvhBuild, RandomBoxesGiveAValidTree) {
  std::mt19937 rng(1);
  for (int count : {1, 2, 3, 17, 1000})
    for (int bins : {2, 16, 64})
      for (int max_leaf : {1, 4, 16}) {
        SCOPED_TRACE("count " + std::to_string(count) + " bins " + std::to_string(bins) +
                     " max_leaf " + std::to_string(max_leaf));
        std::vector<Aabb> boxes;
        for (int i = 0; i < count; ++i) boxes.push_back(RandomBox(rng, 10, i % 7 == 0 ? 8 : 1));
        // Existing nodes and a primitive offset, as for the second mesh of a scene.
        std::vector<BinaryBvhNode> nodes(5);
        std::vector<int> order;
        BvhOptions opt;
        opt.bins = bins;
        opt.max_leaf = max_leaf;
        BvhBuildResult r = build_bvh(boxes, opt, max_leaf, 123, nodes, order);
        ValidateBvh(boxes, nodes, 5, r, order, 123, max_leaf);
      }
}

TEST(GeometryBvhBuild, DegenerateInputsStillGiveAValidTree) {
  for (int max_leaf : {1, 4}) {
    BvhOptions opt;
    opt.max_leaf = max_leaf;
    // Identical boxes: no split separates the centroids (object-median fallback).
    std::vector<Aabb> same(300);
    for (auto& b : same) b.grow(1, 2, 3), b.grow(2, 3, 4);
    std::vector<BinaryBvhNode> nodes;
    std::vector<int> order;
    BvhBuildResult r = build_bvh(same, opt, max_leaf, 0, nodes, order);
    ValidateBvh(same, nodes, 0, r, order, 0, max_leaf);
    // Flat boxes on a line, and points.
    std::vector<Aabb> line(257);
    for (size_t i = 0; i < line.size(); ++i) line[i].grow(static_cast<float>(i % 13), 0, 0);
    nodes.clear();
    r = build_bvh(line, opt, max_leaf, 0, nodes, order);
    ValidateBvh(line, nodes, 0, r, order, 0, max_leaf);
  }
  std::vector<BinaryBvhNode> nodes;
  std::vector<int> order;
  EXPECT_EQ(build_bvh({}, BvhOptions{}, 4, 0, nodes, order).root, -1);
  EXPECT_TRUE(nodes.empty());
}

// ------------------------------------------------------------------------------------------
// BVH traversal against brute force
// ------------------------------------------------------------------------------------------

struct Soup {
  std::vector<Vec3d> positions;
  std::vector<std::array<int, 3>> triangles;
  std::vector<Triangle> tris;  // The same triangles in float.
};

Soup RandomSoup(int count, std::mt19937& rng) {
  Soup s;
  std::uniform_real_distribution<double> u(-1, 1), sz(0.02, 0.25);
  std::normal_distribution<double> g;
  for (int i = 0; i < count; ++i) {
    Vec3d c{u(rng), u(rng), u(rng)};
    double size = sz(rng);
    Triangle t;
    float3* v[3] = {&t.v0, &t.v1, &t.v2};
    for (int k = 0; k < 3; ++k) {
      Vec3d p = RoundToFloat(c + Vec3d{g(rng), g(rng), g(rng)} * size);
      s.positions.push_back(p);
      *v[k] = F3(p);
    }
    s.triangles.push_back({3 * i, 3 * i + 1, 3 * i + 2});
    s.tris.push_back(t);
  }
  return s;
}

struct BruteHit {
  int index = -1;
  float t = 0, b1 = 0, b2 = 0;
};

BruteHit BruteForce(const std::vector<Triangle>& tris, float3 o, float3 d, float tmax, int cull) {
  TriangleRay tr = MakeTriangleRay(o, d);
  BruteHit best;
  for (size_t i = 0; i < tris.size(); ++i) {
    float t, b1, b2;
    if (IntersectTriangle(&tr, tris[i].v0, tris[i].v1, tris[i].v2, tmax, cull, &t, &b1, &b2)) {
      tmax = t;
      best.index = static_cast<int>(i);
      best.t = t;
      best.b1 = b1;
      best.b2 = b2;
    }
  }
  return best;
}

bool SameTriangle(const Triangle& a, const Triangle& b) {
  auto eq = [](float3 x, float3 y) { return x.x == y.x && x.y == y.y && x.z == y.z; };
  return eq(a.v0, b.v0) && eq(a.v1, b.v1) && eq(a.v2, b.v2);
}

struct TestRay {
  float3 o, d;
  float tmax;
};

// Compares closest hits (exactly: both call IntersectTriangle on the same TriangleRay),
// shadow-ray answers and culled closest hits. Returns the number of mismatching rays.
int CompareWithBruteForce(const Soup& soup, const FlatScene& scene,
                          const std::vector<TestRay>& rays, const std::vector<BruteHit>& closest,
                          const std::vector<BruteHit>& culled) {
  int bad = 0;
  for (size_t i = 0; i < rays.size(); ++i) {
    const TestRay& r = rays[i];
    const BruteHit& ref = closest[i];
    Hit h;
    bool hit = Trace(scene, r.o, r.d, r.tmax, 0, &h);
    bool ok = hit == (ref.index >= 0);
    if (ok && hit)
      ok = h.t == ref.t && h.b1 == ref.b1 && h.b2 == ref.b2 &&
           SameTriangle(scene.triangles[h.primitive], soup.tris[ref.index]);
    Hit sh;
    bool shadow = Trace(scene, r.o, r.d, r.tmax, 0, &sh, 1);
    ok = ok && shadow == (ref.index >= 0);
    if (shadow) ok = ok && sh.t < r.tmax && sh.t > 0;
    Hit ch;
    bool chit = Trace(scene, r.o, r.d, r.tmax, 1, &ch);
    ok = ok && chit == (culled[i].index >= 0);
    if (ok && chit) ok = ch.t == culled[i].t;
    if (!ok && ++bad <= 5)
      ADD_FAILURE() << "ray " << i << " o " << Str(r.o) << " d " << Str(r.d) << " tmax " << r.tmax
                    << ": scene " << (hit ? h.t : -1.0f) << " brute "
                    << (ref.index >= 0 ? ref.t : -1.0f) << " shadow " << shadow << " culled scene "
                    << (chit ? ch.t : -1.0f) << " brute "
                    << (culled[i].index >= 0 ? culled[i].t : -1.0f);
  }
  return bad;
}

TEST(GeometryBvhTraversal, ClosestHitMatchesBruteForceOnTriangleSoup) {
  std::mt19937 rng(2024);
  Soup soup = RandomSoup(2000, rng);
  std::vector<TestRay> rays;
  std::uniform_real_distribution<double> u(-1.5, 1.5), uu(0, 1);
  std::normal_distribution<double> g;
  for (int i = 0; i < 10000; ++i) {
    TestRay r;
    r.o = F3(u(rng), u(rng), u(rng));
    int kind = i % 10;
    if (kind == 0) {
      // Axis-aligned: two zero components give infinite reciprocals in the slab test.
      float c[3] = {0, 0, 0};
      c[(i / 10) % 3] = (i / 30) % 2 ? 1.0f : -1.0f;
      r.d = make_float3(c[0], c[1], c[2]);
    } else {
      Vec3d d = normalize({g(rng), g(rng), g(rng)});
      if (kind == 1) d = d * std::pow(10.0, 4 * uu(rng) - 2);  // Non-unit lengths.
      r.d = F3(d);
    }
    r.tmax = (i % 3 == 0) ? static_cast<float>(3 * uu(rng)) : kInf;
    rays.push_back(r);
  }
  std::vector<BruteHit> closest, culled;
  int hits = 0;
  for (auto& r : rays) {
    closest.push_back(BruteForce(soup.tris, r.o, r.d, r.tmax, 0));
    culled.push_back(BruteForce(soup.tris, r.o, r.d, r.tmax, 1));
    hits += closest.back().index >= 0;
  }
  ASSERT_GT(hits, 3000);
  ASSERT_LT(hits, 9500);
  for (int bins : {2, 16, 64})
    for (int max_leaf : {1, 4, 16}) {
      SCOPED_TRACE("bins " + std::to_string(bins) + " max_leaf " + std::to_string(max_leaf));
      SceneDesc s = BaseScene();
      AddMeshObject(s, AddMesh(s, soup.positions, soup.triangles), Mat4());
      FlatScene scene = Flatten(s, bins, max_leaf);
      ASSERT_EQ(scene.triangles.size(), soup.tris.size());
      EXPECT_EQ(CompareWithBruteForce(soup, scene, rays, closest, culled), 0);
    }
}

TEST(GeometryBvhTraversal, AxisRaysThroughSoupVerticesMatchBruteForce) {
  // IntersectTriangle counts a ray through a vertex as a hit. Along an axis, such a ray lies
  // in the plane of a BVH box face whenever the vertex is extreme in its leaf; the traversal
  // must still reach the triangle.
  std::mt19937 rng(31);
  Soup soup = RandomSoup(300, rng);
  std::vector<TestRay> rays;
  for (const Triangle& t : soup.tris)
    for (float3 v : {t.v0, t.v1, t.v2})
      for (int k = 0; k < 3; ++k)
        for (float s : {-1.0f, 1.0f}) {
          for (float zero : {0.0f, -0.0f}) {  // Both signs of the zero components.
            float c[3] = {zero, zero, zero};
            c[k] = s;
            float3 d = make_float3(c[0], c[1], c[2]);
            rays.push_back({v - d * 4.0f, d, kInf});
          }
        }
  std::vector<BruteHit> closest, culled;
  for (auto& r : rays) {
    closest.push_back(BruteForce(soup.tris, r.o, r.d, r.tmax, 0));
    culled.push_back(BruteForce(soup.tris, r.o, r.d, r.tmax, 1));
  }
  SceneDesc s = BaseScene();
  AddMeshObject(s, AddMesh(s, soup.positions, soup.triangles), Mat4());
  FlatScene scene = Flatten(s, 16, 1);
  EXPECT_EQ(CompareWithBruteForce(soup, scene, rays, closest, culled), 0);
}

TEST(GeometryBvhTraversal, AxisRayGrazingTheLowFaceOfALeafBox) {
  // Minimal case of the above: one triangle, rays along -z through its vertices and the
  // midpoints of its axis-aligned edges. IntersectTriangle reports each as a hit at t = 2.
  const float3 v0 = make_float3(0, 0, -2), v1 = make_float3(1, 0, -2), v2 = make_float3(0, 1, -2);
  SceneDesc s = BaseScene();
  AddMeshObject(s, AddMesh(s, {D3(v0), D3(v1), D3(v2)}, {{0, 1, 2}}), Mat4());
  FlatScene scene = Flatten(s);
  const float3 d = make_float3(0, 0, -1);
  for (float3 p : {v0, v1, v2, make_float3(0.5f, 0, -2), make_float3(0, 0.5f, -2),
                   make_float3(0.5f, 0.5f, -2), make_float3(0.25f, 0.25f, -2)}) {
    float3 o = make_float3(p.x, p.y, 0);
    SCOPED_TRACE("origin " + Str(o));
    ASSERT_EQ(HitTriangle(o, d, v0, v1, v2, kInf, 0).hit, 1);
    Hit h;
    EXPECT_TRUE(Trace(scene, o, d, kInf, 0, &h));
    EXPECT_EQ(h.instance >= 0 ? h.t : -1.0f, 2.0f);
  }
}

}  // namespace
}  // namespace rt
