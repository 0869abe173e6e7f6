// The scalar type of the computation, `real`, and its vectors `real2`, `real3`: float by
// default, double when the program is built with RT_REAL_DOUBLE (`--precision double`).
// Only computation is written over `real`; the scene's arrays and the per-pixel outputs
// keep their float layouts (cl/scene_types.h, cl/film/film_types.h), so memory, uploads and the
// layout check do not depend on the precision. A value read from an array enters the
// computation through ToReal3 and a result leaves it through ToFloat3; both are the
// identity in float, and in double they round to nearest on both devices.
//
// The CPU reference compiles the computation headers twice, once per precision, each time
// inside its own namespace (src/device/cpu_kernel_*.cpp); this header is therefore the one
// place that decides what `real` is.
#ifndef RT_UTIL_REAL_H
#define RT_UTIL_REAL_H

#include "../compat.h"

#ifdef RT_REAL_DOUBLE

#ifdef __OPENCL_C_VERSION__
#pragma OPENCL EXTENSION cl_khr_fp64 : enable
typedef double real;
typedef double2 real2;
typedef double3 real3;
#define make_real3(x, y, z) ((double3)((x), (y), (z)))
#define make_real2(x, y) ((double2)((x), (y)))
#define ToReal3(v) convert_double3(v)
#define ToReal2(v) convert_double2(v)
#define ToFloat3(v) convert_float3(v)
#else
typedef double real;
typedef double2 real2;
typedef double3 real3;
inline real3 make_real3(real x, real y, real z) { return make_double3(x, y, z); }
inline real2 make_real2(real x, real y) { return make_double2(x, y); }
inline real3 ToReal3(float3 v) { return make_double3(v.x, v.y, v.z); }
inline real2 ToReal2(float2 v) { return make_double2(v.x, v.y); }
inline float3 ToFloat3(real3 v) {
  return make_float3(static_cast<float>(v.x), static_cast<float>(v.y), static_cast<float>(v.z));
}
#endif
// A literal of type real: RT_R(0.5) is 0.5 here and 0.5f in float.
#define RT_R(x) x

#else  // float

typedef float real;
typedef float2 real2;
typedef float3 real3;
#define make_real3 make_float3
#define make_real2 make_float2
#define ToReal3(v) (v)
#define ToReal2(v) (v)
#define ToFloat3(v) (v)
#define RT_R(x) x##f

#endif

#endif  // RT_UTIL_REAL_H
