// Accumulation of a pixel's samples, shared by the CPU reference and the kernel so both
// sum in the same order and agree to the bit when their samples do.
#ifndef RT_FILM_H
#define RT_FILM_H

#include "film_types.h"
#include "integrator/integrator.h"

RT_DEVICE float4 AddFloat4(float4 a, real3 v, real w) {
  a.x += v.x;
  a.y += v.y;
  a.z += v.z;
  a.w += w;
  return a;
}

// Runs samples [begin, end) of pixel (x, y) into *acc. The first sample of a pixel also
// records its deterministic primary-hit facts.
RT_DEVICE void AccumulatePixel(RT_PRIVATE const SceneData* sd, int x, int y, int begin, int end,
                               RT_GLOBAL PixelAccum* acc, RT_GLOBAL PrimaryInfo* primary) {
  PixelAccum a = *acc;
  uint rays = 0u;
  CameraPixel cp = MakeCameraPixel(sd, x, y);
  for (int s = begin; s < end; ++s) {
    real w;
    PrimaryInfo info;
    real3 l = RenderSample(sd, &cp, (uint)s, &w, s == 0 ? &info : 0, &rays);
    if (s == 0) *primary = info;
    if (!isfinite(l.x) || !isfinite(l.y) || !isfinite(l.z)) {
      // Counted, so --stats and the tests can fail on it, but kept off the film.
      a.nonfinite += 1u;
      continue;
    }
    a.sum = AddFloat4(a.sum, l * w, w);
    a.sum_sq = AddFloat4(a.sum_sq, l * l, 1.0f);
  }
  a.rays += rays;
  *acc = a;
}

#endif  // RT_FILM_H
