// Short vectors of RT_BVH_WIDTH lanes for the wide BVH's node test. OpenCL C has them
// built in (float4 / float8); in C++ the GCC/Clang vector extensions give the same
// element-wise operators, comparisons that yield -1 / 0 per lane, and `mask ? a : b`
// selection, which the compiler maps to SSE (or AVX where enabled). The node test is thus
// written once, in operators both languages share, and rounds the same on both devices.
// `Quad` is four float lanes for the triangle test's data movement (QuadPermute: a
// shuffle by lane indices known only at run time, one `vpermilps` with AVX); moving
// values never rounds them.
#ifndef RT_SIMD_H
#define RT_SIMD_H

#include "../compat.h"

// Children per BVH node. The CPU reference is compiled for 4, whose node test fits GCC's
// 128-bit lanes; the host picks the width per device (RenderDevice::bvh_width: 8 for PoCL
// on a CPU, whose compiler vectorizes the wider node test to 256 bits) and passes it to
// the kernel's build.
#ifndef RT_BVH_WIDTH
#define RT_BVH_WIDTH 4
#endif

#ifdef __OPENCL_C_VERSION__

#if RT_BVH_WIDTH == 4
typedef float4 LaneFloat;
typedef int4 LaneInt;
#define LaneStoreF(v, p) vstore4((v), 0, (p))
#define LaneStoreI(v, p) vstore4((v), 0, (p))
#else
typedef float8 LaneFloat;
typedef int8 LaneInt;
#define LaneStoreF(v, p) vstore8((v), 0, (p))
#define LaneStoreI(v, p) vstore8((v), 0, (p))
#endif
#define RT_ALIGN_NODE __attribute__((aligned(64)))
typedef float4 Quad;
typedef uint4 QuadIndex;
#define QuadFrom3(v) ((float4)((v), 0.0f))
#define QuadPermute(v, index) shuffle((v), (index))
#define QuadIndexOf(a, b, c, d) ((uint4)((uint)(a), (uint)(b), (uint)(c), (uint)(d)))
#define QuadLane(v, i) ((v).s##i)
// Bit i set where lane i of a comparison's mask (-1 / 0 per lane) is set. On an x86 device
// (PoCL) the lanes' sign bits are one instruction (movmskps, or a mask register's move
// with AVX-512); LLVM compiles the portable form below to a masked load, three shuffles
// and ors and a move, which sat between the triangle block's test and its branch.
#if defined(__SSE__) && RT_BVH_WIDTH == 4
RT_DEVICE int LaneBits(int4 m) { return __builtin_ia32_movmskps(as_float4(m)); }
#elif defined(__AVX__) && RT_BVH_WIDTH == 8
RT_DEVICE int LaneBits(int8 m) { return __builtin_ia32_movmskps256(as_float8(m)); }
#elif RT_BVH_WIDTH == 4
RT_DEVICE int LaneBits(int4 m) {
  int4 b = m & (int4)(1, 2, 4, 8);
  return (b.s0 | b.s1) | (b.s2 | b.s3);
}
#else
RT_DEVICE int LaneBits(int8 m) {
  int8 b = m & (int8)(1, 2, 4, 8, 16, 32, 64, 128);
  int4 h = b.lo | b.hi;
  return (h.s0 | h.s1) | (h.s2 | h.s3);
}
#endif
// The lowest lane whose bit is set in a non-zero LaneBits value.
RT_DEVICE int LowestLane(int bits) { return 31 - clz(bits & -bits); }

#else  // C++17

#include <cstring>
#if defined(__SSE__)
#include <immintrin.h>
#endif

typedef float LaneFloat __attribute__((vector_size(4 * RT_BVH_WIDTH)));
typedef int LaneInt __attribute__((vector_size(4 * RT_BVH_WIDTH)));
inline void LaneStoreF(LaneFloat v, float* p) { std::memcpy(p, &v, sizeof v); }
inline void LaneStoreI(LaneInt v, int* p) { std::memcpy(p, &v, sizeof v); }
// Whole nodes on cache lines; OpenCL buffers are aligned at least as well.
#define RT_ALIGN_NODE alignas(64)

typedef float Quad __attribute__((vector_size(16)));
typedef int QuadIndex __attribute__((vector_size(16)));
// A float3 is laid out as four floats (cl/compat.h); the fourth lane is never read.
inline Quad QuadFrom3(float3 v) {
  Quad q;
  std::memcpy(&q, &v, sizeof q);
  return q;
}
#ifdef __clang__  // Clang has no run-time-index shuffle builtin; lanes read by index instead.
inline Quad QuadPermute(Quad v, QuadIndex index) {
  return Quad{v[index[0]], v[index[1]], v[index[2]], v[index[3]]};
}
#else
#define QuadPermute(v, index) __builtin_shuffle((v), (index))
#endif
inline QuadIndex QuadIndexOf(int a, int b, int c, int d) { return QuadIndex{a, b, c, d}; }
#define QuadLane(v, i) ((v)[i])

inline int LaneBits(LaneInt m) {
#if defined(__AVX__) && RT_BVH_WIDTH == 8
  return _mm256_movemask_ps(reinterpret_cast<__m256>(m));
#elif defined(__SSE__) && RT_BVH_WIDTH == 4
  return _mm_movemask_ps(reinterpret_cast<__m128>(m));
#else
  int bits = 0;
  for (int i = 0; i < RT_BVH_WIDTH; ++i) bits |= (m[i] != 0) << i;
  return bits;
#endif
}
inline int LowestLane(int bits) { return __builtin_ctz(static_cast<unsigned>(bits)); }

#endif

#endif  // RT_SIMD_H
