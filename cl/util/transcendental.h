// exp, log, pow, sin and cos of the computation's type (cl/util/real.h). In float they are
// the library's, which PoCL and glibc round alike. In double the two libraries differ in the
// last bit, so the double versions here use only operations both devices round exactly
// (+, -, *, /, floor, frexp, ldexp): argument reduction by exact steps, then a polynomial
// in the reduced argument, evaluated in a fixed order. Accuracy: a few ulps of double.
#ifndef RT_UTIL_TRANSCENDENTAL_H
#define RT_UTIL_TRANSCENDENTAL_H

#include "real.h"

#ifndef RT_REAL_DOUBLE

RT_DEVICE real ExpR(real x) { return exp(x); }
RT_DEVICE real PowR(real x, real e) { return pow(x, e); }
RT_DEVICE real SinR(real x) { return sin(x); }
RT_DEVICE real CosR(real x) { return cos(x); }

#else

// e^x: x = k ln2 + r with |r| <= ln2 / 2 (ln2 split in a high part with 32 trailing zero
// bits, so k * high is exact for any k in range), e^r by its Taylor series to r^14 / 14!
// (error < 1e-17 there), then 2^k exactly.
RT_DEVICE real ExpR(real x) {
  if (x != x) return x;
  if (x > 709.782712893384) return x * 1e308 * 10.0;  // Overflows to +inf.
  if (x < -745.1332191019412) return 0.0;
  real k = floor(x * 1.4426950408889634 + 0.5);
  real r = (x - k * 6.93147180369123816490e-01) - k * 1.90821492927058770002e-10;
  real term = 1.0, sum = 1.0;
  for (int i = 1; i <= 14; ++i) {
    term = term * r / (real)i;
    sum = sum + term;
  }
  return ldexp(sum, (int)k);
}

// ln x for x > 0: x = m 2^k with m in [sqrt(1/2), sqrt(2)), ln m = 2 atanh(s) with
// s = (m - 1) / (m + 1), |s| < 0.1716, by its series to s^25 (error < 1e-19).
RT_DEVICE real LogR(real x) {
  if (!(x > 0.0)) return x == 0.0 ? -INFINITY : (x - x) / (x - x);
  if (x == INFINITY) return x;
  int k;
  real m = frexp(x, &k);  // m in [0.5, 1).
  if (m < 0.70710678118654752) {
    m = m * 2.0;
    k = k - 1;
  }
  real s = (m - 1.0) / (m + 1.0), s2 = s * s;
  real series = 0.0;
  for (int n = 12; n >= 1; --n) series = (series + 1.0 / (real)(2 * n + 1)) * s2;
  real ln_m = 2.0 * s + 2.0 * s * series;
  return (real)k * 6.93147180369123816490e-01 + ((real)k * 1.90821492927058770002e-10 + ln_m);
}

// x^e for x >= 0 (the renderer's only use): exp(e ln x), with the exact cases of pow.
RT_DEVICE real PowR(real x, real e) {
  if (e == 0.0 || x == 1.0) return 1.0;
  if (x == 0.0) return e > 0.0 ? 0.0 : INFINITY;
  return ExpR(e * LogR(x));
}

// sin and cos of r in [-pi/4, pi/4] by their Taylor series to r^21 / 21! and r^20 / 20!.
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

// x = k pi/2 + r, pi/2 in three parts of 33 bits each (k * part exact for |k| < 2^20);
// the renderer's angles are within a few turns.
RT_DEVICE real ReducePiHalves(real x, RT_PRIVATE int* quadrant) {
  real k = floor(x * 6.36619772367581382433e-01 + 0.5);
  *quadrant = (int)(k - 4.0 * floor(k * 0.25));
  return ((x - k * 1.57079632673412561417e+00) - k * 6.07710050650619224932e-11) -
         k * 2.02226624879595063154e-21;
}

RT_DEVICE real SinR(real x) {
  int q;
  real r = ReducePiHalves(x, &q);
  return q == 0 ? SinReduced(r) : q == 1 ? CosReduced(r) : q == 2 ? -SinReduced(r) : -CosReduced(r);
}

RT_DEVICE real CosR(real x) {
  int q;
  real r = ReducePiHalves(x, &q);
  return q == 0 ? CosReduced(r) : q == 1 ? -SinReduced(r) : q == 2 ? -CosReduced(r) : SinReduced(r);
}

#endif

#endif  // RT_UTIL_TRANSCENDENTAL_H
