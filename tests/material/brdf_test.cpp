// Tests of the reflection models of assignment 6 (cl/material/brdf.h) against closed forms:
// directional albedo by quadrature (white furnace), reciprocity, the sampling routines
// against their densities (chi-square at significance 1e-3), and the original Blinn-Phong
// against the shading of assignments 1-5, bit for bit.
#include <gtest/gtest.h>

#include <cmath>
#include <random>
#include <string>
#include <vector>

#include "cl/material/blinn_phong.h"
#include "cl/material/brdf.h"

namespace rt {
namespace {

constexpr double kPi = 3.14159265358979323846;

float3 Dir(double theta, double phi) {
  return make_float3(static_cast<float>(std::sin(theta) * std::cos(phi)),
                     static_cast<float>(std::sin(theta) * std::sin(phi)),
                     static_cast<float>(std::cos(theta)));
}

BrdfParams Params(int model, int flags, float kd, float ks, float exponent) {
  BrdfParams b;
  b.kd = make_float3(kd, kd, kd);
  b.ks = make_float3(ks, ks, ks);
  b.exponent = exponent;
  b.model = model;
  b.flags = flags;
  b.eta = 0.37f;  // Gold, as in the course's Torrance-Sparrow scene.
  b.kappa = 2.82f;
  return b;
}

const float3 kN = make_float3(0, 0, 1);

// Integral over the sphere of g(direction), midpoint rule on a grid uniform in cos(theta)
// and phi (uniform in solid angle), fine enough for exponents up to ~100.
template <class G>
double SphereIntegral(G g, int n_cos = 2000, int n_phi = 400) {
  double sum = 0;
  for (int i = 0; i < n_cos; ++i) {
    double c = -1 + (i + 0.5) * 2.0 / n_cos, s = std::sqrt(std::max(0.0, 1 - c * c));
    for (int j = 0; j < n_phi; ++j) {
      double phi = (j + 0.5) * 2 * kPi / n_phi;
      sum += g(make_float3(static_cast<float>(s * std::cos(phi)),
                           static_cast<float>(s * std::sin(phi)), static_cast<float>(c)));
    }
  }
  return sum * (2.0 / n_cos) * (2 * kPi / n_phi);
}

// Directional albedo: the reflected share of light arriving from everywhere, seen from wo.
double Albedo(const BrdfParams& b, float3 wo, int n_cos = 2000, int n_phi = 400) {
  return SphereIntegral([&](float3 wi) { return static_cast<double>(BrdfFCos(&b, kN, wo, wi).x); },
                        n_cos, n_phi);
}

struct Model {
  const char* name;
  int model, flags;
};
const Model kNormalizedModels[] = {
    {"normalized modified Phong", RT_BRDF_MODIFIED_PHONG, RT_BRDF_NORMALIZED},
    {"normalized modified Blinn-Phong", RT_BRDF_MODIFIED_BLINN_PHONG, RT_BRDF_NORMALIZED},
    {"Torrance-Sparrow", RT_BRDF_TORRANCE_SPARROW, 0},
    {"Torrance-Sparrow kdfresnel", RT_BRDF_TORRANCE_SPARROW, RT_BRDF_KD_FRESNEL},
};

// A Lambertian surface (ks = 0) reflects exactly kd of a white furnace from any direction.
TEST(Brdf, WhiteFurnaceLambertian) {
  for (const Model& m : kNormalizedModels) {
    if (m.flags & RT_BRDF_KD_FRESNEL) continue;  // (1 - F) kd is not Lambertian.
    BrdfParams b = Params(m.model, m.flags, 0.8f, 0.0f, 50);
    for (double theta : {0.0, 0.5, 1.0, 1.4})
      EXPECT_NEAR(Albedo(b, Dir(theta, 0.3)), 0.8, 1e-3) << m.name << " theta " << theta;
  }
}

// The normalized Phong lobe holds exactly ks at normal incidence, where no part of it is cut
// by the horizon: (p + 2) / (2 pi) cos^p cos integrates to 1.
TEST(Brdf, WhiteFurnaceNormalizedPhongLobe) {
  for (float p : {1.0f, 10.0f, 50.0f}) {
    BrdfParams b = Params(RT_BRDF_MODIFIED_PHONG, RT_BRDF_NORMALIZED, 0.0f, 1.0f, p);
    EXPECT_NEAR(Albedo(b, kN), 1.0, 2e-3) << "p " << p;
  }
}

// The normalized Blinn-Phong's albedo at normal incidence in closed form: with x = cos(t / 2),
// (p + 8) / 4 * integral over [1/sqrt 2, 1] of 4 x^(p+1) (2 x^2 - 1) dx. Its factor
// (p + 8) / (8 pi) is an approximation of the exact normalization: 1.0748 at p = 10.
double BlinnAlbedoAtNormal(double p) {
  auto antiderivative = [p](double x) {
    return 4 * (2 * std::pow(x, p + 4) / (p + 4) - std::pow(x, p + 2) / (p + 2));
  };
  return (p + 8) / 4 * (antiderivative(1.0) - antiderivative(std::sqrt(0.5)));
}

TEST(Brdf, WhiteFurnaceNormalizedBlinnPhongLobe) {
  for (float p : {1.0f, 10.0f, 50.0f}) {
    BrdfParams b = Params(RT_BRDF_MODIFIED_BLINN_PHONG, RT_BRDF_NORMALIZED, 0.0f, 1.0f, p);
    EXPECT_NEAR(Albedo(b, kN), BlinnAlbedoAtNormal(p), 2e-3) << "p " << p;
  }
}

// Energy conservation: with kd + ks = 1, no normalized model reflects more than arrives, from
// any direction (0.3 % allowance for the quadrature), but for the normalized Blinn-Phong, whose
// approximate factor reflects up to its albedo at normal incidence (above).
TEST(Brdf, WhiteFurnaceConservesEnergy) {
  for (const Model& m : kNormalizedModels)
    for (float p : {1.0f, 10.0f, 50.0f})
      for (double ks : {0.5, 1.0}) {  // ks = 0: WhiteFurnaceLambertian.
        BrdfParams b =
            Params(m.model, m.flags, static_cast<float>(1 - ks), static_cast<float>(ks), p);
        for (double theta : {0.0, 0.4, 0.8, 1.2, 1.5}) {
          double a = Albedo(b, Dir(theta, 1.1), 800, 200);
          double bound =
              (m.model == RT_BRDF_MODIFIED_BLINN_PHONG ? std::max(1.0, BlinnAlbedoAtNormal(p))
                                                       : 1.0) +
              3e-3;
          EXPECT_LE(a, bound) << m.name << " p " << p << " ks " << ks << " theta " << theta;
          EXPECT_GT(a, 0.0) << m.name;
        }
      }
}

// f(wo, wi) = f(wi, wo) for the modified and normalized models. The original models divide
// by cos(t_i) and Torrance-Sparrow evaluates F at the angle of incidence (the course's
// convention), so for them only those factors may break the symmetry.
TEST(Brdf, Reciprocity) {
  std::mt19937 rng(7);
  std::uniform_real_distribution<double> u(0, 1);
  const int models[] = {RT_BRDF_ORIGINAL_BLINN_PHONG, RT_BRDF_ORIGINAL_PHONG,
                        RT_BRDF_MODIFIED_BLINN_PHONG, RT_BRDF_MODIFIED_PHONG,
                        RT_BRDF_TORRANCE_SPARROW};
  for (int model : models)
    for (int flags : {0, RT_BRDF_NORMALIZED}) {
      BrdfParams b = Params(model, flags, 0.3f, 0.7f, 20);
      if (model == RT_BRDF_TORRANCE_SPARROW || model <= RT_BRDF_ORIGINAL_PHONG) b.kd = Vec3(0.0f);
      for (int i = 0; i < 1000; ++i) {
        float3 a = Dir(std::acos(u(rng)), 2 * kPi * u(rng));
        float3 c = Dir(std::acos(u(rng)), 2 * kPi * u(rng));
        double ca = a.z, cc = c.z;
        double f_ac = BrdfFCos(&b, kN, a, c).x / cc, f_ca = BrdfFCos(&b, kN, c, a).x / ca;
        if (model == RT_BRDF_TORRANCE_SPARROW) {
          f_ac /= FrConductor(c.z, b.eta, b.kappa);
          f_ca /= FrConductor(a.z, b.eta, b.kappa);
        } else if (model <= RT_BRDF_ORIGINAL_PHONG) {
          f_ac *= cc;
          f_ca *= ca;
        }
        ASSERT_NEAR(f_ac, f_ca, 2e-5 * std::max(1.0, std::fabs(f_ac)))
            << "model " << model << " flags " << flags;
      }
    }
}

// The original Blinn-Phong is the shading of assignments 1-5: the same float operations.
TEST(Brdf, OriginalBlinnPhongIsTheCoursesShadingBitForBit) {
  std::mt19937 rng(3);
  std::uniform_real_distribution<double> u(0, 1);
  Material m{};
  m.diffuse = make_float3(0.5f, 0.43f, 0.285f);
  m.specular = make_float3(1.0f, 0.86f, 0.57f);
  m.phong_exponent = 50;
  BrdfParams b = Params(RT_BRDF_ORIGINAL_BLINN_PHONG, 0, 0, 0, 50);
  b.kd = m.diffuse;
  b.ks = m.specular;
  for (int i = 0; i < 1000; ++i) {
    float3 wo = Dir(std::acos(u(rng)), 2 * kPi * u(rng)),
           wi = Dir(std::acos(u(rng)), 2 * kPi * u(rng));
    float3 e = make_float3(1.0f, 1.0f, 1.0f);
    float3 want = BlinnPhong(&m, kN, wo, wi, e), got = BrdfFCos(&b, kN, wo, wi) * e;
    ASSERT_EQ(want.x, got.x);
    ASSERT_EQ(want.y, got.y);
    ASSERT_EQ(want.z, got.z);
  }
}

// Upper critical value of chi-square at significance 1e-3 (Wilson-Hilferty).
double ChiSquareCritical(int df) {
  const double z = 3.0902;
  double h = 2.0 / (9.0 * df);
  return df * std::pow(1 - h + z * std::sqrt(h), 3);
}

// Sampling against the density: the density integrates to the share of draws that are not
// lost (1 but for half vectors facing away from wo at grazing angles), every sample
// reports the density and value that BrdfPdf and BrdfFCos give its direction, and a
// histogram over (cos(theta), phi) cells follows the density (chi-square, significance 1e-3;
// cells expecting fewer than 5 samples are pooled).
TEST(Brdf, SamplingMatchesDensity) {
  struct Case {
    int model, flags;
    float kd, ks, p;
    double theta_o;
  };
  const Case cases[] = {
      {RT_BRDF_MODIFIED_PHONG, RT_BRDF_NORMALIZED, 0.5f, 0.5f, 20, 0.6},
      {RT_BRDF_ORIGINAL_PHONG, 0, 0.2f, 0.8f, 5, 1.2},
      {RT_BRDF_MODIFIED_BLINN_PHONG, RT_BRDF_NORMALIZED, 0.5f, 0.5f, 30, 0.3},
      {RT_BRDF_ORIGINAL_BLINN_PHONG, 0, 0.5f, 0.5f, 50, 1.0},
      {RT_BRDF_TORRANCE_SPARROW, 0, 0.3f, 0.7f, 50, 0.8},
      {RT_BRDF_TORRANCE_SPARROW, 0, 0.0f, 1.0f, 10, 1.0},
      {RT_BRDF_MODIFIED_PHONG, 0, 1.0f, 0.0f, 1, 0.5},
  };
  const int kCos = 24, kPhi = 24, kSamples = 300000;
  for (const Case& c : cases) {
    BrdfParams b = Params(c.model, c.flags, c.kd, c.ks, c.p);
    float3 wo = Dir(c.theta_o, 0.4);
    std::string what = "model " + std::to_string(c.model) + " p " + std::to_string(c.p);
    double mass = SphereIntegral([&](float3 wi) { return double(BrdfPdf(&b, kN, wo, wi)); });
    int lost = 0;
    std::vector<double> observed(kCos * kPhi, 0.0), expected(kCos * kPhi, 0.0);
    std::mt19937 rng(11);
    std::uniform_real_distribution<float> u(0.0f, 1.0f);
    for (int i = 0; i < kSamples; ++i) {
      float3 wi;
      float pdf;
      float3 f = BrdfSample(&b, kN, wo, make_float2(u(rng), u(rng)), &wi, &pdf);
      if (pdf == 0.0f) {  // A lost draw: no direction.
        ASSERT_EQ(f.x, 0.0f);
        ++lost;
        continue;
      }
      ASSERT_NEAR(Length(wi), 1.0f, 1e-5f) << what;
      ASSERT_EQ(pdf, BrdfPdf(&b, kN, wo, wi)) << what;
      ASSERT_EQ(f.x, BrdfFCos(&b, kN, wo, wi).x) << what;
      int ci = std::min(kCos - 1, static_cast<int>((wi.z + 1) * 0.5 * kCos));
      double phi = std::atan2(wi.y, wi.x);
      if (phi < 0) phi += 2 * kPi;
      int pj = std::min(kPhi - 1, static_cast<int>(phi / (2 * kPi) * kPhi));
      observed[ci * kPhi + pj] += 1;
    }
    // The density's mass is the share of draws that succeed (binomial, 4 sigma, plus 5e-3 for
    // the quadrature of the Jacobian's peak at wi = -wo).
    double success = 1.0 - double(lost) / kSamples;
    EXPECT_NEAR(mass, success, 4 * std::sqrt(success * (1 - success) / kSamples) + 5e-3) << what;
    if (lost == 0) {
      EXPECT_NEAR(mass, 1.0, 2e-3) << what;
    }
    // Expected counts: the density integrated over each cell (32 x 32 midpoints per cell: the
    // half-vector Jacobian 1 / (4 wo.h) has an integrable peak at wi = -wo).
    const int sub = 32;
    for (int ci = 0; ci < kCos; ++ci)
      for (int pj = 0; pj < kPhi; ++pj) {
        double sum = 0;
        for (int a = 0; a < sub; ++a)
          for (int d = 0; d < sub; ++d) {
            double cz = -1 + (ci + (a + 0.5) / sub) * 2.0 / kCos;
            double phi = (pj + (d + 0.5) / sub) * 2 * kPi / kPhi, s = std::sqrt(1 - cz * cz);
            sum +=
                BrdfPdf(&b, kN, wo,
                        make_float3(float(s * std::cos(phi)), float(s * std::sin(phi)), float(cz)));
          }
        expected[ci * kPhi + pj] = kSamples * sum / (sub * sub) * (2.0 / kCos) * (2 * kPi / kPhi);
      }
    double chi2 = 0, pooled_obs = 0, pooled_exp = 0;
    int df = -1;
    for (size_t k = 0; k < observed.size(); ++k) {
      if (expected[k] < 5) {
        pooled_obs += observed[k];
        pooled_exp += expected[k];
        continue;
      }
      chi2 += (observed[k] - expected[k]) * (observed[k] - expected[k]) / expected[k];
      ++df;
    }
    if (pooled_exp >= 5) {
      chi2 += (pooled_obs - pooled_exp) * (pooled_obs - pooled_exp) / pooled_exp;
      ++df;
    }
    ASSERT_GE(df, 10) << what;
    EXPECT_LT(chi2, ChiSquareCritical(df)) << what << ": chi2 " << chi2 << " df " << df;
  }
}

}  // namespace
}  // namespace rt
