// Watertightness of closed meshes (a cube, an icosahedron, an icosphere): rays aimed exactly
// at shared edges and vertices, from every direction and along the face planes, must hit the
// mesh, through the full scene path.
#include <gtest/gtest.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <map>
#include <random>
#include <string>
#include <utility>
#include <vector>

#include "support/geometry_harness.h"

namespace rt {
namespace {

using namespace test;

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

}  // namespace
}  // namespace rt
