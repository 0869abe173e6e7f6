// The build's box arithmetic in SSE-width vector registers (a box, a primitive, the
// binning of centroids and the bins of the SAH sweep), computing the very bytes the scalar
// Aabb of bvh_build.h does. Internal to the builder (src/bvh/bvh_build.cpp).
#pragma once

#if defined(__SSE__)
#include <xmmintrin.h>
#endif

#include "bvh_build.h"

namespace rt {
namespace bvh_detail {

typedef float Vec4 __attribute__((vector_size(16)));
typedef int Vec4i __attribute__((vector_size(16)));

// std::min and std::max lane by lane, with their choice between equal values (-0, +0), so
// that the vector code computes the very bytes the scalar Aabb does. SSE's min(x, y) is
// x < y ? x : y, one instruction where the generic select takes four.
#if defined(__SSE__)
inline Vec4 vmin(Vec4 a, Vec4 b) { return _mm_min_ps(b, a); }
inline Vec4 vmax(Vec4 a, Vec4 b) { return _mm_max_ps(b, a); }
#else
inline Vec4 vmin(Vec4 a, Vec4 b) { return b < a ? b : a; }
inline Vec4 vmax(Vec4 a, Vec4 b) { return a < b ? b : a; }
#endif

// Aabb in two vector registers; lane 3 is unused.
struct Box4 {
  Vec4 lo = {3.4e38f, 3.4e38f, 3.4e38f, 3.4e38f};
  Vec4 hi = {-3.4e38f, -3.4e38f, -3.4e38f, -3.4e38f};

  void grow(Vec4 l, Vec4 h) {
    lo = vmin(lo, l);
    hi = vmax(hi, h);
  }
  void grow(const Box4& b) { grow(b.lo, b.hi); }
  // The same arithmetic as Aabb::area.
  float area() const {
    if (lo[0] > hi[0]) return 0;
    float dx = hi[0] - lo[0], dy = hi[1] - lo[1], dz = hi[2] - lo[2];
    return 2.0f * (dx * dy + dy * dz + dz * dx);
  }
};

// A primitive's box in vector registers; lane 3 of lo holds the index's bits, of hi nothing.
struct Prim {
  Vec4 lo, hi;
};
static_assert(sizeof(Prim) == sizeof(BvhPrimitive), "Prim mirrors BvhPrimitive");

// Vector loads straight from the record (a memcpy into a Prim went through the stack, a
// store and a reload on the binning loop's critical path); may_alias makes them legal.
typedef float Vec4Alias __attribute__((vector_size(16), may_alias));
inline Prim load(const BvhPrimitive& q) {
  return Prim{*reinterpret_cast<const Vec4Alias*>(q.lo), *reinterpret_cast<const Vec4Alias*>(q.hi)};
}

// A primitive's centroid, rounded as every other centroid of the build.
inline Vec4 centroid(const Prim& p) { return 0.5f * (p.lo + p.hi); }

// The bin of a centroid along each axis: min(bins - 1, int((c - lo) * scale)), clamped in
// float before the conversion (the same integer for every x >= 0, and a valid bin, not
// garbage, for the NaN or negative x of degenerate boxes).
struct Binning {
  Vec4 lo, scale, top;
  Binning(const Box4& cbox, int bins) : lo(cbox.lo) {
    for (int k = 0; k < 4; ++k) {
      float extent = k < 3 ? cbox.hi[k] - cbox.lo[k] : 0;
      scale[k] = extent > 0 ? bins / extent : 0;  // Axes without extent are never split.
      top[k] = static_cast<float>(bins - 1);
    }
  }
  Vec4i bin(Vec4 c) const {
    Vec4 zero = {0, 0, 0, 0};
    return __builtin_convertvector(vmax(zero, vmin(top, (c - lo) * scale)), Vec4i);
  }
};

constexpr int kMaxBins = 256;
// Per-axis bins. Only the first `bins` of each axis are cleared and used: the many small
// nodes near the leaves would otherwise spend their time initialising all kMaxBins.
struct Bins {
  Bins() {}
  union {
    Box4 box[3][kMaxBins];
  };
  int count[3][kMaxBins];
};

}  // namespace bvh_detail
}  // namespace rt
