// A family of per-cell, per-channel tests over an image (a cell is a pixel or a k x k
// tile) and the one verdict drawn from it: family-wise correction (Sidak, or optionally
// Benjamini-Hochberg), deterministic failures, and a check that the p-values are uniform.
#pragma once

#include <cstdint>
#include <string>
#include <vector>

#include "stats.h"

namespace cmp {

enum class CellStatus : uint8_t {
  kTested,         // p holds a p-value
  kEqual,          // no variance at float resolution and equal means: nothing to test
  kDeterministic,  // zero variance in both, different means: p compares the difference
                   // with the float resolution alone; rejected, a deterministic failure
  kNone,           // no data (e.g. a tile with no observations)
};

struct Cell {
  double p[3] = {1, 1, 1};
  double diff[3] = {0, 0, 0};  // B - A, in radiance units (255 = white)
  CellStatus status[3] = {CellStatus::kNone, CellStatus::kNone, CellStatus::kNone};
  bool rejected[3] = {false, false, false};  // Filled in by decide().
};

struct FamilyOptions {
  double alpha = 0.01;     // Family-wise false-alarm probability of the whole verdict.
  bool bh = false;         // Reject by Benjamini-Hochberg instead of Sidak.
  bool uniformity = true;  // Also fail when small p-values are over-represented.
};

// The grid of cells plus extra image-wide tests (which have no place on the grid).
struct Family {
  int width = 0, height = 0;  // image size in pixels
  int tile = 1;               // cell edge in pixels
  int cells_x = 0, cells_y = 0;
  std::vector<Cell> cells;
  std::vector<Cell> global;  // e.g. the whole-image sign test of `paired`

  void resize(int w, int h, int k);
  Cell& at(int cx, int cy) { return cells[static_cast<size_t>(cy) * cells_x + cx]; }
};

// A p-value below this counts as "small" for the uniformity check.
constexpr double kSmallP = 0.05;

struct Verdict {
  size_t tests = 0, equal = 0;
  size_t certain = 0;        // zero-variance cells with different means (tested on r)
  size_t deterministic = 0;  // of those, the rejected: deterministic failures
  size_t rejections = 0;     // by the method the verdict uses
  size_t sidak_rejections = 0, bh_rejections = 0;
  double alpha_tests = 0;    // the share of alpha given to the per-cell tests
  double alpha_uniform = 0;  // the share given to the uniformity check (0: off)
  double sidak_level = 0;    // per-test level
  double bh_threshold = 0;   // largest p rejected by BH (0: none)
  double min_p = 1;
  int min_x = -1, min_y = -1, min_c = -1;  // first pixel of the cell, channel
  int det_x = -1, det_y = -1, det_c = -1;  // the first deterministic failure
  double det_diff = 0;
  // The uniformity check, per channel over the cells (independent under H0): the count of
  // p-values below kSmallP against Binomial(m, kSmallP), Bonferroni over the channels.
  // The Kolmogorov-Smirnov figures are printed for information only (see decide()).
  Uniformity uniform[3];
  size_t small[3] = {0, 0, 0};
  double uniform_p = 1;
  bool uniform_rejected = false;
  bool pass = true;
};

// Marks rejected cells in `f` and returns the verdict. With the uniformity check on, alpha
// is split evenly between the cell tests and the check (Bonferroni), so the verdict's
// false-alarm probability stays at most alpha.
Verdict decide(Family& f, const FamilyOptions& o);

// Prints the figures, one per line, indented, then "verdict: PASS|FAIL".
void print_verdict(const Verdict& v, const FamilyOptions& o, const Family& f);

}  // namespace cmp
