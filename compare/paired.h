// The paired comparison of two renders that drew the same random numbers (equal seeds):
// their per-pixel means then differ only where the two computations diverge, so a
// systematic difference stands out far above the sampling noise.
//
// Null hypothesis: each pixel's difference d = mean_B - mean_A is symmetric about zero
// (positive and negative equally likely), independently across pixels. It holds when B
// is A computed with other rounding (the divergences go either way), and also when the
// seeds differ and both renders estimate the same image (d is then the difference of two
// exchangeable estimates) — so the test keeps its level either way, and is most powerful
// with equal seeds. Differences within the float resolution count as ties and are dropped.
#pragma once

#include "family.h"
#include "io/moments.h"

namespace cmp {

struct PairedOptions {
  int tile = 8;  // cells of k x k pixels; every cell's sign test sees up to k^2 pixels
  // Ties: |B - A| <= rel_tol * |mean| + abs_tol. Same-seed renders sum the same samples in
  // the same order, so their means differ only by rounding in the samples themselves.
  double rel_tol = 1e-4;
  double abs_tol = 1e-6;
};

// Per tile and channel, and over the whole image per channel: an exact two-sided sign
// test of the number of positive against negative per-pixel differences.
Family paired_test(const rt::MomentImage& a, const rt::MomentImage& b, const PairedOptions& o);

// Per-pixel figures for a person: how many pixel-channels differ beyond the float
// resolution, and the largest difference relative to the unpaired standard error.
struct PairedFigures {
  size_t values = 0, differing = 0, positive = 0;
  double max_abs = 0, max_z = 0;
};
PairedFigures paired_figures(const rt::MomentImage& a, const rt::MomentImage& b,
                             const PairedOptions& o);

}  // namespace cmp
