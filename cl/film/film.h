// The film: a pixel's sums of weighted radiance, squared radiance and rays (PixelAccum,
// film_types.h), added to in one order by both devices, so they agree to the bit when
// their samples do.
#ifndef RT_FILM_H
#define RT_FILM_H

#include "../util/math.h"
#include "film_types.h"

RT_DEVICE float4 AddFloat4(float4 a, real3 v, real w) {
  a.x += v.x;
  a.y += v.y;
  a.z += v.z;
  a.w += w;
  return a;
}

// Adds radiance l of reconstruction-filter weight w to the pixel's sums. A NaN or infinite
// sample is counted, so --stats and the tests can fail on it, but kept off the film.
RT_DEVICE_INLINE void AddFilmSample(RT_PRIVATE PixelAccum* a, real3 l, real w) {
  if (!isfinite(l.x) || !isfinite(l.y) || !isfinite(l.z)) {
    a->nonfinite += 1u;
    return;
  }
  a->sum = AddFloat4(a->sum, l * w, w);
  a->sum_sq = AddFloat4(a->sum_sq, l * l, 1.0f);
}

#endif  // RT_FILM_H
