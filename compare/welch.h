// Welch's unequal-variance t-test between two renders, per pixel or per k x k tile and per
// channel (Jung, Hanika and Dachsbacher, "Detecting Bias in Monte Carlo Renderers using
// Welch's t-test", JCGT 9(2), 2020). Null hypothesis: in every cell, both renders estimate
// the same expected radiance.
#pragma once

#include "family.h"
#include "io/moments.h"
#include "io/png_io.h"

namespace cmp {

struct WelchOptions {
  int tile = 1;  // k: test k x k tiles of pixel means instead of single pixels
  // Float resolution r = rel_tol * |mean| / n^(1/4) + abs_tol of a cell's mean (n: the
  // fewest samples of its pixels), added in quadrature to the standard error. The variance
  // comes from float sums of x and x^2; their rounding, a random walk over n additions,
  // leaves the variance uncertain by about 3 * 2^-24 * sqrt(n) * mean^2, so a pixel whose
  // samples are all alike can show a standard error near sqrt(3 * 2^-24) |mean| / n^(1/4)
  // (4.2e-4 |mean| / n^(1/4)), as can a real but tiny variance; the two cannot be told
  // apart. Cells where both variances are 0 (every sample alike, or rounding below zero)
  // are counted apart: means within r are equal and not tested; others are tested on r
  // alone and, when rejected, are deterministic failures.
  double rel_tol = 6e-4;
  // Take each pixel's per-sample variance as the larger of the two renders' estimates.
  // Right when both draw from the same per-sample distribution (same scene and sampler,
  // other sample counts): a render with few samples can see none of a pixel's rare
  // bright paths and report zero variance, which plain Welch then trusts.
  bool pooled = false;
  double abs_tol = 1e-6;
};

// Throws std::runtime_error when the two files cannot be tested against each other:
// different sizes, fewer than 2 samples in a pixel, or a weighted (Gaussian-filter) mean
// unless `allow_weighted`.
void check_testable(const rt::MomentImage& a, const rt::MomentImage& b, bool allow_weighted);

// Per cell and channel: t = (mean_B - mean_A) / sqrt(se_A^2 + se_B^2 + r^2), where a tile's
// mean is the mean of its pixel means and se^2 the sum of var / n over its pixels divided
// by K^2, r the float resolution; degrees of freedom by Welch-Satterthwaite over every
// pixel of both renders in the cell; two-sided p from Student's t.
Family welch_test(const rt::MomentImage& a, const rt::MomentImage& b, const WelchOptions& o);

// The same against an 8-bit image that carries no variance (e.g. a converged reference):
// the reference's rounding error counts as uniform noise of variance 1/12 level^2 (with
// infinite degrees of freedom), and the candidate's means are clamped to [0, 255] as its
// PNG would be.
Family welch_vs_image(const rt::Image8& ref, const rt::MomentImage& b, const WelchOptions& o);

}  // namespace cmp
