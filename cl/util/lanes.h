// The wide BVH's node test in the computation's precision (cl/util/real.h). Nodes store
// their boxes as float lanes (cl/bvh/simd.h); the test widens them to `LaneReal`, so in double
// the slabs are met by the unrounded double ray and the box test stays as conservative as
// the float test is in float (a rounded copy of the ray could miss a box that the double
// triangle test then finds a hit in).
#ifndef RT_UTIL_LANES_H
#define RT_UTIL_LANES_H

#include "../bvh/simd.h"
#include "real.h"

#ifndef RT_REAL_DOUBLE
typedef LaneFloat LaneReal;
typedef LaneInt LaneRealMask;  // What a comparison of LaneReal yields: -1 / 0 per lane.
#define LaneToReal(v) (v)
#define LaneStoreR(v, p) LaneStoreF((v), (p))
#define LaneMaskToInt(m) (m)
#elif defined(__OPENCL_C_VERSION__)
#if RT_BVH_WIDTH == 4
typedef double4 LaneReal;
typedef long4 LaneRealMask;
#define LaneToReal(v) convert_double4(v)
#define LaneStoreR(v, p) vstore4((v), 0, (p))
#define LaneMaskToInt(m) convert_int4(m)
#else
typedef double8 LaneReal;
typedef long8 LaneRealMask;
#define LaneToReal(v) convert_double8(v)
#define LaneStoreR(v, p) vstore8((v), 0, (p))
#define LaneMaskToInt(m) convert_int8(m)
#endif
#else  // C++17, double
// The lanes are passed by value between inline functions of one translation unit, so the
// note that 32-byte vectors pass differently with and without AVX concerns no call here.
#pragma GCC diagnostic ignored "-Wpsabi"
typedef double LaneReal __attribute__((vector_size(8 * RT_BVH_WIDTH)));
typedef decltype(LaneReal{} < LaneReal{}) LaneRealMask;
#define LaneToReal(v) __builtin_convertvector((v), LaneReal)
inline void LaneStoreR(LaneReal v, double* p) { std::memcpy(p, &v, sizeof v); }
// A comparison of double lanes yields 64-bit lanes of -1 / 0.
#define LaneMaskToInt(m) __builtin_convertvector((m), LaneInt)
#endif

// Per-lane minimum and maximum with the scalar MinF / MaxF rule (the second operand
// when either is NaN), so a lane computes exactly what the scalar test would.
RT_DEVICE LaneReal LaneMin(LaneReal a, LaneReal b) { return a < b ? a : b; }
RT_DEVICE LaneReal LaneMax(LaneReal a, LaneReal b) { return a > b ? a : b; }

RT_DEVICE LaneReal LaneSplat(real x) {
#ifdef __OPENCL_C_VERSION__
  return (LaneReal)(x);
#else
  return x - LaneReal{};  // Broadcasts x; x - (+0) is x for every x, -0 included.
#endif
}

// A ray's value that every lane of a node or triangle-block test reads, kept by the node
// and triangle rays. On a GPU a vector takes a register per lane for as long as it lives,
// so the value is kept once and broadcast where a test reads it; elsewhere it is kept
// broadcast, in one SIMD register, so no test broadcasts it again. The lanes hold the same
// value either way.
#if RT_GPU_FORMS
typedef real RayLane;
#define RayLaneOf(x) (x)
#define RayLaneRead(v) LaneSplat(v)
#else
typedef LaneReal RayLane;
#define RayLaneOf(x) LaneSplat(x)
#define RayLaneRead(v) (v)
#endif

#endif  // RT_UTIL_LANES_H
