// Two-level BVH traversal against brute force: the closest hit of random triangle soups
// matches testing every triangle, also for axis rays through vertices and rays grazing a
// leaf box's face.
#include <gtest/gtest.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <random>
#include <string>
#include <vector>

#include "support/geometry_harness.h"

namespace rt {
namespace {

using namespace test;

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

// A ray through an edge two triangles share meets both at the same t, and one through a
// vertex meets all around it: ties, here on a bumpy grid (integer x, y; z in eighths) whose
// triangles are numbered in shuffled order, with rays along -z through its edges' midpoints
// and its vertices (edge functions exactly zero). The closest hit must be the least
// (t, primitive) over every triangle (ClosestHitWins), whatever tree is built and so
// whatever order its leaves are visited in, which also makes it the same for 4- and 8-wide
// nodes. Before that rule, the triangle visited first won a tie.
TEST(GeometryBvhTraversal, TiesGoToTheLowestIndexWhateverTheTree) {
  std::mt19937 rng(77);
  const int n = 24;
  std::vector<Vec3d> positions;
  for (int y = 0; y <= n; ++y)
    for (int x = 0; x <= n; ++x) positions.push_back({double(x), double(y), (rng() % 16) / 8.0});
  std::vector<std::array<int, 3>> triangles;
  for (int y = 0; y < n; ++y)
    for (int x = 0; x < n; ++x) {
      int a = y * (n + 1) + x, b = a + 1, c = a + n + 1, d = c + 1;
      triangles.push_back({a, b, d});
      triangles.push_back({a, d, c});
    }
  std::shuffle(triangles.begin(), triangles.end(), rng);
  std::vector<TestRay> rays;
  const float3 down = make_float3(0, 0, -1);
  for (int y = 1; y < n; ++y)
    for (int x = 1; x < n; ++x)
      for (float3 p : {F3(x, y, 5), F3(x + 0.5, y, 5), F3(x, y + 0.5, 5), F3(x + 0.5, y + 0.5, 5)})
        rays.push_back({p, down, kInf});
  int ties = 0;
  for (int bins : {2, 16, 64})
    for (int max_leaf : {1, 4, 16}) {
      SCOPED_TRACE("bins " + std::to_string(bins) + " max_leaf " + std::to_string(max_leaf));
      SceneDesc s = BaseScene();
      AddMeshObject(s, AddMesh(s, positions, triangles), Mat4());
      FlatScene scene = Flatten(s, bins, max_leaf);
      int bad = 0;
      for (const TestRay& r : rays) {
        TriangleRay tr = MakeTriangleRay(r.o, r.d);
        int best = -1, tied = 0;
        float best_t = 0;
        for (size_t i = 0; i < scene.triangles.size(); ++i) {
          const Triangle& t = scene.triangles[i];
          float ti, b1, b2;
          if (!IntersectTriangle(&tr, t.v0, t.v1, t.v2, kInf, 0, &ti, &b1, &b2)) continue;
          if (best >= 0 && ti == best_t) ++tied;
          if (best < 0 || ti < best_t) best = static_cast<int>(i), best_t = ti, tied = 1;
        }
        ties += tied > 1;
        Hit h;
        bool hit = Trace(scene, r.o, r.d, r.tmax, 0, &h);
        if ((hit ? h.primitive : -1) != best || (hit && h.t != best_t)) ++bad;
      }
      EXPECT_EQ(bad, 0);
    }
  // Every ray lies on an edge or a vertex.
  EXPECT_EQ(ties, 9 * static_cast<int>(rays.size()));
}

}  // namespace
}  // namespace rt
