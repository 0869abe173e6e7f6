#include "paired.h"

#include <algorithm>
#include <cmath>
#include <stdexcept>

namespace cmp {
namespace {

// -1, 0 (a tie: within the float resolution) or +1.
int sign_of_difference(const rt::MomentImage& a, const rt::MomentImage& b, size_t j,
                       const PairedOptions& o) {
  double ma = a.mean[j], mb = b.mean[j];
  double res = o.rel_tol * std::max(std::fabs(ma), std::fabs(mb)) + o.abs_tol;
  double d = mb - ma;
  return std::fabs(d) <= res ? 0 : (d > 0 ? 1 : -1);
}

void fill(Cell* cell, int c, long pos, long neg, double diff_sum, long k) {
  cell->diff[c] = k ? diff_sum / k : 0.0;
  if (pos + neg == 0) {
    cell->status[c] = CellStatus::kEqual;
    return;
  }
  cell->status[c] = CellStatus::kTested;
  cell->p[c] = sign_test_two_sided(pos, neg);
}

}  // namespace

Family paired_test(const rt::MomentImage& a, const rt::MomentImage& b, const PairedOptions& o) {
  if (a.width != b.width || a.height != b.height) throw std::runtime_error("sizes differ");
  if (o.tile < 2) throw std::runtime_error("paired needs tiles of at least 2x2 pixels");
  Family f;
  f.resize(a.width, a.height, o.tile);
  long gpos[3] = {0, 0, 0}, gneg[3] = {0, 0, 0};
  double gsum[3] = {0, 0, 0};
  for (int cy = 0; cy < f.cells_y; ++cy)
    for (int cx = 0; cx < f.cells_x; ++cx) {
      long pos[3] = {0, 0, 0}, neg[3] = {0, 0, 0}, k = 0;
      double sum[3] = {0, 0, 0};
      for (int y = cy * o.tile; y < std::min(a.height, (cy + 1) * o.tile); ++y)
        for (int x = cx * o.tile; x < std::min(a.width, (cx + 1) * o.tile); ++x, ++k)
          for (int c = 0; c < 3; ++c) {
            size_t j = (static_cast<size_t>(y) * a.width + x) * 3 + c;
            int s = sign_of_difference(a, b, j, o);
            pos[c] += s > 0;
            neg[c] += s < 0;
            sum[c] += static_cast<double>(b.mean[j]) - a.mean[j];
          }
      for (int c = 0; c < 3; ++c) {
        fill(&f.at(cx, cy), c, pos[c], neg[c], sum[c], k);
        gpos[c] += pos[c];
        gneg[c] += neg[c];
        gsum[c] += sum[c];
      }
    }
  // The image-wide test catches a small shift shared by every pixel (a brighter light).
  f.global.resize(1);
  for (int c = 0; c < 3; ++c)
    fill(&f.global[0], c, gpos[c], gneg[c], gsum[c], static_cast<long>(a.pixels()));
  return f;
}

PairedFigures paired_figures(const rt::MomentImage& a, const rt::MomentImage& b,
                             const PairedOptions& o) {
  PairedFigures r;
  for (size_t j = 0; j < a.mean.size(); ++j) {
    ++r.values;
    int s = sign_of_difference(a, b, j, o);
    if (s == 0) continue;
    ++r.differing;
    r.positive += s > 0;
    double d = std::fabs(static_cast<double>(b.mean[j]) - a.mean[j]);
    size_t i = j / 3;
    double se2 = (a.count[i] ? a.var[j] / a.count[i] : 0.0) +
                 (b.count[i] ? b.var[j] / b.count[i] : 0.0);
    r.max_abs = std::max(r.max_abs, d);
    if (se2 > 0) r.max_z = std::max(r.max_z, d / std::sqrt(se2));
  }
  return r;
}

}  // namespace cmp
