// Vector helpers shared by both devices. They are spelled out component by component so
// that the CPU reference and the kernel evaluate the same rounded operations in the same
// order (FP contraction is off on both sides).
#ifndef RT_UTIL_MATH_H
#define RT_UTIL_MATH_H

#include "real.h"
#include "transcendental.h"

#define RT_INFINITY 3.402823466e+38f

// Plain comparisons rather than fmin/fmax: they compile to single min/max instructions on
// every device (fmin's NaN rules cost a library call on the CPU), and both devices pick
// the same operand when one is NaN.
RT_DEVICE real MinF(real a, real b) { return a < b ? a : b; }
RT_DEVICE real MaxF(real a, real b) { return a > b ? a : b; }

RT_DEVICE real Dot(real3 a, real3 b) { return a.x * b.x + a.y * b.y + a.z * b.z; }

RT_DEVICE real3 Cross(real3 a, real3 b) {
  return make_real3(a.y * b.z - a.z * b.y, a.z * b.x - a.x * b.z, a.x * b.y - a.y * b.x);
}

RT_DEVICE real Length(real3 a) { return sqrt(Dot(a, a)); }

RT_DEVICE real3 Normalize(real3 a) { return a * (1.0f / Length(a)); }

RT_DEVICE real3 Vec3(real s) { return make_real3(s, s, s); }

// MaxF, not fmax: the same value for every input without NaN (fmax's NaN rule is a library
// call on the CPU, ten of them per camera sample before this changed).
RT_DEVICE real MaxComponent(real3 a) { return MaxF(a.x, MaxF(a.y, a.z)); }

RT_DEVICE real Component(real3 a, int axis) { return axis == 0 ? a.x : (axis == 1 ? a.y : a.z); }

RT_DEVICE real3 Abs3(real3 a) { return make_real3(fabs(a.x), fabs(a.y), fabs(a.z)); }

RT_DEVICE int MaxDimension(real3 a) {
  return (a.x > a.y) ? (a.x > a.z ? 0 : 2) : (a.y > a.z ? 1 : 2);
}

RT_DEVICE real3 Permute3(real3 a, int x, int y, int z) {
  return make_real3(Component(a, x), Component(a, y), Component(a, z));
}

// x^e. Whole exponents (the course's Phong exponents all are) use square-and-multiply:
// exact-order multiplications that every device rounds alike, and far cheaper than pow,
// which PoCL evaluates through a precise log and exp.
RT_DEVICE real PowF(real x, real e) {
  if (e >= 0.0f && e <= 65536.0f && e == floor(e)) {
    uint n = (uint)e;
    real result = 1.0f, base = x;
    while (n != 0u) {
      if ((n & 1u) != 0u) result *= base;
      base *= base;
      n >>= 1;
    }
    return result;
  }
  return PowR(x, e);
}

// A right-handed orthonormal basis around a unit vector n (Duff et al. 2017), used for
// glossy lobes; it has no branch that could flip between devices.
RT_DEVICE void CoordinateSystem(real3 n, RT_PRIVATE real3* u, RT_PRIVATE real3* v) {
  real sign = n.z >= 0.0f ? 1.0f : -1.0f;
  real a = -1.0f / (sign + n.z);
  real b = n.x * n.y * a;
  *u = make_real3(1.0f + sign * n.x * n.x * a, sign * b, -sign * n.x);
  *v = make_real3(b, sign + n.y * n.y * a, -n.y);
}

// The unit direction at polar angle theta from unit `axis` (given as its sine and cosine)
// and azimuth 2 pi u_phi, around the basis above: the last step of every sampling of a
// cone, lobe or hemisphere (pbrt's SphericalDirection in the axis's frame).
RT_DEVICE real3 SphericalDirection(real3 axis, real sin_theta, real cos_theta, real u_phi) {
  real sin_phi, cos_phi;
  SinCos2Pi(u_phi, &sin_phi, &cos_phi);
  real3 s, t;
  CoordinateSystem(axis, &s, &t);
  return s * (sin_theta * cos_phi) + t * (sin_theta * sin_phi) + axis * cos_theta;
}

RT_DEVICE real3 Reflect(real3 wo, real3 n) { return n * (2.0f * Dot(wo, n)) - wo; }

#endif  // RT_UTIL_MATH_H
