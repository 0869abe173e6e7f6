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

  // The reconstructed image: weighted mean radiance per pixel, 3 floats each.
  std::vector<float> rgb() const;
  // Samples that produced NaN or infinite radiance (left off the film); 0 when healthy.
  uint64_t nonfinite() const;
};

// Renders the camera set in `flat` on `threads` CPU threads (0: all cores). The image
// does not depend on the thread count: every pixel is computed by one thread alone.
RenderResult render_cpu(const FlatScene& flat, int threads, Progress& progress);

}  // namespace rt
