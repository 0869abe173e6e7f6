// The per-pixel outputs of a render, as both devices write them: fixed float layouts,
// whatever the precision of the computation (cl/util/real.h), so the host reads the same
// bytes from either device and either precision.
#ifndef RT_FILM_TYPES_H
#define RT_FILM_TYPES_H

#include "../compat.h"

// Per pixel: sum of weight * radiance (xyz) and of weights (w); sum of squared radiance
// (xyz) and the sample count (w), from which compare/ forms per-pixel variances.
typedef struct PixelAccum {
  float4 sum;
  float4 sum_sq;
  uint rays;       // Rays cast for this pixel, for the rays/s figures.
  uint nonfinite;  // Samples whose radiance was NaN or infinite; they are left out.
  uint pad1, pad2;
} PixelAccum;

// Deterministic facts about a pixel's first camera ray, for exact comparisons.
typedef struct PrimaryInfo {
  float t;
  int instance;
  int primitive;
  float3 normal;
} PrimaryInfo;

#endif  // RT_FILM_TYPES_H
