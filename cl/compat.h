// Qualifier macros and vector types that let the same headers compile as OpenCL C 1.2
// (the kernel) and as C++17 (the CPU reference). Everything below this file is written
// in the common subset: no recursion, no templates, no references, explicit address
// spaces through RT_GLOBAL / RT_PRIVATE.
#ifndef RT_COMPAT_H
#define RT_COMPAT_H

#ifdef __OPENCL_C_VERSION__

#define RT_DEVICE static inline
// Inlined whatever the compiler's size heuristics say (see the C++ definition). PoCL's
// compiler kept the camera's stratified sample out of line, a call on every sample.
#define RT_DEVICE_INLINE static inline __attribute__((always_inline))
// Inlined in the kernel only, where PoCL's inliner left a function out of line at a cost;
// the CPU reference keeps GCC's own choice (its kernel is at GCC's inlining limits, and
// forcing more into it moves other functions out).
#define RT_KERNEL_INLINE static inline __attribute__((always_inline))
// Unrolls the loop it precedes in the kernel only. PoCL's compiler keeps a short loop over
// a node's lanes as a loop, with its arrays in memory; GCC unrolls it on its own.
#define RT_KERNEL_UNROLL _Pragma("unroll")
// A call of its own in the kernel on a CPU device (RT_CL_CPU_DEVICE, set by the host: PoCL),
// whose compiler then optimizes the function apart from the large kernel function. A GPU's
// compiler keeps its own choice (OpenCL compilers for GPUs inline nearly everything).
#ifdef RT_CL_CPU_DEVICE
#define RT_KERNEL_NOINLINE static __attribute__((noinline))
#else
#define RT_KERNEL_NOINLINE static inline
#endif
// 1 where code takes its GPU form: in the kernel on any device but a CPU (the host sets
// RT_CL_CPU_DEVICE on CPU devices, whose compilers and caches favour the CPU reference's
// forms). A GPU keeps a work-item's private arrays and values in registers and scratch, so
// its forms hold fewer of them at once.
#ifdef RT_CL_CPU_DEVICE
#define RT_GPU_FORMS 0
#else
#define RT_GPU_FORMS 1
#endif
#define RT_GLOBAL __global
#define RT_PRIVATE __private
#define make_float3(x, y, z) ((float3)((x), (y), (z)))
#define make_float2(x, y) ((float2)((x), (y)))
// The CPU reference rounds every operation; contraction into FMA would make the two
// devices disagree in the last bit, so it is off here too.
#pragma OPENCL FP_CONTRACT OFF
// OpenCL C has no way to report a failed check; the CPU reference's debug build does.
#define RT_ASSERT(cond) ((void)0)

#else  // C++17

#include <cassert>
#include <cmath>
#include <cstdint>
#include <cstring>

// Live in CPU debug builds (the tests' and developers' build), empty in release builds
// (NDEBUG) and in the kernel, so a check costs nothing where speed matters.
#define RT_ASSERT(cond) assert(cond)

#define RT_DEVICE inline
// Inlined whatever the compiler's size heuristics say: the camera sample's path from its
// ray to the traversal call (cl/integrator/pixel.h). As calls, each step handed the ray and the
// sample on through stack copies of mismatched widths, and every such reload stalled on
// store-to-load forwarding.
#define RT_DEVICE_INLINE inline __attribute__((always_inline))
// A plain inline function on the CPU (see the OpenCL definition).
#define RT_KERNEL_INLINE inline
#define RT_KERNEL_UNROLL
#define RT_KERNEL_NOINLINE inline
#define RT_GPU_FORMS 0
#define RT_GLOBAL
#define RT_PRIVATE

typedef std::uint32_t uint;

// OpenCL's as_float: the float whose bits are u (HDR texels are stored as such bits).
inline float as_float(uint u) {
  float f;
  std::memcpy(&f, &u, sizeof f);
  return f;
}

// Same size and alignment as OpenCL's float3 (16 bytes), so buffers match byte for byte.
struct alignas(16) float3 {
  float x, y, z, w_pad;
};
struct alignas(16) float4 {
  float x, y, z, w;
};
struct alignas(8) float2 {
  float x, y;
};

inline float3 make_float3(float x, float y, float z) { return float3{x, y, z, 0.0f}; }
inline float2 make_float2(float x, float y) { return float2{x, y}; }

// The double vectors of `--precision double` (cl/util/real.h). They live in private
// memory only, never in a buffer, so they carry no padding.
struct double3 {
  double x, y, z;
};
struct double2 {
  double x, y;
};
inline double3 make_double3(double x, double y, double z) { return double3{x, y, z}; }
inline double2 make_double2(double x, double y) { return double2{x, y}; }

// The component-wise operators OpenCL C has built in, for one 3-vector type V of scalar S.
#define RT_VEC3_OPERATORS(V, S, MAKE)                                            \
  inline V operator+(V a, V b) { return MAKE(a.x + b.x, a.y + b.y, a.z + b.z); } \
  inline V operator-(V a, V b) { return MAKE(a.x - b.x, a.y - b.y, a.z - b.z); } \
  inline V operator*(V a, V b) { return MAKE(a.x * b.x, a.y * b.y, a.z * b.z); } \
  inline V operator/(V a, V b) { return MAKE(a.x / b.x, a.y / b.y, a.z / b.z); } \
  inline V operator*(V a, S s) { return MAKE(a.x * s, a.y * s, a.z * s); }       \
  inline V operator*(S s, V a) { return MAKE(a.x * s, a.y * s, a.z * s); }       \
  inline V operator/(V a, S s) { return MAKE(a.x / s, a.y / s, a.z / s); }       \
  inline V operator-(V a) { return MAKE(-a.x, -a.y, -a.z); }                     \
  inline V& operator+=(V& a, V b) { return a = a + b; }                          \
  inline V& operator*=(V& a, V b) { return a = a * b; }
RT_VEC3_OPERATORS(float3, float, make_float3)
RT_VEC3_OPERATORS(double3, double, make_double3)
#undef RT_VEC3_OPERATORS

// Scalar maths under the names OpenCL C gives them. Vector helpers (dot, cross,
// normalize) live in util/math.h and are written out by hand for both devices, because
// OpenCL's built-in versions may round differently from any C++ formula.
using std::cos;
using std::exp;
using std::fabs;
using std::floor;
using std::fmax;
using std::fmin;
using std::isfinite;
using std::pow;
using std::sin;
using std::sqrt;
using std::tan;

#endif

#endif  // RT_COMPAT_H
