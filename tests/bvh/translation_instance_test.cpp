// Instances moved by a translation alone (RT_INSTANCE_TRANSLATION, cl/bvh/bvh.h): they share the
// world ray's direction setup and add their translation to the world origin, and must give
// exactly the hits of the general instance path (TransformPoint, TransformVector and a node
// ray of their own), bit for bit, including rays with zero and -0 components.
#include <gtest/gtest.h>

#include <array>
#include <cmath>
#include <cstring>
#include <random>
#include <vector>

#include "support/geometry_harness.h"

namespace rt {
namespace {

using namespace test;

bool SameBits(float a, float b) { return std::memcmp(&a, &b, sizeof a) == 0; }

bool SameBits3(float3 a, float3 b) {
  return SameBits(a.x, b.x) && SameBits(a.y, b.y) && SameBits(a.z, b.z);
}

// Rows of a transform whose linear part is the identity, moving points by t.
void TranslationRows(float4 rows[3], float3 t) {
  rows[0] = float4{1.0f, 0.0f, 0.0f, t.x};
  rows[1] = float4{0.0f, 1.0f, 0.0f, t.y};
  rows[2] = float4{0.0f, 0.0f, 1.0f, t.z};
}

// Components that exercise the signs of zero, tiny and huge values and non-finite ones.
const float kSpecial[] = {0.0f,    -0.0f,    1.0f, -1.0f,  1e-40f,           -1e-40f,
                          3.4e38f, -3.4e38f, 0.5f, -2.75f, RT_INFINITY * 10, -RT_INFINITY * 10};

TEST(TranslationInstance, IdentityLinearPartPlusTranslationIsTransformPoint) {
  std::mt19937 rng(7);
  std::uniform_int_distribution<int> pick(0, sizeof kSpecial / sizeof kSpecial[0] - 1);
  std::uniform_real_distribution<float> u(-5, 5);
  for (int i = 0; i < 20000; ++i) {
    auto component = [&]() { return i % 2 ? kSpecial[pick(rng)] : u(rng); };
    float3 p = make_float3(component(), component(), component());
    float3 t = make_float3(component(), component(), component());
    float4 rows[3];
    TranslationRows(rows, t);
    float3 general = TransformPoint(rows, p);
    float3 identity = IdentityLinearPart(p);
    float3 fast =
        make_float3(identity.x + rows[0].w, identity.y + rows[1].w, identity.z + rows[2].w);
    // NaN results (infinite inputs) agree as NaN; everything else bit for bit.
    auto same = [](float a, float b) { return SameBits(a, b) || (a != a && b != b); };
    ASSERT_TRUE(same(general.x, fast.x) && same(general.y, fast.y) && same(general.z, fast.z))
        << "p " << Str(p) << " t " << Str(t) << ": " << Str(general) << " against " << Str(fast);
  }
}

TEST(TranslationInstance, KeptDirectionsAreExactlyTheTransformedOnes) {
  std::mt19937 rng(8);
  std::uniform_int_distribution<int> pick(0, sizeof kSpecial / sizeof kSpecial[0] - 1);
  float4 rows[3];
  TranslationRows(rows, make_float3(3, -4, 5));
  int kept = 0, refused = 0;
  for (int i = 0; i < 20000; ++i) {
    float3 d = make_float3(kSpecial[pick(rng)], kSpecial[pick(rng)], kSpecial[pick(rng)]);
    if (!IdentityKeepsDirection(ReciprocalDirection(d))) {
      ++refused;
      continue;
    }
    ++kept;
    ASSERT_TRUE(SameBits3(TransformVector(rows, d), d)) << "d " << Str(d);
  }
  EXPECT_GT(kept, 1000);
  EXPECT_GT(refused, 1000);
  // The cases the check must refuse: a -0 component that the identity turns into +0, and an
  // infinite one that turns the other components into NaN.
  EXPECT_FALSE(IdentityKeepsDirection(ReciprocalDirection(make_float3(-0.0f, 1.0f, 1.0f))));
  EXPECT_FALSE(
      IdentityKeepsDirection(ReciprocalDirection(make_float3(1.0f, RT_INFINITY * 10, 1.0f))));
  EXPECT_TRUE(IdentityKeepsDirection(ReciprocalDirection(make_float3(0.0f, 0.0f, -1.0f))));
}

struct Mesh {
  std::vector<Vec3d> positions;
  std::vector<std::array<int, 3>> triangles;
};

// A bumpy grid of n x n quads over [-1, 1]^2, tilted so rays meet it from every side, and a
// square in the plane z = 0 through the origin, whose edges and corners lie on the axes that
// rays with zero components run along.
Mesh BumpyGridAndSquare(int n, std::mt19937& rng) {
  Mesh m;
  std::uniform_real_distribution<double> bump(-0.3, 0.3);
  for (int j = 0; j <= n; ++j)
    for (int i = 0; i <= n; ++i) {
      double x = 2.0 * i / n - 1, y = 2.0 * j / n - 1;
      m.positions.push_back(RoundToFloat({x, y, 0.5 * x + bump(rng)}));
    }
  for (int j = 0; j < n; ++j)
    for (int i = 0; i < n; ++i) {
      int a = j * (n + 1) + i, b = a + 1, c = a + n + 1, d = c + 1;
      m.triangles.push_back({a, b, d});
      m.triangles.push_back({a, d, c});
    }
  int base = static_cast<int>(m.positions.size());
  for (Vec3d p : {Vec3d{0, 0, 0}, Vec3d{1, 0, 0}, Vec3d{1, 1, 0}, Vec3d{0, 1, 0}})
    m.positions.push_back(p);
  m.triangles.push_back({base, base + 1, base + 2});
  m.triangles.push_back({base, base + 2, base + 3});
  return m;
}

bool SameHit(bool a_hit, const Hit& a, bool b_hit, const Hit& b) {
  if (a_hit != b_hit) return false;
  if (!a_hit) return true;
  return SameBits(a.t, b.t) && SameBits(a.b1, b.b1) && SameBits(a.b2, b.b2) &&
         a.instance == b.instance && a.primitive == b.primitive;
}

TEST(TranslationInstance, HitsAreTheGeneralPathsBitForBit) {
  std::mt19937 rng(2025);
  Mesh grid = BumpyGridAndSquare(12, rng);
  SceneDesc s = BaseScene();
  int mesh = AddMesh(s, grid.positions, grid.triangles);
  // Translations with zero components on some axes (a -0 or +0 translation there), one
  // instance that is not moved at all, and a rotated one, which takes the general path and
  // makes the direction setup change between instances of one ray.
  const Vec3d moves[] = {{0, 0, 0},      {2.5, 0, 0},   {0, -2.25, 0},  {0, 0, 3},
                         {1.5, 1.5, -1}, {-3, 0.75, 0}, {0.1, 0.2, 0.3}};
  for (Vec3d m : moves) AddMeshObject(s, mesh, Mat4::translation(m));
  AddMeshObject(s, mesh, Mat4::translation({-1, -1, 1}) * Mat4::rotation(30, {0, 0, 1}));
  FlatScene fast = Flatten(s);
  int translated = 0;
  for (size_t i = 0; i < fast.instances.size(); ++i)
    translated += (fast.instances[i].flags & RT_INSTANCE_TRANSLATION) != 0;
  ASSERT_EQ(translated, 6) << "every translated instance must take the shared-direction path";
  // The same scene with the flag cleared takes the general path for every instance.
  FlatScene general = Flatten(s);
  for (size_t i = 0; i < general.instances.size(); ++i)
    general.instances[i].flags &= ~RT_INSTANCE_TRANSLATION;

  std::uniform_real_distribution<float> u(-4, 4), uu(0, 1);
  std::normal_distribution<float> g;
  std::uniform_int_distribution<int> zero(0, 5);
  int hits = 0, bad = 0;
  for (int i = 0; i < 20000; ++i) {
    float3 o = make_float3(u(rng), u(rng), u(rng));
    float3 d = make_float3(g(rng), g(rng), g(rng));
    // Zero components of either sign in the direction and the origin, and origins on the
    // square's edges: the cases where the identity could change a sign of zero.
    float* dc[3] = {&d.x, &d.y, &d.z};
    float* oc[3] = {&o.x, &o.y, &o.z};
    if (i % 4 == 1) *dc[zero(rng) % 3] = zero(rng) % 2 ? 0.0f : -0.0f;
    if (i % 4 == 2) *oc[zero(rng) % 3] = zero(rng) % 2 ? 0.0f : -0.0f;
    if (i % 8 == 3) {
      *dc[0] = zero(rng) % 2 ? 0.0f : -0.0f;
      *dc[1] = zero(rng) % 2 ? 0.0f : -0.0f;
      *dc[2] = zero(rng) % 2 ? 1.0f : -1.0f;
    }
    float tmax = i % 3 == 0 ? 8 * uu(rng) : kInf;
    for (int cull = 0; cull < 2; ++cull)
      for (int any_hit = 0; any_hit < 2; ++any_hit) {
        Hit a, b;
        bool ha = Trace(fast, o, d, tmax, cull, &a, any_hit);
        bool hb = Trace(general, o, d, tmax, cull, &b, any_hit);
        hits += ha;
        // Both paths visit the same nodes in the same order, so even a shadow ray's first
        // hit found is the same.
        bool ok = SameHit(ha, a, hb, b);
        if (!ok && ++bad <= 5)
          ADD_FAILURE() << "ray " << i << " o " << Str(o) << " d " << Str(d) << " cull " << cull
                        << " any_hit " << any_hit << ": " << (ha ? a.t : -1.0f) << " against "
                        << (hb ? b.t : -1.0f);
      }
  }
  EXPECT_EQ(bad, 0);
  EXPECT_GT(hits, 10000);
}

// The kernel compiles the shared-direction path only when the scene header says a mesh
// needs it (RT_FEATURE_WORLD_MESHES, cl/bvh/bvh.h); the bit must be set exactly when some mesh
// instance is untransformed or translated alone, or such an instance would be traced with
// the general path's arithmetic in the kernel and the world's in the CPU reference.
TEST(TranslationInstance, WorldMeshesFeatureIsSetExactlyForSuchMeshes) {
  std::mt19937 rng(11);
  Mesh grid = BumpyGridAndSquare(4, rng);
  const Mat4 rotated = Mat4::rotation(30, {0, 0, 1});
  const Mat4 scaled = Mat4::scaling({2, 2, 2});
  const Mat4 moved = Mat4::translation({1.5, 0, -2});
  struct Case {
    const char* name;
    std::vector<Mat4> meshes;
    bool sphere;
    bool want;
  } cases[] = {
      {"untransformed mesh", {Mat4{}}, false, true},
      {"translated mesh", {moved}, false, true},
      {"rotated mesh", {rotated}, false, false},
      {"scaled mesh", {scaled}, false, false},
      {"rotated and translated meshes", {rotated, moved}, false, true},
      {"sphere only", {}, true, false},
      {"rotated mesh and sphere", {rotated}, true, false},
  };
  for (const Case& c : cases) {
    SceneDesc s = BaseScene();
    int mesh = AddMesh(s, grid.positions, grid.triangles);
    for (const Mat4& m : c.meshes) AddMeshObject(s, mesh, m);
    if (c.sphere) AddSphere(s, Mat4::translation({0, 0, -5}));
    FlatScene f = Flatten(s);
    bool world_instance = false;
    for (const Instance& inst : f.instances)
      world_instance = world_instance || (inst.kind == RT_INSTANCE_MESH &&
                                          ((inst.flags & RT_INSTANCE_TRANSFORMED) == 0 ||
                                           (inst.flags & RT_INSTANCE_TRANSLATION) != 0));
    const bool bit = (f.header.features & RT_FEATURE_WORLD_MESHES) != 0;
    EXPECT_EQ(bit, c.want) << c.name;
    EXPECT_EQ(bit, world_instance) << c.name << ": the bit and the instances' flags disagree";
  }
}

}  // namespace
}  // namespace rt
