// The statistics of `compare`: distributions against values computed to 30 digits with
// mpmath, the multiple-testing rules, and the tests on synthetic moment images whose
// truth is known.
#include <gtest/gtest.h>

#include <cmath>
#include <random>

#include "exact.h"
#include "family.h"
#include "paired.h"
#include "stats.h"
#include "welch.h"

namespace {

TEST(Stats, IncompleteBetaMatchesKnownValues) {
  EXPECT_NEAR(cmp::incomplete_beta(2, 5, 0.3), 0.579825, 1e-12);
  EXPECT_NEAR(cmp::incomplete_beta(0.5, 0.5, 0.9), 0.795167235300866548, 1e-12);
  EXPECT_NEAR(cmp::incomplete_beta(200, 300, 0.5), 0.999996456519735607, 1e-12);
  EXPECT_EQ(cmp::incomplete_beta(3, 4, 0), 0);
  EXPECT_EQ(cmp::incomplete_beta(3, 4, 1), 1);
  EXPECT_TRUE(std::isnan(cmp::incomplete_beta(-1, 4, 0.5)));
}

TEST(Stats, StudentTTwoSidedMatchesKnownValues) {
  EXPECT_NEAR(cmp::student_t_two_sided(2.0, 10), 0.0733880347707403656, 1e-12);
  EXPECT_NEAR(cmp::student_t_two_sided(-2.0, 10), 0.0733880347707403656, 1e-12);
  EXPECT_NEAR(cmp::student_t_two_sided(3.5, 4.7), 0.0191295935002764325, 1e-12);
  EXPECT_NEAR(cmp::student_t_two_sided(0.1, 2), 0.929465438414140173, 1e-12);
  // Far tails keep their relative accuracy (no 1 - p cancellation).
  EXPECT_NEAR(cmp::student_t_two_sided(10, 30) / 4.57525140822961319e-11, 1.0, 1e-9);
  EXPECT_NEAR(cmp::student_t_two_sided(3, INFINITY), 0.00269979606326018905, 1e-14);
  EXPECT_EQ(cmp::student_t_two_sided(0, 7), 1.0);
  EXPECT_TRUE(std::isnan(cmp::student_t_two_sided(NAN, 7)));
}

TEST(Stats, BinomialTailAndSignTest) {
  EXPECT_NEAR(cmp::binomial_upper_tail(60, 100, 0.5), 0.0284439668204903958, 1e-13);
  EXPECT_NEAR(cmp::binomial_upper_tail(7, 20, 0.05), 3.39461653014337748e-5, 1e-15);
  EXPECT_EQ(cmp::binomial_upper_tail(0, 20, 0.05), 1.0);
  EXPECT_EQ(cmp::binomial_upper_tail(21, 20, 0.05), 0.0);
  EXPECT_NEAR(cmp::sign_test_two_sided(60, 40), 2 * 0.0284439668204903958, 1e-13);
  EXPECT_NEAR(cmp::sign_test_two_sided(40, 60), 2 * 0.0284439668204903958, 1e-13);
  EXPECT_EQ(cmp::sign_test_two_sided(0, 0), 1.0);
  EXPECT_EQ(cmp::sign_test_two_sided(5, 5), 1.0);
  EXPECT_NEAR(cmp::sign_test_two_sided(10, 0), 2.0 / 1024, 1e-15);
}

TEST(Stats, SidakLevelKeepsTheFamilyWiseRate) {
  EXPECT_NEAR(cmp::sidak_level(0.05, 1), 0.05, 1e-15);
  EXPECT_NEAR(cmp::sidak_level(0.05, 10), 1 - std::pow(0.95, 0.1), 1e-15);
  for (size_t m : {size_t{2}, size_t{1000}, size_t{3000000}}) {
    double l = cmp::sidak_level(0.01, m);
    EXPECT_NEAR(-std::expm1(static_cast<double>(m) * std::log1p(-l)), 0.01, 1e-12) << m;
    EXPECT_GT(l, 0.01 / m);  // Slightly less strict than Bonferroni.
  }
}

TEST(Stats, BenjaminiHochbergOnTheTextbookExample) {
  std::vector<double> p = {0.001, 0.008, 0.039, 0.041, 0.042, 0.06, 0.074, 0.205, 0.212, 0.216};
  double t = -1;
  EXPECT_EQ(cmp::benjamini_hochberg(p, 0.05, &t), 2u);
  EXPECT_EQ(t, 0.008);
  EXPECT_EQ(cmp::benjamini_hochberg(p, 0.1, &t), 6u);  // 0.06 <= 6 * 0.01, not 0.041 <= 0.04
  EXPECT_EQ(t, 0.06);
  EXPECT_EQ(cmp::benjamini_hochberg({0.5, 0.9}, 0.05, &t), 0u);
  EXPECT_EQ(t, 0.0);
}

TEST(Stats, UniformityAcceptsUniformAndRejectsSmallPValues) {
  std::mt19937 rng(7);
  std::uniform_real_distribution<double> u(0, 1);
  std::vector<double> p(5000);
  for (double& v : p) v = u(rng);
  cmp::Uniformity ok = cmp::uniformity(p);
  EXPECT_EQ(ok.count, 5000u);
  EXPECT_GT(ok.p, 1e-3);
  EXPECT_GT(ok.p_plus, 1e-3);
  EXPECT_NEAR(ok.p_plus, std::exp(-2 * 5000 * ok.d_plus * ok.d_plus), 1e-12);
  // Biased tests: p-values pushed toward 0 (squared uniforms) are caught by D+ ...
  for (double& v : p) v = v * v;
  cmp::Uniformity bad = cmp::uniformity(p);
  EXPECT_GT(bad.d_plus, 0.2);
  EXPECT_LT(bad.p_plus, 1e-12);
  // ... while conservative tests (p pushed toward 1) are not a failure of D+.
  for (double& v : p) v = std::sqrt(std::sqrt(v));
  cmp::Uniformity conservative = cmp::uniformity(p);
  EXPECT_LT(conservative.d_plus, 0.02);
  EXPECT_GT(conservative.d, 0.2);
  EXPECT_LT(conservative.p, 1e-12);
}

TEST(Stats, ClopperPearsonMatchesClosedForms) {
  double lo, hi;
  cmp::clopper_pearson(0, 10, 0.95, &lo, &hi);
  EXPECT_EQ(lo, 0);
  EXPECT_NEAR(hi, 1 - std::pow(0.025, 0.1), 1e-9);
  cmp::clopper_pearson(10, 10, 0.95, &lo, &hi);
  EXPECT_NEAR(lo, std::pow(0.025, 0.1), 1e-9);
  EXPECT_EQ(hi, 1);
}

// A moment image of constant statistics.
rt::MomentImage Constant(int w, int h, float mean, float var, uint32_t n, uint32_t seed = 0) {
  rt::MomentImage m;
  m.width = w;
  m.height = h;
  m.info.seed = seed;
  m.info.spp = static_cast<int>(n);
  m.mean.assign(m.pixels() * 3, mean);
  m.var.assign(m.pixels() * 3, var);
  m.normal.assign(m.pixels() * 3, 0.0f);
  m.count.assign(m.pixels(), n);
  m.first_t.assign(m.pixels(), 1.0f);
  m.instance.assign(m.pixels(), 0);
  m.primitive.assign(m.pixels(), 0);
  return m;
}

TEST(Welch, OnePixelIsTheTextbookWelchTest) {
  rt::MomentImage a = Constant(1, 1, 10.0f, 4.0f, 16), b = Constant(1, 1, 12.0f, 9.0f, 25);
  cmp::Family f = cmp::welch_test(a, b, {});
  const cmp::Cell& c = f.cells[0];
  ASSERT_EQ(c.status[0], cmp::CellStatus::kTested);
  double se2 = 4.0 / 16 + 9.0 / 25, res = 6e-4 * 12 / 2 + 1e-6;  // n^(1/4) = 2
  double total = se2 + res * res;
  double dof = total * total / ((0.25 * 0.25) / 15 + (0.36 * 0.36) / 24);
  EXPECT_NEAR(c.p[0], cmp::student_t_two_sided(2.0 / std::sqrt(total), dof), 1e-12);
  EXPECT_NEAR(c.diff[1], 2.0, 1e-12);
}

TEST(Welch, PooledTakesTheLargerPerSampleVariance) {
  // A 16-sample render that missed a pixel's rare bright paths (mean 0, variance 0)
  // against a 256-sample render that saw them: plain Welch trusts the zero variance,
  // pooled uses 6895 for both sides: se^2 = 6895 (1/256 + 1/16).
  rt::MomentImage a = Constant(1, 1, 47.88f, 6895.0f, 256), b = Constant(1, 1, 0.0f, 0.0f, 16);
  cmp::WelchOptions plain, pooled;
  pooled.pooled = true;
  double p_plain = cmp::welch_test(a, b, plain).cells[0].p[0];
  double p_pooled = cmp::welch_test(a, b, pooled).cells[0].p[0];
  EXPECT_LT(p_plain, 1e-15);
  const double mean = 47.88f;  // As stored (float).
  double se2 = 6895.0 * (1.0 / 256 + 1.0 / 16), res = 6e-4 * mean / 2 + 1e-6;  // 16^(1/4)
  double total = se2 + res * res;
  double dof = total * total /
               ((6895.0 / 256) * (6895.0 / 256) / 255 + (6895.0 / 16) * (6895.0 / 16) / 15);
  EXPECT_NEAR(p_pooled, cmp::student_t_two_sided(mean / std::sqrt(total), dof), 1e-9);
  EXPECT_GT(p_pooled, 0.01);
}

TEST(Welch, TilesAverageMeansAndSumVariances) {
  // 4x4 pixels, tile 4: K = 16 pixels, all var v and n samples: se^2 = 2 v / (n K) and
  // Welch-Satterthwaite gives 2 K (n - 1) degrees of freedom.
  rt::MomentImage a = Constant(4, 4, 5.0f, 2.0f, 8), b = Constant(4, 4, 5.5f, 2.0f, 8);
  cmp::WelchOptions o;
  o.tile = 4;
  o.abs_tol = o.rel_tol = 0;
  cmp::Family f = cmp::welch_test(a, b, o);
  ASSERT_EQ(f.cells.size(), 1u);
  double t = 0.5 / std::sqrt(2 * 2.0 / (8 * 16));
  EXPECT_NEAR(f.cells[0].p[2], cmp::student_t_two_sided(t, 2 * 16 * 7), 1e-12);
}

TEST(Welch, PartialTilesAtTheBorderAreTestedToo) {
  cmp::WelchOptions o;
  o.tile = 4;
  cmp::Family f = cmp::welch_test(Constant(6, 5, 1, 1, 4), Constant(6, 5, 1, 1, 4), o);
  EXPECT_EQ(f.cells_x, 2);
  EXPECT_EQ(f.cells_y, 2);
  for (const cmp::Cell& c : f.cells) EXPECT_EQ(c.status[0], cmp::CellStatus::kTested);
}

TEST(Welch, ZeroVariancePixelsAreHandledExplicitly) {
  rt::MomentImage a = Constant(3, 1, 7.0f, 0.0f, 4), b = a;
  b.mean[3] = 7.5f;        // pixel 1, red: certain and different
  b.mean[6] = 7.0000001f;  // pixel 2, red: equal within float resolution
  cmp::Family f = cmp::welch_test(a, b, {});
  EXPECT_EQ(f.cells[0].status[0], cmp::CellStatus::kEqual);
  EXPECT_EQ(f.cells[1].status[0], cmp::CellStatus::kDeterministic);
  EXPECT_EQ(f.cells[2].status[0], cmp::CellStatus::kEqual);
  cmp::Verdict v = cmp::decide(f, {});
  EXPECT_EQ(v.tests, 0u);
  EXPECT_EQ(v.equal, 8u);
  EXPECT_EQ(v.certain, 1u);
  EXPECT_EQ(v.deterministic, 1u);
  EXPECT_EQ(v.det_x, 1);
  EXPECT_FALSE(v.pass);
  // Rounding can zero a tiny real variance: a difference near the float resolution r is
  // measured against r, not failed outright.
  rt::MomentImage c = a;
  c.mean[0] = 7.0f * (1 + 1e-3f);  // r = 6e-4 * 7 / 4^(1/4): 2.4 r away
  cmp::Family fc = cmp::welch_test(a, c, {});
  EXPECT_EQ(fc.cells[0].status[0], cmp::CellStatus::kDeterministic);
  EXPECT_TRUE(cmp::decide(fc, {}).pass);
}

TEST(Welch, RefusesUntestableInputs) {
  rt::MomentImage a = Constant(2, 2, 1, 1, 4);
  EXPECT_THROW(cmp::check_testable(a, Constant(2, 3, 1, 1, 4), false), std::runtime_error);
  EXPECT_THROW(cmp::check_testable(a, Constant(2, 2, 1, 0, 1), false), std::runtime_error);
  rt::MomentImage g = a;
  g.info.filter = "gaussian";
  EXPECT_THROW(cmp::check_testable(a, g, false), std::runtime_error);
  EXPECT_NO_THROW(cmp::check_testable(a, g, true));
}

// Moment images of n normal samples per pixel and channel with the given mean shift.
rt::MomentImage Sampled(int w, int h, uint32_t n, double shift, std::mt19937* rng) {
  rt::MomentImage m = Constant(w, h, 0, 0, n);
  std::normal_distribution<double> z(0, 1);
  for (size_t j = 0; j < m.mean.size(); ++j) {
    double s = 0, s2 = 0;
    for (uint32_t k = 0; k < n; ++k) {
      double x = 100 + shift + 20 * z(*rng);
      s += x;
      s2 += x * x;
    }
    m.mean[j] = static_cast<float>(s / n);
    m.var[j] = static_cast<float>((s2 - s * s / n) / (n - 1));
  }
  return m;
}

TEST(Welch, PerTestRejectionRateIsNominalUnderTheNull) {
  // 60,000 independent tests of equal normal populations: the share of p < 0.05 must be
  // 0.05 within 5 binomial standard deviations (false-failure probability < 1e-6).
  std::mt19937 rng(11);
  long below = 0, tests = 0;
  for (int rep = 0; rep < 5; ++rep) {
    cmp::Family f = cmp::welch_test(Sampled(80, 50, 8, 0, &rng), Sampled(80, 50, 8, 0, &rng), {});
    for (const cmp::Cell& c : f.cells)
      for (int ch = 0; ch < 3; ++ch, ++tests) below += c.p[ch] < 0.05;
  }
  double sd = std::sqrt(tests * 0.05 * 0.95);
  EXPECT_NEAR(below, 0.05 * tests, 5 * sd);
}

TEST(Welch, TilesFindASmallUniformBias) {
  // A shift of 0.1 standard errors per pixel: invisible per pixel, plain in 16x16 tiles.
  std::mt19937 rng(3);
  double se = 20 * std::sqrt(2.0 / 8);
  rt::MomentImage a = Sampled(64, 64, 8, 0, &rng), b = Sampled(64, 64, 8, 0.1 * se, &rng);
  cmp::Family pixels = cmp::welch_test(a, b, {});
  EXPECT_TRUE(cmp::decide(pixels, {}).rejections == 0);
  cmp::WelchOptions o;
  o.tile = 16;
  cmp::Family tiles = cmp::welch_test(a, b, o);
  EXPECT_FALSE(cmp::decide(tiles, {}).pass);
}

TEST(Welch, AgainstAnImageCountsTheRoundingError) {
  // Means spread over many levels, so the rounding errors vary as in a real image.
  rt::MomentImage b = Constant(8, 8, 0, 50.0f, 1000);
  rt::Image8 ref;
  ref.width = ref.height = 8;
  ref.rgb.resize(8 * 8 * 3);
  for (size_t j = 0; j < b.mean.size(); ++j) {
    b.mean[j] = 60.0f + 0.731f * j;
    ref.rgb[j] = static_cast<uint8_t>(std::lround(b.mean[j]));
  }
  cmp::Family same = cmp::welch_vs_image(ref, b, {});
  EXPECT_TRUE(cmp::decide(same, {}).pass);
  for (uint8_t& v : ref.rgb) v -= 3;
  cmp::Family f = cmp::welch_vs_image(ref, b, {});
  EXPECT_FALSE(cmp::decide(f, {}).pass);
  // Means above white compare with 255 as the PNG would show them.
  rt::MomentImage bright = Constant(8, 8, 400.0f, 50.0f, 1000);
  ref.rgb.assign(8 * 8 * 3, 255);
  cmp::Family fb = cmp::welch_vs_image(ref, bright, {});
  EXPECT_TRUE(cmp::decide(fb, {}).pass);
}

TEST(Family, VerdictFiguresAndBenjaminiHochberg) {
  std::mt19937 rng(5);
  rt::MomentImage a = Sampled(32, 32, 16, 0, &rng), b = Sampled(32, 32, 16, 0, &rng);
  b.mean[(5 * 32 + 7) * 3 + 1] += 200;  // one pixel's green far off
  cmp::Family f = cmp::welch_test(a, b, {});
  cmp::Verdict v = cmp::decide(f, {});
  EXPECT_FALSE(v.pass);
  EXPECT_EQ(v.tests, 32u * 32 * 3);
  EXPECT_EQ(v.sidak_rejections, 1u);
  EXPECT_EQ(v.min_x, 7);
  EXPECT_EQ(v.min_y, 5);
  EXPECT_EQ(v.min_c, 1);
  EXPECT_TRUE(f.at(7, 5).rejected[1]);
  EXPECT_NEAR(v.alpha_tests, 0.005, 1e-15);
  EXPECT_NEAR(v.sidak_level, cmp::sidak_level(0.005, v.tests), 1e-18);
  cmp::FamilyOptions bh;
  bh.bh = true;
  cmp::Verdict vb = cmp::decide(f, bh);
  EXPECT_FALSE(vb.pass);
  EXPECT_GE(vb.bh_rejections, 1u);
  cmp::FamilyOptions whole;
  whole.uniformity = false;
  EXPECT_EQ(cmp::decide(f, whole).alpha_tests, 0.01);
}

TEST(Family, UniformityCheckCatchesManySmallShifts) {
  // 1000 cells whose p-values are 0.03 in 10 % of the cells: no single test is rejected,
  // but twice the expected share of small p-values is no accident.
  cmp::Family f;
  f.resize(1000, 1, 1);
  for (size_t i = 0; i < f.cells.size(); ++i)
    for (int c = 0; c < 3; ++c) {
      f.cells[i].status[c] = cmp::CellStatus::kTested;
      f.cells[i].p[c] = i % 10 == 0 ? 0.03 : 0.06 + 0.9 * (i % 97) / 97.0;
    }
  cmp::Verdict v = cmp::decide(f, {});
  EXPECT_EQ(v.rejections, 0u);
  EXPECT_EQ(v.small[1], 100u);
  EXPECT_TRUE(v.uniform_rejected);
  EXPECT_FALSE(v.pass);
  cmp::FamilyOptions off;
  off.uniformity = false;
  EXPECT_TRUE(cmp::decide(f, off).pass);
}

TEST(Paired, IdenticalRendersHaveNothingToTest) {
  std::mt19937 rng(1);
  rt::MomentImage a = Sampled(16, 16, 4, 0, &rng);
  cmp::Family f = cmp::paired_test(a, a, {});
  cmp::Verdict v = cmp::decide(f, {});
  EXPECT_TRUE(v.pass);
  EXPECT_EQ(v.tests, 0u);
}

TEST(Paired, CatchesASmallSystematicShiftAndPassesSymmetricNoise) {
  std::mt19937 rng(2);
  rt::MomentImage a = Sampled(32, 32, 4, 0, &rng), b = a, noisy = a;
  std::normal_distribution<double> z(0, 1);
  for (size_t j = 0; j < a.mean.size(); ++j) {
    b.mean[j] *= 1.001f;  // 0.1 % brighter everywhere
    noisy.mean[j] += static_cast<float>(z(rng));
  }
  cmp::Family fb = cmp::paired_test(a, b, {});
  EXPECT_FALSE(cmp::decide(fb, {}).pass);
  cmp::Family fn = cmp::paired_test(a, noisy, {});
  EXPECT_TRUE(cmp::decide(fn, {}).pass);
  cmp::PairedFigures pf = cmp::paired_figures(a, b, {});
  EXPECT_EQ(pf.differing, a.mean.size());
  EXPECT_EQ(pf.positive, a.mean.size());
}

TEST(Exact, ReportsEachKindOfMismatch) {
  rt::MomentImage a = Constant(4, 1, 1, 1, 4), b = a;
  a.first_t = {1.0f, 2.0f, 3.0f, INFINITY};
  a.instance[3] = a.primitive[3] = -1;
  b = a;
  EXPECT_TRUE(cmp::exact_test(a, b, {}).pass);
  b.primitive[0] = 5;
  b.first_t[1] = 2.01f;
  b.instance[2] = b.primitive[2] = -1;
  b.first_t[2] = INFINITY;
  cmp::ExactReport r = cmp::exact_test(a, b, {});
  EXPECT_FALSE(r.pass);
  EXPECT_EQ(r.id_mismatch, 1u);
  EXPECT_EQ(r.t_over, 1u);
  EXPECT_EQ(r.hit_mismatch, 1u);
  EXPECT_EQ(r.failing, 3u);
  cmp::ExactOptions lax;
  lax.max_fraction = 0.75;
  EXPECT_TRUE(cmp::exact_test(a, b, lax).pass);
}

}  // namespace
