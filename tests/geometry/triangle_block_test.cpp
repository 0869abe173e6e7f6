// IntersectTriangleBlock, the test of RT_BVH_WIDTH triangles at once (cl/geometry/shapes.h), against
// the scalar watertight test of each triangle: the lane of least t (the first of equal
// ones; with any_hit the first hit), and the same distance and barycentrics bit for bit, for
// closest and any hits, with and without culling, on blocks full of near ties and exact ties
// (repeated and re-ordered triangles) and on partly filled blocks. A closest-hit query keeps
// a triangle at exactly tmax (a tie the traversal settles by index), a shadow ray does not.
#include <gtest/gtest.h>

#include <cstring>
#include <random>

#include "cl/geometry/shapes.h"

namespace rt {
namespace {

struct ScalarResult {
  int lane = -1;
  float t = 0, b1 = 0, b2 = 0;
};

// Each triangle by the scalar test; the nearest of those within tmax, or the first.
ScalarResult ScalarLoop(const TriangleRay& tr, const float3 (&v)[RT_BVH_WIDTH][3], int count,
                        float tmax, int cull, int any_hit) {
  ScalarResult r;
  for (int i = 0; i < count; ++i) {
    float t, b1, b2;
    if (!IntersectTriangle(&tr, v[i][0], v[i][1], v[i][2], INFINITY, cull, &t, &b1, &b2)) continue;
    if (any_hit ? !(t < tmax) : !(t <= tmax)) continue;
    if (r.lane >= 0 && !(t < r.t)) continue;
    r = ScalarResult{i, t, b1, b2};
    if (any_hit) break;
  }
  return r;
}

// A block as src/bvh/triangle_blocks.cpp lays it out: lanes past `count` all zero.
TriangleBlock MakeBlock(const float3 (&v)[RT_BVH_WIDTH][3], int count) {
  float soa[9][RT_BVH_WIDTH] = {};
  for (int lane = 0; lane < count; ++lane)
    for (int k = 0; k < 3; ++k) {
      soa[3 * k][lane] = v[lane][k].x;
      soa[3 * k + 1][lane] = v[lane][k].y;
      soa[3 * k + 2][lane] = v[lane][k].z;
    }
  TriangleBlock b;
  std::memset(&b, 0, sizeof b);
  for (int j = 0; j < 9; ++j) std::memcpy(&b.v[j], soa[j], sizeof b.v[j]);
  return b;
}

float3 RandomPoint(std::mt19937& rng, float spread) {
  std::uniform_real_distribution<float> u(-spread, spread);
  return make_float3(u(rng), u(rng), u(rng));
}

TEST(TriangleBlock, MatchesTheScalarLoopBitForBit) {
  std::mt19937 rng(12345);
  std::uniform_int_distribution<int> pick(0, 5);
  int hits = 0, multi = 0, ties = 0;
  for (int trial = 0; trial < 20000; ++trial) {
    // Triangles around the origin, some repeated exactly or with their vertices rotated
    // (the same plane, rounded differently), some nearly coplanar: many rays hit several.
    float3 v[RT_BVH_WIDTH][3];
    int count = 1 + trial % RT_BVH_WIDTH;
    for (int i = 0; i < count; ++i) {
      int kind = i > 0 ? pick(rng) : 0;
      if (kind == 1) {  // An exact repeat of the previous triangle: a tie.
        for (int k = 0; k < 3; ++k) v[i][k] = v[i - 1][k];
        ++ties;
      } else if (kind == 2) {  // The previous triangle, its vertices rotated.
        for (int k = 0; k < 3; ++k) v[i][k] = v[i - 1][(k + 1) % 3];
      } else if (kind == 3) {  // The previous triangle moved by a few ulps.
        for (int k = 0; k < 3; ++k)
          v[i][k] = make_float3(v[i - 1][k].x, v[i - 1][k].y,
                                std::nextafter(std::nextafter(v[i - 1][k].z, 9.f), 9.f));
      } else {
        for (int k = 0; k < 3; ++k) v[i][k] = RandomPoint(rng, 1.0f);
      }
    }
    TriangleBlock block = MakeBlock(v, count);
    float3 o = RandomPoint(rng, 4.0f);
    float3 target = RandomPoint(rng, 0.3f);
    float3 d = target - o;
    TriangleRay tr = MakeTriangleRay(o, d);
    const float tmaxes[2] = {INFINITY, 1.0f};
    for (float tmax : tmaxes)
      for (int cull = 0; cull < 2; ++cull)
        for (int any_hit = 0; any_hit < 2; ++any_hit) {
          ScalarResult want = ScalarLoop(tr, v, count, tmax, cull, any_hit);
          float t = -1, b1 = -1, b2 = -1;
          int lane = IntersectTriangleBlock(&block, &tr, tmax, cull, any_hit, &t, &b1, &b2);
          ASSERT_EQ(lane, want.lane) << "trial " << trial << " tmax " << tmax;
          if (lane < 0) continue;
          ++hits;
          EXPECT_EQ(std::memcmp(&t, &want.t, sizeof t), 0) << "trial " << trial;
          EXPECT_EQ(std::memcmp(&b1, &want.b1, sizeof b1), 0) << "trial " << trial;
          EXPECT_EQ(std::memcmp(&b2, &want.b2, sizeof b2), 0) << "trial " << trial;
          if (lane > 0) ++multi;
        }
  }
  // The cases the test is for did occur: hits, hits past the first lane, exact ties.
  EXPECT_GT(hits, 10000);
  EXPECT_GT(multi, 1000);
  EXPECT_GT(ties, 1000);
}

// Lanes past a leaf's end are zero triangles: never hit, whatever the ray.
TEST(TriangleBlock, ZeroLanesNeverHit) {
  float3 v[RT_BVH_WIDTH][3] = {};
  TriangleBlock block = MakeBlock(v, 0);
  const float3 origins[3] = {make_float3(0, 0, -1), make_float3(0, 0, 0), make_float3(1, 2, 3)};
  for (float3 o : origins) {
    TriangleRay tr = MakeTriangleRay(o, make_float3(0, 0, 1) - o + make_float3(0, 0, 0.5f));
    float t, b1, b2;
    EXPECT_EQ(IntersectTriangleBlock(&block, &tr, INFINITY, 0, 0, &t, &b1, &b2), -1);
  }
}

}  // namespace
}  // namespace rt
