// The course's gradient noise. Its lattice is not in the scene files; it was recovered
// from the official sphere_perlin image (docs/textures.md): Perlin's construction with a
// 16-entry permutation P and the 16 gradients of his improved noise (the 12 cube edges,
// four of them twice), the gradient of lattice point (i, j, k) being
// G[P[(i + P[(j + P[k mod 16]) mod 16]) mod 16]], each corner weighted by
// 1 - (6|t|^5 - 15|t|^4 + 10|t|^3) per axis. Float arithmetic in a fixed order on both
// devices.
#ifndef RT_PERLIN_H
#define RT_PERLIN_H

#include "../util/math.h"
#include "texture_types.h"

#ifdef __OPENCL_C_VERSION__
#define RT_PERLIN_TABLE __constant
#else
#define RT_PERLIN_TABLE static const
#endif

RT_PERLIN_TABLE int kPerlinPermutation[16] = {4, 10, 11, 15, 14, 5, 13, 1, 6, 9, 3, 7, 8, 2, 0, 12};

// Gradient g as (g.x, g.y, g.z) triples, in the order of Perlin's improved noise.
RT_PERLIN_TABLE real kPerlinGradients[48] = {
    1, 1, 0, -1, 1,  0, 1, -1, 0,  -1, -1, 0,  1, 0, 1, -1, 0, 1, 1, 0,  -1, -1, 0,  -1,
    0, 1, 1, 0,  -1, 1, 0, 1,  -1, 0,  -1, -1, 1, 1, 0, -1, 1, 0, 0, -1, 1,  0,  -1, -1};

// P[i mod 16], also for negative i (two's complement: i & 15 is i mod 16).
RT_DEVICE int PerlinHash(int i) { return kPerlinPermutation[(i < 0 ? -i : i) & 15]; }

// The weight of a lattice point at distance t along one axis (|t| <= 1).
RT_DEVICE real PerlinWeight(real t) {
  t = fabs(t);
  return 1.0f - t * t * t * (t * (t * 6.0f - 15.0f) + 10.0f);
}

// Noise in about [-1, 1], zero on the integer lattice.
RT_DEVICE real PerlinNoise(real3 p) {
  real fx = floor(p.x), fy = floor(p.y), fz = floor(p.z);
  int i0 = (int)fx, j0 = (int)fy, k0 = (int)fz;
  real sum = 0.0f;
  for (int c = 0; c < 8; ++c) {
    int di = c & 1, dj = (c >> 1) & 1, dk = (c >> 2) & 1;
    real dx = p.x - (fx + (real)di), dy = p.y - (fy + (real)dj), dz = p.z - (fz + (real)dk);
    int g = 3 * PerlinHash(i0 + di + PerlinHash(j0 + dj + PerlinHash(k0 + dk)));
    real dot =
        kPerlinGradients[g] * dx + kPerlinGradients[g + 1] * dy + kPerlinGradients[g + 2] * dz;
    sum += PerlinWeight(dx) * PerlinWeight(dy) * PerlinWeight(dz) * dot;
  }
  return sum;
}

// The texture's value at point p: noise at p * NoiseScale, converted to [0, 1].
RT_DEVICE real PerlinTexture(RT_GLOBAL const TextureDesc* t, real3 p) {
  real n = PerlinNoise(p * t->noise_scale);
  return t->noise_conversion == RT_NOISE_ABSVAL ? fabs(n) : (n + 1.0f) * 0.5f;
}

#endif  // RT_PERLIN_H
