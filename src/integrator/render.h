// What a render produces, whichever device ran it: the film (per-pixel accumulators and
// first-hit facts) and the figures of the run, with the one definition of a pixel's mean
// and variance that the image, the moment files and the noise stop rule share.
#pragma once

#include <cstdint>
#include <vector>

#include "cl/film/film_types.h"

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

// The same image from a film's accumulators.
std::vector<float> film_rgb(const std::vector<PixelAccum>& accum);

// One pixel's estimate from its accumulator, in double from the float sums.
struct PixelEstimate {
  double mean[3] = {0, 0, 0};  // Weighted mean radiance (sum / filter weight); 0 when empty.
  double var[3] = {0, 0, 0};   // Unbiased variance of one sample; 0 with fewer than 2.
  double n = 0;                // Samples taken.
};
PixelEstimate estimate_pixel(const PixelAccum& a);

// The estimated relative error of an image `width` pixels wide: the root mean, over pixels
// and channels, of the variance of the pixel mean over (mean^2 + floor^2) (the square root
// of the relative MSE that bench/sweep measures). The floor keeps dark pixels finite: one
// output level in radiance, 1 on the 0-255 scale of an 8-bit film (noise_floor).
// A pixel whose samples all agree (variance 0) takes its 8 x 8 tile's ratio instead (the
// sum of the tile's variances of the mean over the sum of its mean^2 + floor^2): a path
// tracer's estimate is heavy-tailed, and with few samples most pixels have not yet found
// the light their paths rarely reach, so their own ratio (0 / floor^2) says "converged"
// while the tile has found it. (Without this, --noise-target 0.5 stopped the course's
// uniform diffuse camera after 5 samples, when its error was 10 times the target.) A
// uniformly lit, converged tile has 0 variance and keeps 0.
// 0 with < 2 samples.
double relative_noise(const std::vector<PixelAccum>& accum, int width, double floor = 1.0);

// What relative_noise estimates, measured: the mean over pixels and channels of
// (x - r)^2 / (r^2 + floor^2) of image `img` against a converged `ref` (3 floats a pixel).
double relative_mse(const std::vector<float>& img, const std::vector<float>& ref,
                    double floor = 1.0);

// One output level in radiance. An 8-bit film has radiance on the 0-255 scale: 1. A film
// tone mapped by the photographic operator (tonemap_key > 0: hw5/hw6 HDR cameras, radiance
// in arbitrary units) maps its log-average luminance Yavg to the key and Yavg / key to
// about mid-grey, so a level is taken as Yavg / (key * 255): the same floor relative to
// the image's brightness, whatever the scene's units. Without it a path-traced film of
// radiance near 0.5 would count every pixel's error against 1 + 0.25 instead of 0.25,
// and the noise stop rule would stop long before the error asked for.
double noise_floor(const std::vector<PixelAccum>& accum, double tonemap_key);
double noise_floor(const std::vector<float>& rgb, double tonemap_key);

}  // namespace rt
