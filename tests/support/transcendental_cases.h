// The accuracy cases of cl/util/transcendental.h, included by transcendental_test.cpp
// (float) and transcendental_double_test.cpp (double) after each has brought the header in
// at its precision and defined RT_SUITE (the test suite's name) and kBounds (the largest
// error each function may have, in units in the last place of `real`). Every error is
// measured against the long-double library (64-bit significand, so its own error is below
// 1/1000 of a double ulp) over a dense grid.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <limits>

namespace {

// |got - want| in units in the last place of `real` at want.
double UlpError(real got, long double want) {
  if (want == 0.0L) return got == 0 ? 0.0 : std::numeric_limits<double>::infinity();
  int e = std::max(std::ilogb(want), std::numeric_limits<real>::min_exponent - 1);
  long double ulp = std::ldexp(1.0L, e - (std::numeric_limits<real>::digits - 1));
  return static_cast<double>(std::fabs(static_cast<long double>(got) - want) / ulp);
}

// The worst error of ours(x) against want(x) at n + 1 points spread evenly over [lo, hi]
// (each rounded to `real`), and where it occurs.
struct Worst {
  double ulps = 0.0;
  real at = 0;
};
template <typename Ours, typename Want>
Worst WorstOnGrid(long double lo, long double hi, int n, Ours ours, Want want) {
  Worst w;
  for (int i = 0; i <= n; ++i) {
    real x = static_cast<real>(lo + (hi - lo) * i / n);
    double u = UlpError(ours(x), want(static_cast<long double>(x)));
    if (u > w.ulps) w = Worst{u, x};
  }
  return w;
}

// Prints the measured worst error (the figure the bounds in the including files come from)
// and checks it against the bound.
void ExpectWithin(const char* what, Worst w, double bound) {
  std::printf("%-24s worst %.3g ulps at %.17g (bound %g)\n", what, w.ulps,
              static_cast<double>(w.at), bound);
  EXPECT_LE(w.ulps, bound) << what << " at " << w.at;
}

// The sine (part 0) or the cosine (part 1) from a function that returns both.
real SinCosPart(void (*sin_cos)(real, real*, real*), real x, int part) {
  real s, c;
  sin_cos(x, &s, &c);
  return part == 0 ? s : c;
}

const int kGrid = 1 << 20;
const long double kPiL = 3.141592653589793238462643383279502884L;

TEST(RT_SUITE, ExpAcrossItsRange) {
  real top = std::log(std::numeric_limits<real>::max()) - 0.01;
  Worst w = WorstOnGrid(-top, top, kGrid, Exp, [](long double x) { return std::exp(x); });
  ExpectWithin("exp", w, kBounds.exp);
  EXPECT_EQ(Exp(0), 1);
  EXPECT_EQ(Exp(2 * top), std::numeric_limits<real>::infinity());
  EXPECT_EQ(Exp(-2 * top - 100), 0);
}

TEST(RT_SUITE, LogOverEveryBinadeAndAroundOne) {
  // Log-spaced over the normal range, then evenly around 1, where ln x is near zero.
  real lo = std::log2(std::numeric_limits<real>::min()), hi = -lo;
  auto x_of = [](long double t) { return static_cast<real>(std::exp2(t)); };
  Worst w = WorstOnGrid(
      lo, hi, kGrid, [&](real t) { return Log(x_of(t)); },
      [&](long double t) { return std::log(static_cast<long double>(x_of(t))); });
  ExpectWithin("log (at 2^x)", w, kBounds.log);
  w = WorstOnGrid(0.5L, 2.0L, kGrid, Log, [](long double x) { return std::log(x); });
  ExpectWithin("log near 1", w, kBounds.log);
  EXPECT_EQ(Log(1), 0);
  EXPECT_EQ(Log(0), -std::numeric_limits<real>::infinity());
}

// e^(e ln x) carries the rounding of e ln x, relative to its size, into the result: the
// error is bounded in ulps per unit of max(1, |e ln x|).
TEST(RT_SUITE, PowOfUnitBasesAndLargerOnes) {
  Worst w;
  for (real e : {real(0.5), real(1) / 3, real(1) / 52, real(1) / 202, real(2.5), real(37.5)})
    for (int i = 0; i <= kGrid / 8; ++i) {
      real x = static_cast<real>(1e-3L + 999.0L * i / (kGrid / 8));  // Below and above 1.
      long double want = std::pow(static_cast<long double>(x), static_cast<long double>(e));
      if (want > std::numeric_limits<real>::max()) continue;  // Overflows: inf, checked below.
      double scale = std::max(1.0L, std::fabs(e * std::log(static_cast<long double>(x))));
      double u = UlpError(Pow(x, e), want) / scale;
      if (u > w.ulps) w = Worst{u, x};
    }
  ExpectWithin("Pow (per |e ln x|)", w, kBounds.pow);
  EXPECT_EQ(Pow(1000, 1000), std::numeric_limits<real>::infinity());
  EXPECT_EQ(Pow(0, real(0.5)), 0);
  EXPECT_EQ(Pow(1, real(0.5)), 1);
  EXPECT_EQ(Pow(real(0.3), 0), 1);
}

TEST(RT_SUITE, SinCosOverEightTurns) {
  auto sin_of = [](real x) { return SinCosPart(SinCos, x, 0); };
  auto cos_of = [](real x) { return SinCosPart(SinCos, x, 1); };
  Worst ws =
      WorstOnGrid(-8 * kPiL, 8 * kPiL, kGrid, sin_of, [](long double x) { return std::sin(x); });
  Worst wc =
      WorstOnGrid(-8 * kPiL, 8 * kPiL, kGrid, cos_of, [](long double x) { return std::cos(x); });
  ExpectWithin("SinCos: sin", ws, kBounds.sin_cos);
  ExpectWithin("SinCos: cos", wc, kBounds.sin_cos);
  EXPECT_EQ(sin_of(0), 0);
  EXPECT_EQ(cos_of(0), 1);
}

TEST(RT_SUITE, SinCos2PiOverATurn) {
  auto sin_of = [](real u) { return SinCosPart(SinCos2Pi, u, 0); };
  auto cos_of = [](real u) { return SinCosPart(SinCos2Pi, u, 1); };
  // The reference reduces 4u to the nearest quarter turn exactly too, so that its zeros are
  // exact (2 pi u in long double is not a multiple of pi where sin 2 pi u = 0).
  auto quarter_turns = [](long double u, long double* s, long double* c) {
    long double k = std::nearbyint(4 * u), a = (4 * u - k) * (kPiL / 2);
    int q = static_cast<int>(k - 4 * std::floor(k / 4));
    long double sa = std::sin(a), ca = std::cos(a);
    *s = q == 0 ? sa : q == 1 ? ca : q == 2 ? -sa : -ca;
    *c = q == 0 ? ca : q == 1 ? -sa : q == 2 ? -ca : sa;
  };
  auto sin_want = [&](long double u) {
    long double s, c;
    quarter_turns(u, &s, &c);
    return s;
  };
  auto cos_want = [&](long double u) {
    long double s, c;
    quarter_turns(u, &s, &c);
    return c;
  };
  Worst ws = WorstOnGrid(-0.5L, 1.0L, kGrid, sin_of, sin_want);
  Worst wc = WorstOnGrid(-0.5L, 1.0L, kGrid, cos_of, cos_want);
  ExpectWithin("SinCos2Pi: sin", ws, kBounds.sin_cos_2pi);
  ExpectWithin("SinCos2Pi: cos", wc, kBounds.sin_cos_2pi);
  real s, c;
  SinCos2Pi(0, &s, &c);
  EXPECT_EQ(s, 0);
  EXPECT_EQ(c, 1);
  SinCos2Pi(real(0.25), &s, &c);
  EXPECT_EQ(s, 1);
  EXPECT_EQ(c, 0);
  SinCos2Pi(real(0.5), &s, &c);
  EXPECT_EQ(c, -1);
}

TEST(RT_SUITE, Atan2AllAroundAtSeveralRadii) {
  for (long double r : {1e-3L, 0.7L, 1.0L, 250.0L}) {
    auto ours = [r](real a) {
      return Atan2(static_cast<real>(r * std::sin(static_cast<long double>(a))),
                   static_cast<real>(r * std::cos(static_cast<long double>(a))));
    };
    auto want = [r](long double a) {
      return std::atan2(static_cast<long double>(static_cast<real>(r * std::sin(a))),
                        static_cast<long double>(static_cast<real>(r * std::cos(a))));
    };
    Worst w = WorstOnGrid(-3.3L, 3.3L, kGrid / 4, ours, want);
    ExpectWithin("Atan2 (angle)", w, kBounds.atan2);
  }
  EXPECT_EQ(Atan2(0, 1), 0);
  EXPECT_EQ(Atan2(1, 0), RT_PI * real(0.5));
  EXPECT_EQ(Atan2(0, -1), RT_PI);
  EXPECT_EQ(Atan2(-1, 0), -RT_PI * real(0.5));
}

TEST(RT_SUITE, SafeACosOverItsDomainAndClamped) {
  Worst w = WorstOnGrid(-1.0L, 1.0L, kGrid, SafeACos, [](long double c) { return std::acos(c); });
  ExpectWithin("SafeACos", w, kBounds.acos);
  EXPECT_EQ(SafeACos(1), 0);
  EXPECT_EQ(SafeACos(0), RT_PI * real(0.5));
  EXPECT_EQ(SafeACos(-1), RT_PI);
  EXPECT_EQ(SafeACos(real(1.5)), 0);  // Rounding may push a unit vector's component past 1.
}

}  // namespace
