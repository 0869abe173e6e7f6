// Exponential, logarithm, power, sine, cosine, arctangent and arccosine of the computation's
// type (cl/util/real.h), built only from operations that every device rounds exactly alike
// (+, -, *, /, sqrt, floor, frexp, ldexp). The libraries' exp, log, pow, sin, cos, atan2 and
// acos differ in the last bit between OpenCL implementations and glibc, and one differing
// bit can send a sampled path elsewhere, so whatever must agree across devices uses these.
//
// Each function is an exact argument reduction and reconstruction, written once, around a
// polynomial in the reduced argument, which is the one part that depends on the precision:
// in float the Cephes single-precision polynomials (about one float ulp), in double Taylor
// or atanh series long enough for double (a few double ulps). tests/util/transcendental_test.cpp
// and transcendental_double_test.cpp state and check the bounds.
//
// ExpR, PowR, SinR and CosR (the end of this file) are what tools/to_real.py writes for
// exp, pow, sin and cos in ray-tracing code: the library's in float and these functions in
// double. PoCL and glibc do not round the library's alike for every argument (the Gaussian
// filter's weights, the disk lens's angles and the ray tree's absorption differed in the
// last bit), so what the devices must agree on takes these functions in float too.
#ifndef RT_UTIL_TRANSCENDENTAL_H
#define RT_UTIL_TRANSCENDENTAL_H

#include "real.h"

#define RT_PI RT_R(3.14159265358979323846)

// ---- The per-precision parts: splits of constants and the reduced polynomials. ----------

#ifdef RT_REAL_DOUBLE

// ln 2 = RT_LN2_HI + RT_LN2_LO, the high part with 32 trailing zero bits, so k * RT_LN2_HI
// is exact for every k in range.
#define RT_LN2_HI 6.93147180369123816490e-01
#define RT_LN2_LO 1.90821492927058770002e-10
// pi/2 as two parts of 33 bits (k * part is exact for |k| < 2^20; the renderer's angles are
// within a few turns) and the rest, fdlibm's split.
#define RT_PIO2_1 1.57079632673412561417e+00
#define RT_PIO2_2 6.07710050630396597660e-11
#define RT_PIO2_3 2.02226624879595063154e-21
// e^x overflows above the first and is below half the least subnormal under the second.
#define RT_EXP_MAX 709.782712893384
#define RT_EXP_MIN -745.1332191019412

// e^r for |r| <= ln2 / 2 by its Taylor series to r^14 / 14! (truncation below 1e-17).
RT_DEVICE real ExpReduced(real r) {
  real term = 1.0, sum = 1.0;
  for (int i = 1; i <= 14; ++i) {
    term = term * r / (real)i;
    sum = sum + term;
  }
  return sum;
}

// ln(1 + f) + k ln 2 for 1 + f in [sqrt(1/2), sqrt(2)): ln(1 + f) = 2 atanh(s) with
// s = f / (2 + f), |s| < 0.1716, by its series to s^25 (truncation below 1e-19).
RT_DEVICE real LogReduced(real f, real k) {
  real s = f / (f + 2.0), s2 = s * s;
  real series = 0.0;
  for (int n = 12; n >= 1; --n) series = (series + 1.0 / (real)(2 * n + 1)) * s2;
  real ln_m = 2.0 * s + 2.0 * s * series;
  return k * RT_LN2_HI + (k * RT_LN2_LO + ln_m);
}

// sin r and cos r for |r| <= pi/4 by their Taylor series to r^21 / 21! and r^20 / 20!.
RT_DEVICE real SinReduced(real r) {
  real r2 = r * r, term = r, sum = r;
  for (int i = 1; i <= 10; ++i) {
    term = -term * r2 / (real)((2 * i) * (2 * i + 1));
    sum = sum + term;
  }
  return sum;
}
RT_DEVICE real CosReduced(real r) {
  real r2 = r * r, term = 1.0, sum = 1.0;
  for (int i = 1; i <= 10; ++i) {
    term = -term * r2 / (real)((2 * i - 1) * (2 * i));
    sum = sum + term;
  }
  return sum;
}

// atan x for |x| <= tan(pi/8) by its series to x^45 / 45 (x^2 <= 0.1716, truncation below
// 1e-18 of x).
RT_DEVICE real AtanReduced(real x) {
  real z = x * x, series = 0.0;
  for (int n = 22; n >= 1; --n) series = (series + ((n & 1) ? -1.0 : 1.0) / (real)(2 * n + 1)) * z;
  return x * series + x;
}

#else  // float

// Cephes' split: 0.693359375 has 9 significant bits.
#define RT_LN2_HI 0.693359375f
#define RT_LN2_LO -2.12194440e-4f
// Cephes' split of pi/2 (twice its pi/4 split): k * part is exact for the few turns the
// renderer's angles span.
#define RT_PIO2_1 1.5703125f
#define RT_PIO2_2 4.837512969970703125e-4f
#define RT_PIO2_3 7.54978995489188216e-8f
// Above 89 the reconstruction below rounds to infinity and under -104 to zero anyway; the
// guards only keep (int)k in range.
#define RT_EXP_MAX 89.0f
#define RT_EXP_MIN -104.0f

// e^r for |r| <= ln2 / 2: the Cephes expf polynomial.
RT_DEVICE real ExpReduced(real r) {
  real z = r * r;
  return (((((1.9875691500e-4f * r + 1.3981999507e-3f) * r + 8.3334519073e-3f) * r +
            4.1665795894e-2f) *
               r +
           1.6666665459e-1f) *
              r +
          5.0000001201e-1f) *
             z +
         r + 1.0f;
}

// ln(1 + f) + k ln 2 for 1 + f in [sqrt(1/2), sqrt(2)): the Cephes logf polynomial, with
// k ln 2 added in Cephes' order (low part first).
RT_DEVICE real LogReduced(real f, real k) {
  real z = f * f;
  real y = ((((((((7.0376836292e-2f * f - 1.1514610310e-1f) * f + 1.1676998740e-1f) * f -
                 1.2420140846e-1f) *
                    f +
                1.4249322787e-1f) *
                   f -
               1.6668057665e-1f) *
                  f +
              2.0000714765e-1f) *
                 f -
             2.4999993993e-1f) *
                f +
            3.3333331174e-1f) *
           f * z;
  y = y + k * RT_LN2_LO;
  y = y - 0.5f * z;
  return f + y + k * RT_LN2_HI;
}

// sin r and cos r for |r| <= pi/4: the Cephes sinf and cosf polynomials.
RT_DEVICE real SinReduced(real r) {
  real z = r * r;
  return ((-1.9515295891e-4f * z + 8.3321608736e-3f) * z - 1.6666654611e-1f) * z * r + r;
}
RT_DEVICE real CosReduced(real r) {
  real z = r * r;
  return ((2.443315711809948e-5f * z - 1.388731625493765e-3f) * z + 4.166664568298827e-2f) * z * z -
         0.5f * z + 1.0f;
}

// atan x for |x| <= tan(pi/8): the Cephes atanf polynomial (odd, degree 9).
RT_DEVICE real AtanReduced(real x) {
  real z = x * x;
  real poly =
      ((8.05374449538e-2f * z - 1.38776856032e-1f) * z + 1.99777106478e-1f) * z - 3.33329491539e-1f;
  return poly * z * x + x;
}

#endif

// ---- The functions: reductions and reconstructions, the same in both precisions. --------

// e^x: x = k ln2 + r with |r| <= ln2 / 2 (exact steps: k * RT_LN2_HI is exact), then e^r
// scaled by 2^k exactly.
RT_DEVICE real Exp(real x) {
  if (x != x) return x;
  if (x > RT_EXP_MAX) return INFINITY;
  if (x < RT_EXP_MIN) return 0.0f;
  real k = floor(x * RT_R(1.4426950408889634) + 0.5f);
  real r = (x - k * RT_LN2_HI) - k * RT_LN2_LO;
  return ldexp(ExpReduced(r), (int)k);
}

// ln x: x = m 2^k exactly (frexp, then one doubling) with m in [sqrt(1/2), sqrt(2)), so that
// f = m - 1 is exact too.
RT_DEVICE real Log(real x) {
  if (!(x > 0.0f)) return x == 0.0f ? -INFINITY : (x - x) / (x - x);
  if (x == INFINITY) return x;
  int k;
  real m = frexp(x, &k);  // m in [0.5, 1).
  if (m < RT_R(0.70710678118654752)) {
    m = m + m;
    k = k - 1;
  }
  return LogReduced(m - 1.0f, (real)k);
}

// x^e for x >= 0 (the renderer's only use) as e^(e ln x), with pow's exact cases.
RT_DEVICE real Pow(real x, real e) {
  if (e == 0.0f || x == 1.0f) return 1.0f;
  if (x == 0.0f) return e > 0.0f ? 0.0f : INFINITY;
  return Exp(e * Log(x));
}

// The quarter turn k (a whole number) modulo 4, without converting a large k to int.
RT_DEVICE int Quadrant(real k) { return (int)(k - 4.0f * floor(k * 0.25f)); }

// sin and cos of q pi/2 + r: the reduced pair, swapped and negated by the quarter turn.
RT_DEVICE void SinCosQuadrant(real r, int q, RT_PRIVATE real* s, RT_PRIVATE real* c) {
  real sr = SinReduced(r), cr = CosReduced(r);
  *s = q == 0 ? sr : (q == 1 ? cr : (q == 2 ? -sr : -cr));
  *c = q == 0 ? cr : (q == 1 ? -sr : (q == 2 ? -cr : sr));
}

// sin x and cos x: x = k pi/2 + r with |r| <= pi/4, pi/2 taken in three parts so that each
// product with k is exact.
RT_DEVICE void SinCos(real x, RT_PRIVATE real* s, RT_PRIVATE real* c) {
  real k = floor(x * RT_R(6.36619772367581382433e-01) + 0.5f);
  real r = ((x - k * RT_PIO2_1) - k * RT_PIO2_2) - k * RT_PIO2_3;
  SinCosQuadrant(r, Quadrant(k), s, c);
}

// sin and cos of 2 pi u (a uniform angle): 4u is reduced to the nearest whole number k
// exactly, and only the remainder, within a quarter turn, is scaled by pi/2.
RT_DEVICE void SinCos2Pi(real u, RT_PRIVATE real* s, RT_PRIVATE real* c) {
  real v = 4.0f * u;
  real k = floor(v + 0.5f);
  SinCosQuadrant((v - k) * (RT_PI * 0.5f), Quadrant(k), s, c);
}

// atan x for x >= 0, reduced below tan(pi/8) through pi/2 - atan(1/x) and
// pi/4 + atan((x - 1) / (x + 1)).
RT_DEVICE real AtanPositive(real x) {
  real base = 0.0f;
  if (x > RT_R(2.414213562373095)) {
    base = RT_PI * 0.5f;
    x = -1.0f / x;
  } else if (x > RT_R(0.4142135623730950)) {
    base = RT_PI * 0.25f;
    x = (x - 1.0f) / (x + 1.0f);
  }
  return base + AtanReduced(x);
}

// The angle of (x, y) in (-pi, pi], as atan2(y, x) (0 at the origin).
RT_DEVICE real Atan2(real y, real x) {
  real ax = fabs(x), ay = fabs(y);
  if (ax == 0.0f && ay == 0.0f) return 0.0f;
  real a = ay <= ax ? AtanPositive(ay / ax) : RT_PI * 0.5f - AtanPositive(ax / ay);
  if (x < 0.0f) a = RT_PI - a;
  return y < 0.0f ? -a : a;
}

// acos c with c clamped to [-1, 1] (rounding may push a unit vector's component past 1),
// as the angle of (c, sqrt(1 - c^2)).
RT_DEVICE real SafeACos(real c) {
  c = fmin(RT_R(1.0), fmax(RT_R(-1.0), c));
  return Atan2(sqrt((1.0f - c) * (1.0f + c)), c);
}

// ---- exp, pow, sin and cos as tools/to_real.py writes them in ray-tracing code. ---------

#ifdef RT_REAL_DOUBLE
RT_DEVICE real ExpR(real x) { return Exp(x); }
RT_DEVICE real PowR(real x, real e) { return Pow(x, e); }
RT_DEVICE real SinR(real x) {
  real s, c;
  SinCos(x, &s, &c);
  return s;
}
RT_DEVICE real CosR(real x) {
  real s, c;
  SinCos(x, &s, &c);
  return c;
}
#else
RT_DEVICE real ExpR(real x) { return exp(x); }
RT_DEVICE real PowR(real x, real e) { return pow(x, e); }
RT_DEVICE real SinR(real x) { return sin(x); }
RT_DEVICE real CosR(real x) { return cos(x); }
#endif

#endif  // RT_UTIL_TRANSCENDENTAL_H
