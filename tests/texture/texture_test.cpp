// Exact values of the texture maths in cl/texture/: sphere coordinates, image lookups,
// the course's Perlin noise against an independent evaluation, the course's
// checkerboard, tangent frames and the bump and normal-map perturbations.
#include <gtest/gtest.h>

#include <cmath>
#include <vector>

#include "cl/texture/checkerboard.h"
#include "cl/texture/image_texture.h"
#include "cl/texture/perlin.h"
#include "cl/texture/tangent_frame.h"

namespace {

float3 V(float x, float y, float z) { return make_float3(x, y, z); }

void ExpectExact(float3 a, float3 b) {
  EXPECT_EQ(a.x, b.x);
  EXPECT_EQ(a.y, b.y);
  EXPECT_EQ(a.z, b.z);
}

void ExpectNear(float3 a, float3 b, float tol) {
  EXPECT_NEAR(a.x, b.x, tol);
  EXPECT_NEAR(a.y, b.y, tol);
  EXPECT_NEAR(a.z, b.z, tol);
}

// ---- Sphere coordinates (the course's: u = (pi - phi) / 2pi, v = theta / pi) ----

TEST(TextureSphere, CoordinatesAtTheAxes) {
  float2 a = SphereUV(V(1, 0, 0));
  EXPECT_EQ(a.x, 0.5f);
  EXPECT_EQ(a.y, 0.5f);
  float2 b = SphereUV(V(0, 0, 1));
  EXPECT_EQ(b.x, 0.25f);
  EXPECT_EQ(b.y, 0.5f);
  float2 c = SphereUV(V(-1, 0, 0));
  EXPECT_EQ(c.x, 0.0f);
  float2 north = SphereUV(V(0, 1, 0)), south = SphereUV(V(0, -1, 0));
  EXPECT_EQ(north.y, 0.0f);  // v = 0 at the top row of the image.
  EXPECT_EQ(south.y, 1.0f);
}

TEST(TextureSphere, TangentsAreTheDerivativesOfTheCoordinates) {
  float3 dpdu, dpdv;
  SphereTangents(V(1, 0, 0), &dpdu, &dpdv);
  ExpectExact(dpdu, V(0, 0, -2.0f * RT_PI));
  ExpectExact(dpdv, V(0, -RT_PI, 0));
  // Moving along dp/du by h changes u by h (to first order), v not at all.
  float3 p = Normalize(V(0.3f, 0.4f, -0.5f));
  SphereTangents(p, &dpdu, &dpdv);
  const float h = 1e-3f;
  float2 uv = SphereUV(p), du = SphereUV(Normalize(p + dpdu * h)),
         dv = SphereUV(Normalize(p + dpdv * h));
  EXPECT_NEAR(du.x - uv.x, h, 2e-5f);
  EXPECT_NEAR(du.y - uv.y, 0.0f, 2e-5f);
  EXPECT_NEAR(dv.y - uv.y, h, 2e-5f);
  EXPECT_NEAR(dv.x - uv.x, 0.0f, 2e-5f);
}

// ---- Image lookups ----

// A 2 x 2 image: red 0, 100 / 200, 40 (top row first); green and blue 1 and 2.
struct SmallImage {
  std::vector<uint> texels;
  TextureDesc desc{};
  SmallImage() {
    for (uint r : {0u, 100u, 200u, 40u}) texels.push_back(r | (1u << 8) | (2u << 16));
    desc.width = 2;
    desc.height = 2;
    desc.first_texel = 0;
  }
};

TEST(TextureLookup, NearestPicksTheTexelContainingTheScaledPoint) {
  SmallImage im;
  ExpectExact(LookupNearest(im.texels.data(), &im.desc, make_float2(0.25f, 0.75f)), V(200, 1, 2));
  ExpectExact(LookupNearest(im.texels.data(), &im.desc, make_float2(0.5f, 0.0f)), V(100, 1, 2));
  // u = v = 1 is the far edge: the edge texel repeats, as beyond it.
  ExpectExact(LookupNearest(im.texels.data(), &im.desc, make_float2(1.0f, 1.0f)), V(40, 1, 2));
  ExpectExact(LookupNearest(im.texels.data(), &im.desc, make_float2(-0.5f, 7.0f)), V(200, 1, 2));
}

TEST(TextureLookup, BilinearWeighsTexelAndNeighboursByTheFraction) {
  SmallImage im;
  // (u W, v H) = (0.5, 0.5): the four texels equally, (0 + 100 + 200 + 40) / 4.
  ExpectExact(LookupBilinear(im.texels.data(), &im.desc, make_float2(0.25f, 0.25f)), V(85, 1, 2));
  // On a texel's corner: exactly that texel.
  ExpectExact(LookupBilinear(im.texels.data(), &im.desc, make_float2(0.5f, 0.0f)), V(100, 1, 2));
  // Past the last column the edge repeats: (0.75 W) = 1.5 blends texel 1 with itself.
  ExpectExact(LookupBilinear(im.texels.data(), &im.desc, make_float2(0.75f, 0.0f)), V(100, 1, 2));
  // A quarter of the way from texel 0 to texel 1 of the top row.
  ExpectExact(LookupBilinear(im.texels.data(), &im.desc, make_float2(0.125f, 0.0f)), V(25, 1, 2));
}

// ---- Perlin noise ----

TEST(TexturePerlin, ZeroOnTheLattice) {
  for (int i = -3; i <= 3; ++i)
    for (int j = -3; j <= 3; ++j) EXPECT_EQ(PerlinNoise(V(i, j, 2 * i - j)), 0.0f);
}

TEST(TexturePerlin, MatchesAnIndependentEvaluationOfTheCourseLattice) {
  // The recovered lattice (docs/textures.md) evaluated in double by a separate script at
  // the same float inputs; the float evaluation agrees to a few ulps.
  EXPECT_EQ(PerlinNoise(V(0.5f, 0.5f, 0.5f)), -0.125f);
  EXPECT_NEAR(PerlinNoise(V(1.25f, -2.75f, 3.5f)), 0.4281759262084961, 1e-6);
  EXPECT_NEAR(PerlinNoise(V(3.14f, 42.0f, -7.0f)), -0.11799976488291508, 1e-6);
  EXPECT_NEAR(PerlinNoise(V(-0.3f, 0.7f, 100.9f)), -0.04577333901249517, 1e-6);
}

TEST(TexturePerlin, SlopeAtALatticePointIsItsGradient) {
  // G[P[0 + P[0 + P[0]]]] = G[P[P[4]]] = G[P[14]] = G[0] = (1, 1, 0); at (-1, -1, -1)
  // the indices are taken as |i| mod 16: G[P[|-1 + P[|-1 + P[1]|]|]] = G[6] = (1, 0, -1).
  // (The far corners' weights, 1 - fade(1 - h), cancel in float to within ~1e-6.)
  const float h = 1e-3f;
  EXPECT_NEAR(PerlinNoise(V(h, 0, 0)) / h, 1.0f, 2e-3f);
  EXPECT_NEAR(PerlinNoise(V(0, h, 0)) / h, 1.0f, 2e-3f);
  EXPECT_NEAR(PerlinNoise(V(0, 0, h)) / h, 0.0f, 2e-3f);
  EXPECT_NEAR(PerlinNoise(V(-1 + h, -1, -1)) / h, 1.0f, 2e-3f);
  EXPECT_NEAR(PerlinNoise(V(-1, -1 + h, -1)) / h, 0.0f, 2e-3f);
  EXPECT_NEAR(PerlinNoise(V(-1, -1, -1 + h)) / h, -1.0f, 2e-3f);
}

TEST(TexturePerlin, ConversionsAndScale) {
  TextureDesc t{};
  t.noise_scale = 2.0f;
  t.noise_conversion = RT_NOISE_LINEAR;
  EXPECT_EQ(PerlinTexture(&t, V(0.25f, 0.25f, 0.25f)), 0.4375f);  // (-0.125 + 1) / 2
  t.noise_conversion = RT_NOISE_ABSVAL;
  EXPECT_EQ(PerlinTexture(&t, V(0.25f, 0.25f, 0.25f)), 0.125f);
}

// ---- Checkerboard (the specification's pseudo-code, integer cast towards zero) ----

TEST(TextureCheckerboard, FollowsThePseudoCodeLiterally) {
  TextureDesc t{};
  t.black = V(0, 0, 0);
  t.white = V(1, 1, 1);
  t.checker_scale = 1.0f;
  t.checker_offset = 0.0f;
  ExpectExact(CheckerboardTexture(&t, V(0.5f, 0.5f, 0.5f)), t.white);  // 0, 0, 0
  ExpectExact(CheckerboardTexture(&t, V(1.5f, 0.5f, 0.5f)), t.black);  // 1, 0, 0
  ExpectExact(CheckerboardTexture(&t, V(1.5f, 1.5f, 0.5f)), t.white);  // 1, 1, 0
  ExpectExact(CheckerboardTexture(&t, V(1.5f, 1.5f, 1.5f)), t.black);  // 1, 1, 1
  // (int)(-0.5) is 0, as (int)(0.5): the squares either side of 0 have one colour.
  ExpectExact(CheckerboardTexture(&t, V(-0.5f, 0.5f, 0.5f)), t.white);
  // -1.5 casts to -1 and -1 % 2 is -1, which counts as odd.
  ExpectExact(CheckerboardTexture(&t, V(-1.5f, 0.5f, 0.5f)), t.black);
  t.checker_scale = 2.0f;
  t.checker_offset = 0.25f;
  ExpectExact(CheckerboardTexture(&t, V(0.3f, 0.0f, 0.0f)), t.black);  // (int)1.1 = 1
}

// ---- Tangent frames and perturbed normals ----

TEST(TextureTangents, TriangleTangentsSolveTheEdgeEquations) {
  float3 dpdu, dpdv;
  TriangleTangents(V(0, 0, 0), V(2, 0, 0), V(0, 3, 0), make_float2(0, 0), make_float2(1, 0),
                   make_float2(0, 1), &dpdu, &dpdv);
  ExpectExact(dpdu, V(2, 0, 0));
  ExpectExact(dpdv, V(0, 3, 0));
  // A mirrored mapping (u decreasing along x, v down the image) flips the tangents.
  TriangleTangents(V(0, 0, 0), V(1, 0, 0), V(0, 1, 0), make_float2(1, 1), make_float2(0, 1),
                   make_float2(1, 0), &dpdu, &dpdv);
  ExpectExact(dpdu, V(-1, 0, 0));
  ExpectExact(dpdv, V(0, -1, 0));
  // All corners at one uv: no frame.
  TriangleTangents(V(0, 0, 0), V(1, 0, 0), V(0, 1, 0), make_float2(0.5f, 0.5f),
                   make_float2(0.5f, 0.5f), make_float2(0.5f, 0.5f), &dpdu, &dpdv);
  ExpectExact(dpdu, V(0, 0, 0));
}

TEST(TextureTangents, NormalMapFrame) {
  float3 n = V(0, 0, 1), dpdu = V(3, 0, 0.5f), dpdv = V(0, 2, 0);
  ExpectExact(TangentToWorld(n, dpdu, dpdv, V(0, 0, 1)), n);  // The flat normal (128,128,255).
  ExpectExact(TangentToWorld(n, dpdu, dpdv, V(1, 0, 0)), V(1, 0, 0));
  ExpectExact(TangentToWorld(n, dpdu, dpdv, V(0, 1, 0)), V(0, 1, 0));
  // v follows dp/dv also when the frame is left-handed.
  ExpectExact(TangentToWorld(n, dpdu, V(0, -2, 0), V(0, 1, 0)), V(0, -1, 0));
  ExpectNear(TangentToWorld(n, dpdu, dpdv, Normalize(V(1, 1, 1))), Normalize(V(1, 1, 1)), 1e-6f);
}

TEST(TextureTangents, BumpedNormals) {
  float3 n = V(0, 0, 1), dpdu = V(1, 0, 0), dpdv = V(0, 1, 0);
  ExpectExact(BumpedNormal(n, dpdu, dpdv, 0.0f, 0.0f), n);
  // Height rising by 1 per unit u: the normal of the slope z = x.
  ExpectNear(BumpedNormal(n, dpdu, dpdv, 1.0f, 0.0f),
             V(-1 / std::sqrt(2.0f), 0, 1 / std::sqrt(2.0f)), 1e-7f);
  // Oriented like n whatever the handedness of the tangents.
  ExpectNear(BumpedNormal(n, dpdu, V(0, -1, 0), 0.0f, 1.0f),
             V(0, 1 / std::sqrt(2.0f), 1 / std::sqrt(2.0f)), 1e-7f);
  // A gradient in space tilts the normal by its tangential part only.
  ExpectExact(GradientBumpedNormal(n, V(0, 0, 5)), n);
  ExpectNear(GradientBumpedNormal(n, V(1, 0, 5)), V(-1 / std::sqrt(2.0f), 0, 1 / std::sqrt(2.0f)),
             1e-7f);
}

}  // namespace
