// What a render produces, whichever device ran it: the film (per-pixel accumulators and
// first-hit facts) and the figures of the run, with the one definition of a pixel's mean
// and variance that the image, the moment files and the noise stop rule share.
#pragma once

#include <cstdint>
#include <vector>

#include "cl/film_types.h"

namespace rt {

struct RenderResult {
  int width = 0, height = 0;
  std::vector<PixelAccum> accum;
  std::vector<PrimaryInfo> primary;
  double seconds = 0;
  uint64_t samples = 0, rays = 0;
  int spp = 0;  // Samples per pixel actually taken (fewer than asked when a StopRule hit).
  bool cancelled = false;  // Sampling was stopped early by request (an interrupt).

  // The reconstructed image: weighted mean radiance per pixel, 3 floats each.
  std::vector<float> rgb() const;
  // Samples that produced NaN or infinite radiance (left off the film); 0 when healthy.
  uint64_t nonfinite() const;
};

// One pixel's estimate from its accumulator, in double from the float sums.
struct PixelEstimate {
  double mean[3] = {0, 0, 0};  // Weighted mean radiance (sum / filter weight); 0 when empty.
  double var[3] = {0, 0, 0};   // Unbiased variance of one sample; 0 with fewer than 2.
  double n = 0;                // Samples taken.
};
PixelEstimate estimate_pixel(const PixelAccum& a);

// The estimated relative error of an image: the root mean, over pixels and channels, of
// the variance of the pixel mean over (mean^2 + 1), radiance on the 0-255 scale (the
// square root of the relative MSE that bench/sweep measures). 0 with < 2 samples.
double relative_noise(const std::vector<PixelAccum>& accum);

}  // namespace rt
