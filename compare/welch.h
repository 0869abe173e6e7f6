// Welch's unequal-variance t-test between two renders, per pixel or per k x k tile and per
// channel (Jung, Hanika and Dachsbacher, "Detecting Bias in Monte Carlo Renderers using
// Welch's t-test", JCGT 9(2), 2020). Null hypothesis: in every cell, both renders estimate
// the same expected radiance.
#pragma once

#include "family.h"
#include "moments.h"
#include "png_io.h"

namespace cmp {

struct WelchOptions {
  int tile = 1;  // k: test k x k tiles of pixel means instead of single pixels
  // Float resolution r = rel_tol * |mean| + abs_tol of a cell's standard error. The
  // variance comes from float sums of x and x^2, whose rounding leaves it uncertain by up to
  // about 3 * 2^-24 * n * mean^2, so the standard error of the mean is only known to about
  // sqrt(3 * 2^-24) |mean| = 4.2e-4 |mean|, whatever n. A cell whose standard error is
  // below r has "zero variance"; its means must then agree within 4 r. Elsewhere r^2 is
  // added to the variance of the difference, which keeps tiny variances honest.
  double rel_tol = 5e-4;
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
