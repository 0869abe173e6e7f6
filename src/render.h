// What a render produces, whichever device ran it, and the CPU reference renderer.
#pragma once

#include <cstdint>
#include <vector>

#include "cl/film.h"
#include "flat_scene.h"
#include "progress.h"

namespace rt {

struct RenderResult {
  int width = 0, height = 0;
  std::vector<PixelAccum> accum;
  std::vector<PrimaryInfo> primary;
  double seconds = 0;
  uint64_t samples = 0, rays = 0;
  int spp = 0;  // Samples per pixel actually taken (fewer than asked when a StopRule hit).

  // The reconstructed image: weighted mean radiance per pixel, 3 floats each.
  std::vector<float> rgb() const;
  // Samples that produced NaN or infinite radiance (left off the film); 0 when healthy.
  uint64_t nonfinite() const;
};

// The estimated relative error of an image: the root mean, over pixels and channels, of
// the variance of the pixel mean over (mean^2 + 1), radiance on the 0-255 scale (the
// square root of the relative MSE that bench/sweep measures). 0 with < 2 samples.
double relative_noise(const std::vector<PixelAccum>& accum);

// Renders the camera set in `flat` on `threads` CPU threads (0: all cores), in passes of
// samples over the whole image. The image does not depend on the thread count: every
// pixel's samples are taken in order by one thread at a time.
RenderResult render_cpu(const FlatScene& flat, int threads, Progress& progress,
                        const StopRule& stop = StopRule());

}  // namespace rt
