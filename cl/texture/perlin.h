// Gradient noise after Ken Perlin's reference "improved noise" (2002): his permutation
// of 0..255, the twelve cube-edge gradients picked by the hash's low four bits, and the
// quintic fade 6t^5 - 15t^4 + 10t^3. Float arithmetic in a fixed order on both devices.
#ifndef RT_PERLIN_H
#define RT_PERLIN_H

#include "../util/math.h"
#include "texture_types.h"

#ifdef __OPENCL_C_VERSION__
#define RT_PERLIN_TABLE __constant uchar
#else
#define RT_PERLIN_TABLE static const unsigned char
#endif

RT_PERLIN_TABLE kPerlinPermutation[256] = {
    151, 160, 137, 91,  90,  15,  131, 13,  201, 95,  96,  53,  194, 233, 7,   225, 140, 36,  103,
    30,  69,  142, 8,   99,  37,  240, 21,  10,  23,  190, 6,   148, 247, 120, 234, 75,  0,   26,
    197, 62,  94,  252, 219, 203, 117, 35,  11,  32,  57,  177, 33,  88,  237, 149, 56,  87,  174,
    20,  125, 136, 171, 168, 68,  175, 74,  165, 71,  134, 139, 48,  27,  166, 77,  146, 158, 231,
    83,  111, 229, 122, 60,  211, 133, 230, 220, 105, 92,  41,  55,  46,  245, 40,  244, 102, 143,
    54,  65,  25,  63,  161, 1,   216, 80,  73,  209, 76,  132, 187, 208, 89,  18,  169, 200, 196,
    135, 130, 116, 188, 159, 86,  164, 100, 109, 198, 173, 186, 3,   64,  52,  217, 226, 250, 124,
    123, 5,   202, 38,  147, 118, 126, 255, 82,  85,  212, 207, 206, 59,  227, 47,  16,  58,  17,
    182, 189, 28,  42,  223, 183, 170, 213, 119, 248, 152, 2,   44,  154, 163, 70,  221, 153, 101,
    155, 167, 43,  172, 9,   129, 22,  39,  253, 19,  98,  108, 110, 79,  113, 224, 232, 178, 185,
    112, 104, 218, 246, 97,  228, 251, 34,  242, 193, 238, 210, 144, 12,  191, 179, 162, 241, 81,
    51,  145, 235, 249, 14,  239, 107, 49,  192, 214, 31,  181, 199, 106, 157, 184, 84,  204, 176,
    115, 121, 50,  45,  127, 4,   150, 254, 138, 236, 205, 93,  222, 114, 67,  29,  24,  72,  243,
    141, 128, 195, 78,  66,  215, 61,  156, 180};

// The reference doubles the table to avoid wrapping; indexing modulo 256 is the same.
RT_DEVICE int PerlinHash(int i) { return (int)kPerlinPermutation[i & 255]; }

RT_DEVICE float PerlinFade(float t) { return t * t * t * (t * (t * 6.0f - 15.0f) + 10.0f); }

RT_DEVICE float PerlinLerp(float t, float a, float b) { return a + t * (b - a); }

// The dot product of (x, y, z) with one of the twelve edge directions (four repeated).
RT_DEVICE float PerlinGrad(int hash, float x, float y, float z) {
  int h = hash & 15;
  float u = h < 8 ? x : y;
  float v = h < 4 ? y : (h == 12 || h == 14 ? x : z);
  return ((h & 1) == 0 ? u : -u) + ((h & 2) == 0 ? v : -v);
}

// Noise in about [-1, 1], zero on the integer lattice.
RT_DEVICE float PerlinNoise(float3 p) {
  float fx = floor(p.x), fy = floor(p.y), fz = floor(p.z);
  int X = (int)fx & 255, Y = (int)fy & 255, Z = (int)fz & 255;
  float x = p.x - fx, y = p.y - fy, z = p.z - fz;
  float u = PerlinFade(x), v = PerlinFade(y), w = PerlinFade(z);
  int A = PerlinHash(X) + Y, AA = PerlinHash(A) + Z, AB = PerlinHash(A + 1) + Z;
  int B = PerlinHash(X + 1) + Y, BA = PerlinHash(B) + Z, BB = PerlinHash(B + 1) + Z;
  float x1 = x - 1.0f, y1 = y - 1.0f, z1 = z - 1.0f;
  float near_z = PerlinLerp(
      v, PerlinLerp(u, PerlinGrad(PerlinHash(AA), x, y, z), PerlinGrad(PerlinHash(BA), x1, y, z)),
      PerlinLerp(u, PerlinGrad(PerlinHash(AB), x, y1, z), PerlinGrad(PerlinHash(BB), x1, y1, z)));
  float far_z = PerlinLerp(v,
                           PerlinLerp(u, PerlinGrad(PerlinHash(AA + 1), x, y, z1),
                                      PerlinGrad(PerlinHash(BA + 1), x1, y, z1)),
                           PerlinLerp(u, PerlinGrad(PerlinHash(AB + 1), x, y1, z1),
                                      PerlinGrad(PerlinHash(BB + 1), x1, y1, z1)));
  return PerlinLerp(w, near_z, far_z);
}

// The texture's value at point p: noise at p * NoiseScale, converted to [0, 1].
RT_DEVICE float PerlinTexture(RT_GLOBAL const TextureDesc* t, float3 p) {
  float n = PerlinNoise(p * t->noise_scale);
  return t->noise_conversion == RT_NOISE_ABSVAL ? fabs(n) : (n + 1.0f) * 0.5f;
}

#endif  // RT_PERLIN_H
