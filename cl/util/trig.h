// Inverse trigonometry from additions, multiplications, divisions and square roots only,
// so that both devices round every step alike (library atan2/acos differ in the last bit
// between OpenCL implementations and glibc).
#ifndef RT_UTIL_TRIG_H
#define RT_UTIL_TRIG_H

#include "math.h"

// atan(x) for x >= 0: the argument is reduced below tan(pi/8) (through pi/2 - atan(1/x)
// and pi/4 + atan((x-1)/(x+1))), where an odd polynomial of degree 9 (the Cephes atanf
// coefficients) is accurate to about one float ulp.
RT_DEVICE float AtanPositive(float x) {
  float base = 0.0f;
  if (x > 2.414213562373095f) {
    base = RT_PI * 0.5f;
    x = -1.0f / x;
  } else if (x > 0.4142135623730950f) {
    base = RT_PI * 0.25f;
    x = (x - 1.0f) / (x + 1.0f);
  }
  float z = x * x;
  float poly =
      ((8.05374449538e-2f * z - 1.38776856032e-1f) * z + 1.99777106478e-1f) * z - 3.33329491539e-1f;
  return base + (poly * z * x + x);
}

// The angle of (x, y) in (-pi, pi], as atan2(y, x).
RT_DEVICE float Atan2F(float y, float x) {
  float ax = fabs(x), ay = fabs(y);
  if (ax == 0.0f && ay == 0.0f) return 0.0f;
  float a = ay <= ax ? AtanPositive(ay / ax) : RT_PI * 0.5f - AtanPositive(ax / ay);
  if (x < 0.0f) a = RT_PI - a;
  return y < 0.0f ? -a : a;
}

// acos(c) for c in [-1, 1] (clamped), as the angle of (c, sqrt(1 - c^2)).
RT_DEVICE float AcosF(float c) {
  c = fmin(1.0f, fmax(-1.0f, c));
  return Atan2F(sqrt((1.0f - c) * (1.0f + c)), c);
}

// sin(2 pi t) and cos(2 pi t) for any t, from the same operations on both devices (library
// sin and cos, like atan2, differ in the last bit between OpenCL implementations and
// glibc). t is reduced to a quarter turn q and a remainder a in [-pi/4, pi/4], where the
// Cephes sinf/cosf polynomials are accurate to about one float ulp; q rotates the pair.
RT_DEVICE void SinCos2Pi(float t, RT_PRIVATE float* s, RT_PRIVATE float* c) {
  float x = 4.0f * (t - floor(t));  // Quarter turns, in [0, 4].
  float q = floor(x + 0.5f);
  float a = (x - q) * (RT_PI * 0.5f);
  float z = a * a;
  float sa = ((-1.9515295891e-4f * z + 8.3321608736e-3f) * z - 1.6666654611e-1f) * z * a + a;
  float ca =
      ((2.443315711809948e-5f * z - 1.388731625493765e-3f) * z + 4.166664568298827e-2f) * z * z -
      0.5f * z + 1.0f;
  int quarter = ((int)q) & 3;
  *s = quarter == 0 ? sa : (quarter == 1 ? ca : (quarter == 2 ? -sa : -ca));
  *c = quarter == 0 ? ca : (quarter == 1 ? -sa : (quarter == 2 ? -ca : sa));
}

#endif  // RT_UTIL_TRIG_H
