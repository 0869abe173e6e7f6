#include "stats.h"

#include <algorithm>
#include <cmath>
#include <limits>

namespace cmp {
namespace {

constexpr double kNaN = std::numeric_limits<double>::quiet_NaN();

// The continued fraction of I_x(a, b) (without its prefactor), evaluated with the modified
// Lentz method. It converges quickly for x < (a + 1) / (a + b + 2).
double beta_fraction(double a, double b, double x) {
  const double tiny = 1e-300, eps = 1e-15;
  double c = 1.0, d = 1.0 - (a + b) * x / (a + 1.0);
  if (std::fabs(d) < tiny) d = tiny;
  d = 1.0 / d;
  double f = d;
  for (int m = 1; m < 100000; ++m) {
    // Even step: d_{2m} = m (b - m) x / ((a + 2m - 1)(a + 2m)).
    double num = m * (b - m) * x / ((a + 2.0 * m - 1.0) * (a + 2.0 * m));
    d = 1.0 + num * d;
    c = 1.0 + num / c;
    if (std::fabs(d) < tiny) d = tiny;
    if (std::fabs(c) < tiny) c = tiny;
    d = 1.0 / d;
    f *= d * c;
    // Odd step: d_{2m+1} = -(a + m)(a + b + m) x / ((a + 2m)(a + 2m + 1)).
    num = -(a + m) * (a + b + m) * x / ((a + 2.0 * m) * (a + 2.0 * m + 1.0));
    d = 1.0 + num * d;
    c = 1.0 + num / c;
    if (std::fabs(d) < tiny) d = tiny;
    if (std::fabs(c) < tiny) c = tiny;
    d = 1.0 / d;
    double delta = d * c;
    f *= delta;
    if (std::fabs(delta - 1.0) < eps) break;
  }
  return f;
}

}  // namespace

double incomplete_beta(double a, double b, double x) {
  if (!(a > 0) || !(b > 0) || !(x >= 0) || !(x <= 1)) return kNaN;
  if (x == 0) return 0;
  if (x == 1) return 1;
  double log_front = a * std::log(x) + b * std::log1p(-x) + std::lgamma(a + b) - std::lgamma(a) -
                     std::lgamma(b);
  // The fraction converges fast below the mean of the Beta(a, b) distribution; above it,
  // use the symmetry I_x(a, b) = 1 - I_{1-x}(b, a).
  if (x < (a + 1.0) / (a + b + 2.0)) return std::exp(log_front) * beta_fraction(a, b, x) / a;
  return 1.0 - std::exp(log_front) * beta_fraction(b, a, 1.0 - x) / b;
}

double student_t_two_sided(double t, double dof) {
  if (std::isnan(t) || !(dof > 0)) return kNaN;
  if (std::isinf(dof)) return std::erfc(std::fabs(t) / std::sqrt(2.0));
  if (std::isinf(t)) return 0;
  // P(|T| >= |t|) = I_{dof / (dof + t^2)}(dof / 2, 1 / 2).
  return incomplete_beta(0.5 * dof, 0.5, dof / (dof + t * t));
}

double binomial_upper_tail(long k, long n, double p) {
  if (k <= 0) return 1;
  if (k > n) return 0;
  // P(X >= k) = I_p(k, n - k + 1).
  return incomplete_beta(static_cast<double>(k), static_cast<double>(n - k + 1), p);
}

double sign_test_two_sided(long pos, long neg) {
  long n = pos + neg;
  if (n == 0) return 1;
  long k = std::max(pos, neg);
  return std::min(1.0, 2.0 * binomial_upper_tail(k, n, 0.5));
}

double sidak_level(double alpha, size_t m) {
  if (m == 0) return alpha;
  return -std::expm1(std::log1p(-alpha) / static_cast<double>(m));
}

size_t benjamini_hochberg(std::vector<double> p, double q, double* threshold) {
  p.erase(std::remove_if(p.begin(), p.end(), [](double v) { return std::isnan(v); }), p.end());
  std::sort(p.begin(), p.end());
  size_t m = p.size(), k = 0;
  for (size_t i = 0; i < m; ++i)
    if (p[i] <= q * static_cast<double>(i + 1) / static_cast<double>(m)) k = i + 1;
  if (threshold) *threshold = k ? p[k - 1] : 0.0;
  return k;
}

Uniformity uniformity(std::vector<double> p) {
  p.erase(std::remove_if(p.begin(), p.end(), [](double v) { return std::isnan(v); }), p.end());
  Uniformity u;
  u.count = p.size();
  if (p.empty()) return u;
  std::sort(p.begin(), p.end());
  double m = static_cast<double>(p.size());
  double d_minus = 0;
  for (size_t i = 0; i < p.size(); ++i) {
    u.d_plus = std::max(u.d_plus, (i + 1) / m - p[i]);
    d_minus = std::max(d_minus, p[i] - i / m);
  }
  u.d = std::max(u.d_plus, d_minus);
  u.p_plus = std::min(1.0, std::exp(-2.0 * m * u.d_plus * u.d_plus));
  // Kolmogorov's limit Q(l) = 2 sum_j (-1)^(j-1) exp(-2 j^2 l^2), with Stephens' correction.
  double l = (std::sqrt(m) + 0.12 + 0.11 / std::sqrt(m)) * u.d;
  if (l < 0.2) {
    u.p = 1;
  } else {
    double s = 0;
    for (int j = 1; j <= 100; ++j) {
      double term = std::exp(-2.0 * j * j * l * l);
      s += (j % 2 ? 1 : -1) * term;
      if (term < 1e-17) break;
    }
    u.p = std::clamp(2.0 * s, 0.0, 1.0);
  }
  return u;
}

void clopper_pearson(long k, long n, double confidence, double* lo, double* hi) {
  double a = (1.0 - confidence) / 2;
  // Bisection on the binomial tails: lo solves P(X >= k | lo) = a, hi solves
  // P(X <= k | hi) = a.
  auto solve = [](auto f) {
    double l = 0, h = 1;
    for (int i = 0; i < 200; ++i) {
      double mid = 0.5 * (l + h);
      (f(mid) ? h : l) = mid;
    }
    return 0.5 * (l + h);
  };
  *lo = k == 0 ? 0.0 : solve([&](double x) { return binomial_upper_tail(k, n, x) >= a; });
  *hi = k == n ? 1.0
               : solve([&](double x) { return 1.0 - binomial_upper_tail(k + 1, n, x) <= a; });
}

}  // namespace cmp
