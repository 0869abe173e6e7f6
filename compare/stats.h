// The distributions and multiple-testing rules behind `compare`: Student's t, the
// binomial tail, Sidak and Benjamini-Hochberg thresholds, and a test that p-values are
// uniform. Everything is in double precision and free of external libraries.
#pragma once

#include <cstddef>
#include <vector>

namespace cmp {

// Regularized incomplete beta function I_x(a, b) for a, b > 0 and x in [0, 1], evaluated
// with a continued fraction (modified Lentz) on whichever side converges fast.
double incomplete_beta(double a, double b, double x);

// Two-sided p-value of Student's t statistic with `dof` degrees of freedom (any real
// dof > 0; +infinity gives the normal). NaN t gives NaN.
double student_t_two_sided(double t, double dof);

// P(X >= k) for X ~ Binomial(n, p).
double binomial_upper_tail(long k, long n, double p);

// Exact two-sided sign test of `pos` positive against `neg` negative differences under
// P(positive) = 1/2: twice the smaller tail, at most 1.
double sign_test_two_sided(long pos, long neg);

// Per-test level that keeps the family-wise error rate at `alpha` over m independent
// tests: 1 - (1 - alpha)^(1/m), computed without cancellation. It is also valid (slightly
// conservative) for positively correlated two-sided tests, by Sidak's inequality.
double sidak_level(double alpha, size_t m);

// Benjamini-Hochberg at false discovery rate q: the number of p-values rejected, and the
// largest rejected p in *threshold (0 when none). NaNs are ignored.
size_t benjamini_hochberg(std::vector<double> p, double q, double* threshold);

// How far a sample of p-values is from U(0, 1).
struct Uniformity {
  size_t count = 0;
  double d_plus = 0;  // max_i (i/m - p_(i)): excess of small p-values (what bias causes)
  double p_plus = 1;  // exp(-2 m D+^2): the Dvoretzky-Kiefer-Wolfowitz-Massart bound, valid
                      // for every m, so it never overstates significance
  double d = 0;       // two-sided Kolmogorov-Smirnov statistic
  double p = 1;       // its asymptotic p-value (Stephens' small-sample correction)
};
Uniformity uniformity(std::vector<double> p);

// Two-sided Clopper-Pearson confidence interval for a binomial proportion k/n.
void clopper_pearson(long k, long n, double confidence, double* lo, double* hi);

}  // namespace cmp
