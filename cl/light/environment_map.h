// The environment map of a SphericalDirectionalLight: how a direction finds its texel, and
// back (the two mappings the course's files name), and the piecewise-constant density over
// the map that importance sampling draws from. No scene data here, so the host builds the
// density from the same mapping functions the kernel samples with.
//
// Directions are world-space unit vectors; +y is up and -z is the direction of the map's
// centre, as in the specification's formula. u runs along the rows from the left edge, v
// down from the top edge, both in [0, 1].
#ifndef RT_LIGHT_ENVIRONMENT_MAP_H
#define RT_LIGHT_ENVIRONMENT_MAP_H

#include "../util/math.h"
#include "../util/transcendental.h"

// Mappings (the light's `type` attribute).
// Latitude-longitude, hw5/SPEC.txt: u = (1 + atan2(x, -z) / pi) / 2, v = acos(y) / pi.
#define RT_ENV_LATLONG 0
// Debevec's angular light probe: the disc inscribed in the image, -z at its centre, the
// angle from -z growing linearly with the distance from the centre to pi on the rim:
// (u, v) = (1 + r x, 1 - r y) / 2 with r = acos(-z) / (pi sqrt(x^2 + y^2)).
#define RT_ENV_PROBE 1

// How direct lighting draws the light's directions (the light's `Sampler`).
#define RT_ENV_SAMPLE_IMPORTANCE 0  // By the map's luminance (the default).
#define RT_ENV_SAMPLE_UNIFORM \
  1  // Uniformly over the hemisphere, density 1 / (2 pi): the specification's.
#define RT_ENV_SAMPLE_COSINE 2  // By cos(theta) / pi over the hemisphere.

// The map coordinates of unit direction d.
RT_DEVICE real2 EnvDirectionToUV(int mapping, real3 d) {
  if (mapping == RT_ENV_PROBE) {
    real len = sqrt(d.x * d.x + d.y * d.y);
    // Straight ahead is the centre; straight behind is anywhere on the rim (its right end).
    if (len == 0.0f) return make_real2(d.z <= 0.0f ? 0.5f : 1.0f, 0.5f);
    real r = SafeACos(-d.z) / (RT_PI * len);
    return make_real2(0.5f * (1.0f + r * d.x), 0.5f * (1.0f - r * d.y));
  }
  return make_real2(0.5f * (1.0f + Atan2(d.x, -d.z) / RT_PI), SafeACos(d.y) / RT_PI);
}

// The unit direction at map coordinates uv, and in *jacobian the solid angle per unit of
// map area there (dw / (du dv)), which turns a density over the map into one over
// directions. Points of a probe image outside its disc have no direction: jacobian 0.
RT_DEVICE real3 EnvUVToDirection(int mapping, real2 uv, RT_PRIVATE real* jacobian) {
  real s, c;
  if (mapping == RT_ENV_PROBE) {
    real a = 2.0f * uv.x - 1.0f, b = 1.0f - 2.0f * uv.y;
    real r = sqrt(a * a + b * b);
    if (r > 1.0f) {
      *jacobian = 0.0f;
      return make_real3(0.0f, 0.0f, -1.0f);
    }
    if (r == 0.0f) {
      *jacobian = 4.0f * RT_PI * RT_PI;  // The limit of 4 pi sin(pi r) / r.
      return make_real3(0.0f, 0.0f, -1.0f);
    }
    SinCos2Pi(0.5f * r, &s, &c);  // The angle from -z is pi r.
    // The disc has area 1/4 in uv: du dv = dA / 4 and dw = pi sin(pi r) / r dA.
    *jacobian = 4.0f * RT_PI * s / r;
    return make_real3(s * a / r, s * b / r, -c);
  }
  real sp, cp;
  SinCos2Pi(uv.x - 0.5f, &sp, &cp);  // phi = 2 pi (u - 1/2) = atan2(x, -z).
  SinCos2Pi(0.5f * uv.y, &s, &c);    // theta = pi v = acos(y).
  *jacobian = 2.0f * RT_PI * RT_PI * s;
  return make_real3(s * sp, c, -s * cp);
}

// The texel (column, row) holding uv: the one whose square contains (u W, v H), clamped
// to the image (nearest lookup: the radiance is constant over a texel, as the density is).
RT_DEVICE int EnvTexelIndex(real2 uv, int width, int height) {
  int x = (int)floor(uv.x * (real)width), y = (int)floor(uv.y * (real)height);
  x = x < 0 ? 0 : (x >= width ? width - 1 : x);
  y = y < 0 ? 0 : (y >= height ? height - 1 : y);
  return y * width + x;
}

// Inverts a 1D cumulative distribution of n steps (cdf[0] = 0 ... cdf[n] = 1): the step i
// with cdf[i] <= u < cdf[i + 1] (steps of zero width are never chosen), and in *offset
// where u falls inside it, in [0, 1). A binary search, as pbrt-v4's
// PiecewiseConstant1D::Sample.
RT_DEVICE int SampleCdf(RT_GLOBAL const float* cdf, int n, real u, RT_PRIVATE real* offset) {
  int lo = 0, hi = n;
  while (hi - lo > 1) {
    int mid = (lo + hi) / 2;
    if (cdf[mid] <= u)
      lo = mid;
    else
      hi = mid;
  }
  real o = (u - cdf[lo]) / (cdf[lo + 1] - cdf[lo]);
  *offset = o < 0.99999994f ? o : 0.99999994f;  // The largest float below 1.
  return lo;
}

#endif  // RT_LIGHT_ENVIRONMENT_MAP_H
