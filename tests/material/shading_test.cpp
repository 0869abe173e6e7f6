// Tests for the shared shading code (cl/material/fresnel.h): Fresnel reflectance of
// dielectrics and conductors, refraction and Beer-Lambert attenuation, against closed forms
// evaluated in double precision (Blinn-Phong and Reflect: blinn_phong_test.cpp).
//
// Tolerances: results whose operands are exactly representable and whose operations are
// exact (dyadic values, multiplications by 1) are compared with ==; others allow a few float
// roundings (relative ~1e-7 each) of the handful of operations involved.
#include <gtest/gtest.h>

#include <cmath>
#include <complex>
#include <random>
#include <string>
#include <utility>
#include <vector>

#include "cl/material/blinn_phong.h"
#include "cl/material/fresnel.h"

namespace rt {
namespace {

constexpr double kPi = 3.14159265358979323846;

// Fresnel equations for a dielectric in double: unpolarized reflectance for light going
// from index n1 into n2 with incident cosine c.
double FresnelDielectric(double c, double n1, double n2, double* cos_t) {
  double s2 = (n1 / n2) * (n1 / n2) * (1 - c * c);
  if (s2 >= 1) {
    *cos_t = 0;
    return 1;
  }
  double ct = std::sqrt(1 - s2);
  *cos_t = ct;
  double rs = (n1 * c - n2 * ct) / (n1 * c + n2 * ct);
  double rp = (n2 * c - n1 * ct) / (n2 * c + n1 * ct);
  return 0.5 * (rs * rs + rp * rp);
}

// Exact Fresnel reflectance of a conductor with complex index n + ik seen from air.
double FresnelConductorExact(double c, double n, double k) {
  std::complex<double> eta(n, k);
  std::complex<double> ct = std::sqrt(eta * eta - (1 - c * c)) / eta;
  std::complex<double> rs = (c - eta * ct) / (c + eta * ct);
  std::complex<double> rp = (eta * c - ct) / (eta * c + ct);
  return 0.5 * (std::norm(rs) + std::norm(rp));
}

float3 V(float x, float y, float z) { return make_float3(x, y, z); }

// ------------------------------------------------------------------------------------------
// FrDielectric
// ------------------------------------------------------------------------------------------

TEST(ShadingFrDielectric, NormalIncidence) {
  const float pairs[][2] = {{1.0f, 1.5f}, {1.5f, 1.0f}, {1.0f, 2.4f}, {1.33f, 1.0f}, {1.2f, 1.7f}};
  for (auto& p : pairs) {
    float cos_t = -1;
    float r = FrDielectric(1.0f, p[0], p[1], &cos_t);
    double expect = ((double(p[0]) - p[1]) / (double(p[0]) + p[1]));
    expect *= expect;
    EXPECT_NEAR(r, expect, 1e-7) << p[0] << " -> " << p[1];
    EXPECT_EQ(cos_t, 1.0f);
  }
  // 1 -> 1.5 is the classic 4%.
  float cos_t;
  EXPECT_NEAR(FrDielectric(1.0f, 1.0f, 1.5f, &cos_t), 0.04f, 1e-7);
}

TEST(ShadingFrDielectric, MatchedIndicesReflectNothing) {
  for (float eta : {1.0f, 1.5f, 2.4f})
    for (float c : {1.0f, 0.9f, 0.70710677f, 0.5f, 0.3f, 0.1f, 0.05f, 0.01f}) {
      float cos_t = -1;
      float r = FrDielectric(c, eta, eta, &cos_t);
      // The only error is cos_t = sqrt(1 - (1 - c^2)) instead of c: relative ~1e-7 / c^2.
      EXPECT_NEAR(r, 0.0f, 1e-7) << "eta " << eta << " cos " << c;
      EXPECT_NEAR(cos_t, c, 1e-7 / c) << "eta " << eta << " cos " << c;
    }
}

TEST(ShadingFrDielectric, MatchedIndicesNearGrazingTransmitEverything) {
  // Equal indices mean no interface: nothing is reflected at any angle short of exactly
  // grazing, and there is no total internal reflection.
  for (float c : {2e-3f, 1e-3f, 3e-4f, 1e-4f, 1e-5f}) {
    float cos_t = -1;
    float r = FrDielectric(c, 1.5f, 1.5f, &cos_t);
    EXPECT_NEAR(r, 0.0f, 1e-6) << "cos " << c;
    EXPECT_NEAR(cos_t, c, 1e-3 * c) << "cos " << c;
  }
}

TEST(ShadingFrDielectric, GrazingReflectsEverything) {
  const float pairs[][2] = {{1.0f, 1.5f}, {1.0f, 1.33f}, {1.5f, 1.0f}, {1.0f, 2.4f}};
  for (auto& p : pairs) {
    float cos_t = -1;
    EXPECT_EQ(FrDielectric(0.0f, p[0], p[1], &cos_t), 1.0f) << p[0] << " -> " << p[1];
  }
  // Approaching grazing the reflectance rises monotonically towards 1.
  float cos_t, prev = 0;
  for (float c = 1.0f; c > 1e-3f; c *= 0.8f) {
    float r = FrDielectric(c, 1.0f, 1.5f, &cos_t);
    EXPECT_GE(r, prev - 1e-7f) << "cos " << c;
    prev = r;
  }
  EXPECT_GT(prev, 0.99f);
}

TEST(ShadingFrDielectric, TotalInternalReflectionBeyondTheCriticalAngle) {
  // From 1.5 into 1: critical angle at sin = 1/1.5, cos = sqrt(5)/3 = 0.745356.
  const double critical = std::sqrt(5.0) / 3;
  for (float c : {0.745f, 0.74f, 0.7f, 0.5f, 0.2f, 0.01f, 0.0f}) {
    ASSERT_LT(c, critical);
    float cos_t = -1;
    EXPECT_EQ(FrDielectric(c, 1.5f, 1.0f, &cos_t), 1.0f) << "cos " << c;
    EXPECT_EQ(cos_t, 0.0f) << "cos " << c;
  }
  for (float c : {0.7456f, 0.75f, 0.8f, 1.0f}) {
    ASSERT_GT(c, critical);
    float cos_t = -1;
    float r = FrDielectric(c, 1.5f, 1.0f, &cos_t);
    EXPECT_LT(r, 1.0f) << "cos " << c;
    EXPECT_GT(cos_t, 0.0f) << "cos " << c;
  }
}

TEST(ShadingFrDielectric, MatchesFresnelEquationsAt45DegreesAndAcrossAngles) {
  const float c45 = static_cast<float>(std::cos(kPi / 4));
  double ct_ref;
  float cos_t;
  // Entering glass at 45 degrees: R = 0.0502 (rs^2 = 0.0920, rp^2 = 0.0085).
  double expect = FresnelDielectric(c45, 1.0, 1.5, &ct_ref);
  EXPECT_NEAR(expect, 0.0502, 1e-4);  // Sanity of the reference itself.
  EXPECT_NEAR(FrDielectric(c45, 1.0f, 1.5f, &cos_t), expect, 1e-6);
  EXPECT_NEAR(cos_t, ct_ref, 1e-6);
  // Leaving glass at 20 degrees (below the critical angle of 41.8 degrees).
  const float c20 = static_cast<float>(std::cos(20 * kPi / 180));
  expect = FresnelDielectric(c20, 1.5, 1.0, &ct_ref);
  EXPECT_NEAR(FrDielectric(c20, 1.5f, 1.0f, &cos_t), expect, 1e-6);
  EXPECT_NEAR(cos_t, ct_ref, 1e-6);
  // Every degree, both directions; Brewster's angle (rp = 0) falls in the sweep.
  for (int deg = 0; deg < 90; ++deg) {
    float c = static_cast<float>(std::cos(deg * kPi / 180));
    for (auto n : {std::pair<float, float>{1.0f, 1.5f}, {1.5f, 1.0f}, {1.0f, 2.4f}}) {
      expect = FresnelDielectric(c, n.first, n.second, &ct_ref);
      float r = FrDielectric(c, n.first, n.second, &cos_t);
      // Near the critical angle cos_t = sqrt(1 - sin2_t) amplifies float error; 1e-5 covers
      // one degree away from it.
      EXPECT_NEAR(r, expect, 1e-5) << deg << " degrees, " << n.first << " -> " << n.second;
      EXPECT_NEAR(cos_t, ct_ref, 1e-5) << deg << " degrees, " << n.first << " -> " << n.second;
    }
  }
}

// ------------------------------------------------------------------------------------------
// FrConductor
// ------------------------------------------------------------------------------------------

TEST(ShadingFrConductor, NormalIncidence) {
  const float nk[][2] = {{0.27f, 2.78f}, {1.2f, 7.0f}, {0.2f, 3.0f}, {1.5f, 0.0f}, {2.9f, 3.0f}};
  for (auto& p : nk) {
    double n = p[0], k = p[1];
    double expect = ((n - 1) * (n - 1) + k * k) / ((n + 1) * (n + 1) + k * k);
    EXPECT_NEAR(FrConductor(1.0f, p[0], p[1]), expect, 1e-6) << n << " + " << k << "i";
  }
}

TEST(ShadingFrConductor, GrazingApproachesOne) {
  const float nk[][2] = {{0.27f, 2.78f}, {1.2f, 7.0f}, {2.9f, 3.0f}};
  for (auto& p : nk) {
    EXPECT_NEAR(FrConductor(0.0f, p[0], p[1]), 1.0f, 1e-6);
    // Near grazing R = 1 - O(cos): within 4 n cos of 1.
    EXPECT_NEAR(FrConductor(1e-4f, p[0], p[1]), 1.0f, 4 * p[0] * 1e-4 + 1e-6);
    EXPECT_LT(FrConductor(0.5f, p[0], p[1]), FrConductor(0.0f, p[0], p[1]));
  }
}

TEST(ShadingFrConductor, CloseToExactComplexFresnelForMetals) {
  // The course's form drops cross terms; for metals (k >> 1) it stays within 0.01 of the
  // exact complex Fresnel equations at every angle (0.005 in the worst case below).
  const float nk[][2] = {{0.27f, 2.78f}, {1.2f, 7.0f}, {0.2f, 3.0f}, {2.9f, 3.0f}};
  for (auto& p : nk)
    for (int deg = 0; deg <= 90; ++deg) {
      float c = static_cast<float>(std::cos(deg * kPi / 180));
      EXPECT_NEAR(FrConductor(c, p[0], p[1]), FresnelConductorExact(c, p[0], p[1]), 1e-2)
          << deg << " degrees, " << p[0] << " + " << p[1] << "i";
    }
}

// ------------------------------------------------------------------------------------------
// Refract
// ------------------------------------------------------------------------------------------

TEST(ShadingRefract, SnellsLawAndUnitLength) {
  std::mt19937 rng(8);
  std::normal_distribution<float> g;
  std::uniform_real_distribution<float> u(0.02f, 1.0f);
  const float pairs[][2] = {{1.0f, 1.5f}, {1.5f, 1.0f}, {1.0f, 2.4f}, {1.33f, 1.0f}};
  int checked = 0;
  for (int i = 0; i < 4000; ++i) {
    float3 n = Normalize(V(g(rng), g(rng), g(rng)));
    // Incident direction towards the surface, from the side n faces, cosine c.
    float3 tx, ty;
    CoordinateSystem(n, &tx, &ty);
    float c = u(rng);
    float phi = 6.2831853f * u(rng);
    float s = std::sqrt(1 - c * c);
    float3 d = Normalize(-n * c + (tx * std::cos(phi) + ty * std::sin(phi)) * s);
    const float* p = pairs[i % 4];
    float eta = p[0] / p[1];
    float cos_i = -Dot(d, n);
    float cos_t;
    FrDielectric(cos_i, p[0], p[1], &cos_t);
    if (cos_t <= 0.0f) continue;  // Total internal reflection: nothing to refract.
    ++checked;
    float3 t = Refract(d, n, eta, cos_i, cos_t);
    EXPECT_NEAR(Length(t), 1.0f, 1e-6);
    double sin_i = Length(Cross(d, n)), sin_t = Length(Cross(t, n));
    EXPECT_NEAR(sin_t, eta * sin_i, 1e-6) << "ray " << i;
    // Transmitted to the other side with the cosine FrDielectric reported, in the plane of
    // incidence, and on the same side of the normal tangentially.
    EXPECT_NEAR(Dot(t, n), -cos_t, 1e-6) << "ray " << i;
    EXPECT_NEAR(Dot(t, Normalize(Cross(d, n))), 0.0f, 1e-6) << "ray " << i;
    float3 dt = d + n * cos_i, tt = t + n * cos_t;  // Tangential parts.
    if (Length(dt) > 1e-3f) {
      EXPECT_GT(Dot(dt, tt), 0.0f) << "ray " << i;
    }
  }
  EXPECT_GT(checked, 2000);
}

TEST(ShadingRefract, StraightThroughAtNormalIncidence) {
  for (float3 n : {V(0, 0, 1), V(0, -1, 0), V(1, 0, 0)})
    for (float eta : {1.0f / 1.5f, 1.5f, 1.0f}) {
      float3 t = Refract(-n, n, eta, 1.0f, 1.0f);
      EXPECT_EQ(t.x, -n.x);
      EXPECT_EQ(t.y, -n.y);
      EXPECT_EQ(t.z, -n.z);
    }
  float3 n = Normalize(V(1, -2, 3));
  float cos_t;
  FrDielectric(1.0f, 1.0f, 1.5f, &cos_t);
  float3 t = Refract(-n, n, 1.0f / 1.5f, 1.0f, cos_t);
  // A few roundings of components below 1: up to 4 ulps (6e-8 each).
  EXPECT_NEAR(t.x, -n.x, 2.4e-7);
  EXPECT_NEAR(t.y, -n.y, 2.4e-7);
  EXPECT_NEAR(t.z, -n.z, 2.4e-7);
}

// ------------------------------------------------------------------------------------------
// BeerLambert
// ------------------------------------------------------------------------------------------

// Both exponentials: the library's (the ray tree's) and the portable one (the path's).
TEST(ShadingBeerLambert, ZeroDistanceAndZeroAbsorptionAttenuateNothing) {
  for (int portable : {0, 1}) {
    float3 one = BeerLambert(V(0.5f, 3.0f, 100.0f), 0.0f, portable);
    EXPECT_EQ(one.x, 1.0f);
    EXPECT_EQ(one.y, 1.0f);
    EXPECT_EQ(one.z, 1.0f);
    float3 clear = BeerLambert(V(0, 0, 0), 123.0f, portable);
    EXPECT_EQ(clear.x, 1.0f);
    EXPECT_EQ(clear.y, 1.0f);
    EXPECT_EQ(clear.z, 1.0f);
  }
}

TEST(ShadingBeerLambert, MatchesExpPerChannel) {
  const float3 cs[] = {V(0.1f, 1.0f, 5.0f), V(0.01f, 0.25f, 2.5f), V(3.0f, 0.0f, 0.7f)};
  for (int portable : {0, 1})
    for (float3 c : cs)
      for (float d : {0.001f, 0.3f, 1.0f, 2.75f, 10.0f}) {
        float3 a = BeerLambert(c, d, portable);
        const float ch[3] = {c.x, c.y, c.z}, got[3] = {a.x, a.y, a.z};
        for (int k = 0; k < 3; ++k) {
          double x = -double(ch[k]) * d;
          double expect = std::exp(x);
          // One rounding of c * d (relative 2^-24 of x, scaled by |x| through exp) plus the
          // float exp's own error and the final rounding: a couple of ulps.
          double tol = expect * (std::fabs(x) * 6e-8 + 2.4e-7);
          EXPECT_NEAR(got[k], expect, tol) << "c " << ch[k] << " d " << d;
        }
      }
  // Attenuation over a + b is the product of the attenuations.
  float3 c = V(0.3f, 1.1f, 2.0f);
  float3 ab = BeerLambert(c, 1.5f, 0), a = BeerLambert(c, 0.5f, 0), b = BeerLambert(c, 1.0f, 0);
  EXPECT_NEAR(ab.x, a.x * b.x, 1e-6);
  EXPECT_NEAR(ab.y, a.y * b.y, 1e-6);
  EXPECT_NEAR(ab.z, a.z * b.z, 1e-6);
}

}  // namespace
}  // namespace rt
