#include "family.h"

#include <cmath>
#include <cstdio>

namespace cmp {

void Family::resize(int w, int h, int k) {
  width = w;
  height = h;
  tile = k;
  cells_x = (w + k - 1) / k;
  cells_y = (h + k - 1) / k;
  cells.assign(static_cast<size_t>(cells_x) * cells_y, Cell{});
}

Verdict decide(Family& f, const FamilyOptions& o) {
  Verdict v;
  v.alpha_uniform = o.uniformity ? o.alpha / 2 : 0.0;
  v.alpha_tests = o.alpha - v.alpha_uniform;
  std::vector<double> all, per_channel[3];
  auto visit = [&](auto fn) {
    for (size_t i = 0; i < f.cells.size(); ++i) fn(f.cells[i], static_cast<long>(i));
    for (Cell& c : f.global) fn(c, -1L);
  };
  visit([&](Cell& cell, long index) {
    for (int c = 0; c < 3; ++c) {
      switch (cell.status[c]) {
        case CellStatus::kTested:
          ++v.tests;
          all.push_back(cell.p[c]);
          per_channel[c].push_back(cell.p[c]);
          if (cell.p[c] < v.min_p || v.min_c < 0) {
            v.min_p = cell.p[c];
            v.min_c = c;
            v.min_x = index < 0 ? -1 : static_cast<int>(index % f.cells_x) * f.tile;
            v.min_y = index < 0 ? -1 : static_cast<int>(index / f.cells_x) * f.tile;
          }
          break;
        case CellStatus::kEqual: ++v.equal; break;
        case CellStatus::kDeterministic: ++v.certain; break;
        case CellStatus::kNone: break;
      }
    }
  });
  // Zero-variance cells with different means belong to the family too (they may fail it),
  // but not to Benjamini-Hochberg or the uniformity check: their p is no sampling p-value.
  v.sidak_level = sidak_level(v.alpha_tests, v.tests + v.certain);
  v.bh_rejections = benjamini_hochberg(all, v.alpha_tests, &v.bh_threshold);
  double cut = o.bh ? v.bh_threshold : v.sidak_level;
  visit([&](Cell& cell, long index) {
    for (int c = 0; c < 3; ++c) {
      bool tested = cell.status[c] == CellStatus::kTested;
      if (tested && cell.p[c] <= v.sidak_level) ++v.sidak_rejections;
      bool certain_fail =
          cell.status[c] == CellStatus::kDeterministic && cell.p[c] <= v.sidak_level;
      cell.rejected[c] = (tested && (o.bh ? v.bh_rejections > 0 && cell.p[c] <= cut
                                          : cell.p[c] <= cut)) ||
                         certain_fail;
      if (certain_fail && v.deterministic++ == 0) {
        v.det_c = c;
        v.det_diff = cell.diff[c];
        v.det_x = index < 0 ? -1 : static_cast<int>(index % f.cells_x) * f.tile;
        v.det_y = index < 0 ? -1 : static_cast<int>(index / f.cells_x) * f.tile;
      }
    }
  });
  v.rejections = o.bh ? v.bh_rejections : v.sidak_rejections;
  // A cell's channels share their samples, so each channel is checked on its own (its
  // p-values are independent across cells) and the three checks are Bonferroni-combined.
  // The check counts small p-values only: a bias shows as an excess of them, while the
  // bulk of the distribution departs slightly from uniform even without bias (Student's
  // t only approximates the statistic of non-normal radiance at a few samples), which a
  // whole-range Kolmogorov-Smirnov test would flag on large images.
  double min_p = 1;
  for (int c = 0; c < 3; ++c) {
    v.uniform[c] = uniformity(per_channel[c]);
    for (double p : per_channel[c]) v.small[c] += p < kSmallP;
    long m = static_cast<long>(per_channel[c].size());
    min_p = std::min(min_p, binomial_upper_tail(static_cast<long>(v.small[c]), m, kSmallP));
  }
  v.uniform_p = std::min(1.0, 3 * min_p);
  v.uniform_rejected = o.uniformity && v.uniform_p <= v.alpha_uniform;
  v.pass = v.rejections == 0 && v.deterministic == 0 && !v.uniform_rejected;
  return v;
}

void print_verdict(const Verdict& v, const FamilyOptions& o, const Family& f) {
  std::printf("  tests %zu (%dx%d cells of %dx%d px x 3 channels%s), not tested %zu (equal "
              "within float resolution and no variance)\n",
              v.tests, f.cells_x, f.cells_y, f.tile, f.tile,
              f.global.empty() ? "" : ", plus image-wide tests", v.equal);
  std::printf("  significance: alpha %.4g family-wise; per-cell tests %.4g (Sidak per-test "
              "level %.3g%s), uniformity %.4g\n",
              o.alpha, v.alpha_tests, v.sidak_level, o.bh ? ", verdict by Benjamini-Hochberg" : "",
              v.alpha_uniform);
  std::printf("  rejections %zu (Sidak %zu, Benjamini-Hochberg %zu); zero variance with "
              "different means %zu, of which deterministic failures %zu\n",
              v.rejections, v.sidak_rejections, v.bh_rejections, v.certain, v.deterministic);
  if (v.det_c >= 0)
    std::printf("  first deterministic failure at pixel (%d, %d) channel %c: B - A = %.6g\n",
                v.det_x, v.det_y, "RGB"[v.det_c], v.det_diff);
  if (v.min_c >= 0 && v.min_x >= 0)
    std::printf("  smallest p %.3g at pixel (%d, %d) channel %c\n", v.min_p, v.min_x, v.min_y,
                "RGB"[v.min_c]);
  else if (v.min_c >= 0)
    std::printf("  smallest p %.3g (image-wide test, channel %c)\n", v.min_p, "RGB"[v.min_c]);
  std::printf("  uniformity: p < %.2g in R %zu G %zu B %zu of %zu cells (expected %.3g), excess "
              "p %.3g%s\n",
              kSmallP, v.small[0], v.small[1], v.small[2], v.uniform[0].count,
              kSmallP * v.uniform[0].count, v.uniform_p, v.uniform_rejected ? " REJECTED" : "");
  std::printf("  Kolmogorov-Smirnov against U(0,1), for information: D R %.4f G %.4f B %.4f "
              "(p %.3g %.3g %.3g), D+ R %.4f G %.4f B %.4f\n",
              v.uniform[0].d, v.uniform[1].d, v.uniform[2].d, v.uniform[0].p, v.uniform[1].p,
              v.uniform[2].p, v.uniform[0].d_plus, v.uniform[1].d_plus, v.uniform[2].d_plus);
  std::printf("verdict: %s\n", v.pass ? "PASS" : "FAIL");
}

}  // namespace cmp
