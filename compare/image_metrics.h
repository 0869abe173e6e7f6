// Metrics for comparing a render with a reference image, plus helpers for looking at the
// difference. Used by the tests that check renders against the course's reference images.
#pragma once

#include "../src/io/png_io.h"

namespace rt {

struct ImageDiff {
  double mae = 0;             // mean absolute error over all pixels and channels, 8-bit levels
  double rmse = 0;            // root mean squared error, 8-bit levels
  double psnr = 0;            // 20 * log10(255 / rmse) in dB; +infinity when identical
  double frac_over = 0;       // fraction of pixels whose max channel difference > threshold
  int max_abs = 0;            // largest channel difference
  double frac_identical = 0;  // fraction of pixels identical in all channels
};

// Compares two images of the same size. Throws std::invalid_argument if the sizes differ (the
// message names both sizes) or if a pixel buffer does not match its size. Two empty images count
// as identical.
ImageDiff diff_images(const Image8& a, const Image8& b, int threshold = 8);

// Box-downsamples by k x k, averaging in double and rounding to nearest (halves up). When width or
// height is not divisible by k the trailing partial block is dropped. Lets noisy renders be
// compared at a scale where sampling noise averages out. Throws std::invalid_argument if k < 1.
Image8 downsample(const Image8& img, int k);

// Gray visualization of |a - b| for a person to look at: each pixel is the max channel
// difference times `gain`, rounded and clamped to 255. Throws std::invalid_argument on a size
// mismatch or a negative or NaN gain.
Image8 difference_image(const Image8& a, const Image8& b, double gain = 4.0);

}  // namespace rt
