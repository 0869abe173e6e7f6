#include "welch.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <stdexcept>

namespace cmp {
namespace {

constexpr double kInf = std::numeric_limits<double>::infinity();

// One render's side of a cell: the mean of its pixel means and the variance of that mean,
// with the Welch-Satterthwaite denominator terms.
struct Side {
  double mean_sum[3] = {0, 0, 0};
  double var_sum[3] = {0, 0, 0};  // sum of var_i / n_i
  double dof_den[3] = {0, 0, 0};  // sum of (var_i / n_i)^2 / (n_i - 1)
  double min_n = kInf;            // fewest samples of a pixel (infinite for a known image)
  int k = 0;

  // `var_of_mean` is var / n; `dof` is n - 1 (infinite for a known variance).
  void add(int c, double mean, double var_of_mean, double dof) {
    mean_sum[c] += mean;
    var_sum[c] += var_of_mean;
    if (std::isfinite(dof)) dof_den[c] += var_of_mean * var_of_mean / dof;
  }
};

// Fills one channel of a cell from the two sides.
void test_cell(const Side& a, const Side& b, int c, const WelchOptions& o, Cell* cell) {
  if (a.k == 0) return;
  double k = a.k, k2 = k * k;
  double ma = a.mean_sum[c] / k, mb = b.mean_sum[c] / k;
  double se2 = (a.var_sum[c] + b.var_sum[c]) / k2;
  // Rounding in the float sums grows like sqrt(n), so the standard error it fakes shrinks
  // like n^(-1/4) (see WelchOptions).
  double n = std::min(a.min_n, b.min_n);
  double res = o.rel_tol * std::max(std::fabs(ma), std::fabs(mb)) *
                   (std::isfinite(n) ? std::pow(std::max(n, 1.0), -0.25) : 1.0) +
               o.abs_tol;
  double d = mb - ma;
  cell->diff[c] = d;
  bool zero = a.var_sum[c] == 0 && b.var_sum[c] == 0;
  if (zero && std::fabs(d) <= res) {
    cell->status[c] = CellStatus::kEqual;  // Every sample alike, and the same value.
    return;
  }
  double total = se2 + res * res;
  double den = (a.dof_den[c] + b.dof_den[c]) / (k2 * k2);
  double dof = den > 0 ? total * total / den : kInf;
  // Without variance the difference is measured against the float resolution alone.
  cell->status[c] = zero ? CellStatus::kDeterministic : CellStatus::kTested;
  cell->p[c] = student_t_two_sided(d / std::sqrt(total), dof);
}

template <typename AddA, typename AddB>
Family run(int w, int h, const WelchOptions& o, AddA add_a, AddB add_b) {
  if (o.tile < 1) throw std::runtime_error("tile size must be at least 1");
  Family f;
  f.resize(w, h, o.tile);
  for (int cy = 0; cy < f.cells_y; ++cy)
    for (int cx = 0; cx < f.cells_x; ++cx) {
      Side a, b;
      for (int y = cy * o.tile; y < std::min(h, (cy + 1) * o.tile); ++y)
        for (int x = cx * o.tile; x < std::min(w, (cx + 1) * o.tile); ++x) {
          size_t i = static_cast<size_t>(y) * w + x;
          add_a(i, &a);
          add_b(i, &b);
          ++a.k;
          ++b.k;
        }
      for (int c = 0; c < 3; ++c) test_cell(a, b, c, o, &f.at(cx, cy));
    }
  return f;
}

// Adds pixel i of `m`; with `other`, the per-sample variance is the larger of the two.
void add_moments(const rt::MomentImage& m, size_t i, Side* s, bool clamp,
                 const rt::MomentImage* other = nullptr) {
  double n = m.count[i];
  s->min_n = std::min(s->min_n, n);
  for (int c = 0; c < 3; ++c) {
    double mean = m.mean[i * 3 + c];
    if (clamp) mean = std::clamp(mean, 0.0, 255.0);
    double var = m.var[i * 3 + c];
    if (other) var = std::max(var, static_cast<double>(other->var[i * 3 + c]));
    s->add(c, mean, n > 0 ? var / n : 0.0, n > 1 ? n - 1 : kInf);
  }
}

}  // namespace

void check_testable(const rt::MomentImage& a, const rt::MomentImage& b, bool allow_weighted) {
  if (a.width != b.width || a.height != b.height)
    throw std::runtime_error("sizes differ: " + std::to_string(a.width) + "x" +
                             std::to_string(a.height) + " and " + std::to_string(b.width) +
                             "x" + std::to_string(b.height));
  for (const rt::MomentImage* m : {&a, &b}) {
    if (!allow_weighted && m->info.filter != "box")
      throw std::runtime_error("a render used the " + m->info.filter +
                               " filter: its means are weighted and its variances approximate "
                               "(render with --filter box, or pass --allow-weighted)");
    for (uint32_t n : m->count)
      if (n < 2)
        throw std::runtime_error("a pixel has fewer than 2 samples: its variance is unknown "
                                 "(render with --spp 2 or more)");
  }
}

Family welch_test(const rt::MomentImage& a, const rt::MomentImage& b, const WelchOptions& o) {
  return run(
      a.width, a.height, o,
      [&](size_t i, Side* s) { add_moments(a, i, s, false, o.pooled ? &b : nullptr); },
      [&](size_t i, Side* s) { add_moments(b, i, s, false, o.pooled ? &a : nullptr); });
}

Family welch_vs_image(const rt::Image8& ref, const rt::MomentImage& b, const WelchOptions& o) {
  if (ref.width != b.width || ref.height != b.height)
    throw std::runtime_error("sizes differ: image " + std::to_string(ref.width) + "x" +
                             std::to_string(ref.height) + ", moments " +
                             std::to_string(b.width) + "x" + std::to_string(b.height));
  return run(
      b.width, b.height, o,
      [&](size_t i, Side* s) {
        for (int c = 0; c < 3; ++c) s->add(c, ref.rgb[i * 3 + c], 1.0 / 12.0, kInf);
      },
      [&](size_t i, Side* s) { add_moments(b, i, s, true); });
}

}  // namespace cmp
