#include "report_model.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <numeric>

namespace cmp {
namespace {

std::string fmt(const char* format, double a, double b = 0, double c = 0, double d = 0) {
  char buf[200];
  std::snprintf(buf, sizeof buf, format, a, b, c, d);
  return buf;
}

void fill_tiles(const Side& a, const Side& b, Analysis* r) {
  bool moments = a.has_moments && b.has_moments;
  int w = r->width, t = r->tile;
  for (int ty = 0; ty < r->tiles_y; ++ty)
    for (int tx = 0; tx < r->tiles_x; ++tx) {
      TileFigures f;
      f.x = tx * t;
      f.y = ty * t;
      f.w = std::min(t, w - f.x);
      f.h = std::min(t, r->height - f.y);
      double sum = 0;
      for (int y = f.y; y < f.y + f.h; ++y)
        for (int x = f.x; x < f.x + f.w; ++x) {
          size_t i = static_cast<size_t>(y) * w + x;
          sum += r->pixel_diff[i];
          f.max_abs = std::max(f.max_abs, static_cast<int>(r->pixel_diff[i]));
          for (int c = 0; c < 3; ++c) {
            f.mean_a[c] += moments ? a.moments.mean[i * 3 + c] : a.image.rgb[i * 3 + c];
            f.mean_b[c] += moments ? b.moments.mean[i * 3 + c] : b.image.rgb[i * 3 + c];
          }
        }
      double n = static_cast<double>(f.w) * f.h;
      f.mean_abs = sum / n;
      for (int c = 0; c < 3; ++c) {
        f.mean_a[c] /= n;
        f.mean_b[c] /= n;
      }
      r->tiles.push_back(f);
    }
}

// Runs the test that fits the moments' seeds and copies each cell's result to its tile.
void test_moments(const Side& a, const Side& b, const ReportOptions& o, Analysis* r) {
  bool same_seed = a.moments.info.seed == b.moments.info.seed;
  try {
    check_testable(a.moments, b.moments, same_seed);
    if (same_seed) {
      PairedOptions po = o.paired;
      po.tile = std::max(2, o.tile);
      r->family = paired_test(a.moments, b.moments, po);
      r->test = "paired";
    } else {
      WelchOptions wo = o.welch;
      wo.tile = o.tile;
      wo.pooled = wo.pooled || a.moments.info.spp != b.moments.info.spp;
      r->family = welch_test(a.moments, b.moments, wo);
      r->test = "welch";
    }
  } catch (const std::exception& e) {
    r->untested_why = e.what();
    return;
  }
  r->verdict = decide(r->family, o.family);
  for (size_t i = 0; i < r->tiles.size() && i < r->family.cells.size(); ++i) {
    const Cell& cell = r->family.cells[i];
    TileFigures& f = r->tiles[i];
    for (int c = 0; c < 3; ++c) {
      if (cell.status[c] == CellStatus::kNone || cell.status[c] == CellStatus::kEqual) continue;
      f.tested = true;
      f.p = std::min(f.p, cell.p[c]);
      f.rejected |= cell.rejected[c];
    }
  }
}

std::string summary_words(const Analysis& r) {
  return fmt(
      "largest difference %.0f levels, mean |B - A| %.3g levels, %.3g %% of pixels "
      "differ (%.3g %% by more than 8)",
      r.diff.max_abs, r.diff.mae, 100 * (1 - r.diff.frac_identical), 100 * r.diff.frac_over);
}

std::string biased_words(const Analysis& r) {
  std::vector<size_t> rejected;
  for (size_t i : r.worst)
    if (r.tiles[i].rejected) rejected.push_back(i);
  size_t total = 0;
  for (const TileFigures& t : r.tiles) total += t.rejected;
  if (total == 0) {
    bool global = false;
    for (const Cell& c : r.family.global) global |= c.rejected[0] || c.rejected[1] || c.rejected[2];
    std::string why = global ? "the image-wide sign test rejects"
                      : r.verdict.uniform_rejected
                          ? "too many small p-values: a small shift spread over many tiles"
                          : "a deterministic difference";
    return "biased across the whole image (" + r.test + " test): " + why +
           ", though no single tile is rejected";
  }
  std::string s = "biased here: " + std::to_string(total) + " of " +
                  std::to_string(r.tiles.size()) + " tiles fail the " + r.test + " test: ";
  for (size_t k = 0; k < rejected.size(); ++k)
    s += (k ? ", " : "") + tile_name(r.tiles[rejected[k]]);
  if (total > rejected.size()) s += " and " + std::to_string(total - rejected.size()) + " more";
  return s;
}

}  // namespace

std::vector<size_t> worst_tiles(const std::vector<TileFigures>& tiles, size_t n) {
  std::vector<size_t> order;
  for (size_t i = 0; i < tiles.size(); ++i)
    if (tiles[i].rejected || tiles[i].max_abs > 0) order.push_back(i);
  std::stable_sort(order.begin(), order.end(), [&](size_t i, size_t j) {
    const TileFigures &a = tiles[i], &b = tiles[j];
    // One key, so the order is strict and weak: rejected, then tested by p, then the rest.
    if (a.rejected != b.rejected) return a.rejected;
    if (a.tested != b.tested) return a.tested;
    if (a.tested && a.p != b.p) return a.p < b.p;
    if (a.mean_abs != b.mean_abs) return a.mean_abs > b.mean_abs;
    return a.max_abs > b.max_abs;
  });
  if (order.size() > n) order.resize(n);
  return order;
}

std::string tile_name(const TileFigures& t) {
  return "(" + std::to_string(t.x) + ", " + std::to_string(t.y) + ")-(" +
         std::to_string(t.x + t.w - 1) + ", " + std::to_string(t.y + t.h - 1) + ")";
}

Analysis analyse(const Side& a, const Side& b, const ReportOptions& o) {
  require_same_size(a.path, a.image.width, a.image.height, b.path, b.image.width, b.image.height);
  Analysis r;
  r.width = a.image.width;
  r.height = a.image.height;
  r.tile = std::max(1, o.tile);
  r.tiles_x = (r.width + r.tile - 1) / r.tile;
  r.tiles_y = (r.height + r.tile - 1) / r.tile;
  r.diff = rt::diff_images(a.image, b.image, 8);
  r.pixel_diff.resize(static_cast<size_t>(r.width) * r.height);
  for (size_t i = 0; i < r.pixel_diff.size(); ++i) {
    int d = 0;
    for (int c = 0; c < 3; ++c)
      d = std::max(d, std::abs(a.image.rgb[i * 3 + c] - b.image.rgb[i * 3 + c]));
    r.pixel_diff[i] = static_cast<float>(d);
  }
  // The map's top is the 99.9th percentile, so that one wild pixel does not darken the
  // rest; brighter pixels saturate (the worst tiles show them enlarged).
  if (!r.pixel_diff.empty()) {
    std::vector<float> sorted = r.pixel_diff;
    size_t k = std::min(sorted.size() - 1, static_cast<size_t>(0.999 * sorted.size()));
    std::nth_element(sorted.begin(), sorted.begin() + k, sorted.end());
    r.scale = std::max(1.0f, sorted[k]);
  }
  fill_tiles(a, b, &r);
  bool moments = a.has_moments && b.has_moments;
  bool identical = a.image.rgb == b.image.rgb && (!moments || a.moments.mean == b.moments.mean);
  if (moments && !identical) test_moments(a, b, o, &r);
  r.worst = worst_tiles(r.tiles, static_cast<size_t>(std::max(0, o.worst)));
  if (identical) {
    r.finding = Finding::kIdentical;
    r.words = moments ? "identical: A and B hold the same pixels and the same mean radiance"
                      : "identical: A and B hold the same pixel values";
  } else if (!r.test.empty() && r.verdict.pass) {
    r.finding = Finding::kWithinNoise;
    r.words = "within noise: the " + r.test + " test finds no difference beyond the " +
              "sampling noise (" + std::to_string(r.verdict.tests) + " tests, alpha " +
              fmt("%g", o.family.alpha) + "); " + summary_words(r);
  } else if (!r.test.empty()) {
    r.finding = Finding::kBiased;
    r.words = biased_words(r);
  } else {
    r.finding = Finding::kDiffer;
    r.words = "differ (no moments on both sides to test): " + summary_words(r);
    if (!r.untested_why.empty()) r.words += "; moments not tested: " + r.untested_why;
  }
  return r;
}

}  // namespace cmp
