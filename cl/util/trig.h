// Trigonometry, logarithm and exponential from additions, multiplications, divisions,
// square roots and exact scalings only, so that both devices round every step alike
// (library sin/cos/atan2/acos/pow differ in the last bit between OpenCL implementations
// and glibc, and one differing bit sends a sampled path elsewhere).
#ifndef RT_UTIL_TRIG_H
#define RT_UTIL_TRIG_H

#include "math.h"

// atan(x) for x >= 0: the argument is reduced below tan(pi/8) (through pi/2 - atan(1/x)
// and pi/4 + atan((x-1)/(x+1))), where an odd polynomial of degree 9 (the Cephes atanf
// coefficients) is accurate to about one float ulp.
RT_DEVICE real AtanPositive(real x) {
  real base = 0.0f;
  if (x > 2.414213562373095f) {
    base = RT_PI * 0.5f;
    x = -1.0f / x;
  } else if (x > 0.4142135623730950f) {
    base = RT_PI * 0.25f;
    x = (x - 1.0f) / (x + 1.0f);
  }
  real z = x * x;
  real poly =
      ((8.05374449538e-2f * z - 1.38776856032e-1f) * z + 1.99777106478e-1f) * z - 3.33329491539e-1f;
  return base + (poly * z * x + x);
}

// The angle of (x, y) in (-pi, pi], as atan2(y, x).
RT_DEVICE real Atan2F(real y, real x) {
  real ax = fabs(x), ay = fabs(y);
  if (ax == 0.0f && ay == 0.0f) return 0.0f;
  real a = ay <= ax ? AtanPositive(ay / ax) : RT_PI * 0.5f - AtanPositive(ax / ay);
  if (x < 0.0f) a = RT_PI - a;
  return y < 0.0f ? -a : a;
}

// acos(c) for c in [-1, 1] (clamped), as the angle of (c, sqrt(1 - c^2)).
RT_DEVICE real AcosF(real c) {
  c = fmin(RT_R(1.0), fmax(RT_R(-1.0), c));
  return Atan2F(sqrt((1.0f - c) * (1.0f + c)), c);
}

// sin and cos of 2 pi u, for u in [0, 1] (a uniform angle). u is reduced exactly to the
// nearest quarter turn, leaving |x| <= pi/4, where the Cephes sinf and cosf polynomials
// are accurate to about one float ulp; the quarter turn then swaps and negates them.
RT_DEVICE void SinCos2Pi(real u, RT_PRIVATE real* s, RT_PRIVATE real* c) {
  real v = 4.0f * u;
  real q = floor(v + 0.5f);
  real x = (v - q) * (RT_PI * 0.5f);
  real z = x * x;
  real sx = ((-1.9515295891e-4f * z + 8.3321608736e-3f) * z - 1.6666654611e-1f) * z * x + x;
  real cx =
      ((2.443315711809948e-5f * z - 1.388731625493765e-3f) * z + 4.166664568298827e-2f) * z * z -
      0.5f * z + 1.0f;
  int quadrant = ((int)q) & 3;
  *s = quadrant == 0 ? sx : (quadrant == 1 ? cx : (quadrant == 2 ? -sx : -cx));
  *c = quadrant == 0 ? cx : (quadrant == 1 ? -sx : (quadrant == 2 ? -cx : sx));
}

// ln(x) for finite x > 0: x = m 2^e exactly (frexp), then the Cephes logf polynomial.
RT_DEVICE real LogF(real x) {
  int e;
  real m = frexp(x, &e);  // m in [0.5, 1).
  if (m < 0.70710678118654752f) {
    e -= 1;
    m = m + m - 1.0f;
  } else {
    m = m - 1.0f;
  }
  real z = m * m;
  real y = ((((((((7.0376836292e-2f * m - 1.1514610310e-1f) * m + 1.1676998740e-1f) * m -
                 1.2420140846e-1f) *
                    m +
                1.4249322787e-1f) *
                   m -
               1.6668057665e-1f) *
                  m +
              2.0000714765e-1f) *
                 m -
             2.4999993993e-1f) *
                m +
            3.3333331174e-1f) *
           m * z;
  real fe = (real)e;
  y = y - 2.12194440e-4f * fe;
  y = y - 0.5f * z;
  return m + y + 0.693359375f * fe;
}

// e^x for |x| < 80: x = n ln 2 + r, the Cephes expf polynomial for e^r, then an exact
// scaling by 2^n (ldexp).
RT_DEVICE real ExpF(real x) {
  real n = floor(1.44269504088896341f * x + 0.5f);
  real r = x - n * 0.693359375f;
  r = r + n * 2.12194440e-4f;
  real z = r * r;
  real p = (((((1.9875691500e-4f * r + 1.3981999507e-3f) * r + 8.3334519073e-3f) * r +
              4.1665795894e-2f) *
                 r +
             1.6666665459e-1f) *
                r +
            5.0000001201e-1f) *
               z +
           r + 1.0f;
  return ldexp(p, (int)n);
}

// x^y for x in (0, 1] and y >= 0 (0 for x = 0), to a few float ulps.
RT_DEVICE real PowUnit(real x, real y) {
  if (!(x > 0.0f)) return 0.0f;
  real l = y * LogF(x);
  return l < -80.0f ? 0.0f : ExpF(l);
}

#endif  // RT_UTIL_TRIG_H
