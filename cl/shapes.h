// Ray-shape intersection: the watertight ray-triangle test and a numerically careful
// unit-sphere test (spheres and ellipsoids are unit spheres seen through a transform).
#ifndef RT_SHAPES_H
#define RT_SHAPES_H

#include "ray.h"
#include "scene_types.h"
#include "util/lanes.h"

// Per-ray constants of the watertight test (Woop, Benthin and Wald 2013): the ray is
// sheared so it runs along +z, which makes the edge functions exact in sign.
typedef struct TriangleRay {
  real3 origin;
  int kx, ky, kz;
  real sx, sy, sz;
  real ox, oy, oz;  // The origin's coordinates kx, ky and kz, for the lane test.
} TriangleRay;

RT_DEVICE TriangleRay MakeTriangleRay(real3 origin, real3 dir) {
  TriangleRay tr;
  tr.origin = origin;
  tr.kz = MaxDimension(Abs3(dir));
  tr.kx = tr.kz == 2 ? 0 : tr.kz + 1;
  tr.ky = tr.kx == 2 ? 0 : tr.kx + 1;
  // Swapping keeps the winding, so the sign of det still tells front from back.
  if (Component(dir, tr.kz) < 0.0f) {
    int k = tr.kx;
    tr.kx = tr.ky;
    tr.ky = k;
  }
  real dz = Component(dir, tr.kz);
  tr.sx = Component(dir, tr.kx) / dz;
  tr.sy = Component(dir, tr.ky) / dz;
  tr.sz = 1.0f / dz;
  tr.ox = Component(origin, tr.kx);
  tr.oy = Component(origin, tr.ky);
  tr.oz = Component(origin, tr.kz);
  return tr;
}

// The part of the watertight test that depends on tmax, from the edge functions v, w,
// the sum det of all three and the scaled distance: returns 1 and sets *t, *b1, *b2 when the hit
// lies in 0 < t < tmax. A smaller tmax never accepts what a larger one rejects.
RT_DEVICE int FinishTriangle(real v, real w, real det, real tscaled, real tmax, RT_PRIVATE real* t,
                             RT_PRIVATE real* b1, RT_PRIVATE real* b2) {
  if (det < 0.0f && (tscaled >= 0.0f || tscaled < tmax * det)) return 0;
  if (det > 0.0f && (tscaled <= 0.0f || tscaled > tmax * det)) return 0;
  real inv_det = 1.0f / det;
  *t = tscaled * inv_det;
  *b1 = v * inv_det;
  *b2 = w * inv_det;
  return *t > 0.0f && *t < tmax;
}

// Returns 1 and sets *t, *b1, *b2 when the ray hits the triangle with 0 < t < tmax.
// Edge functions that are exactly zero count as inside for both triangles sharing the
// edge, so a ray through a shared edge or vertex never slips through a closed mesh.
// Back faces (det < 0: the ray sees the vertices clockwise) are skipped when cull is set.
RT_DEVICE int IntersectTriangle(RT_PRIVATE const TriangleRay* tr, real3 p0, real3 p1, real3 p2,
                                real tmax, int cull, RT_PRIVATE real* t, RT_PRIVATE real* b1,
                                RT_PRIVATE real* b2) {
  real3 a = Permute3(p0 - tr->origin, tr->kx, tr->ky, tr->kz);
  real3 b = Permute3(p1 - tr->origin, tr->kx, tr->ky, tr->kz);
  real3 c = Permute3(p2 - tr->origin, tr->kx, tr->ky, tr->kz);
  real ax = a.x - tr->sx * a.z, ay = a.y - tr->sy * a.z;
  real bx = b.x - tr->sx * b.z, by = b.y - tr->sy * b.z;
  real cx = c.x - tr->sx * c.z, cy = c.y - tr->sy * c.z;
  real u = cx * by - cy * bx;
  real v = ax * cy - ay * cx;
  real w = bx * ay - by * ax;
  if ((u < 0.0f || v < 0.0f || w < 0.0f) && (u > 0.0f || v > 0.0f || w > 0.0f)) return 0;
  real det = u + v + w;
  if (det == 0.0f || (cull && det < 0.0f)) return 0;
  real az = tr->sz * a.z, bz = tr->sz * b.z, cz = tr->sz * c.z;
  real tscaled = u * az + v * bz + w * cz;
  return FinishTriangle(v, w, det, tscaled, tmax, t, b1, b2);
}

// IntersectTriangle's edge functions and scaled distances of RT_BVH_WIDTH triangles at once,
// lane i for tris[i] (tris[0] for lanes at or past `count`, which are masked off). Every
// lane performs the scalar test's operations in its order, so it rounds exactly as the
// scalar test would. The coordinates are gathered already permuted (kx, ky, kz pick the
// floats), and the tests that do not shrink with tmax run here; the returned mask has
// the lanes still in the running, which FinishTriangle settles one by one in lane order
// (as the scalar loop would, each against the tmax its predecessors left).
typedef struct TriangleLanes {
  LaneReal v, w, det, tscaled;
} TriangleLanes;

// Coordinate c (vertex * 4 + axis) of each lane's triangle, less the origin's coordinate.
RT_DEVICE LaneReal GatherTriangleLanes(RT_GLOBAL const float* const* lane, int c, real origin_c) {
#define RT_TRIANGLE_LANE(i) lane[i][c]
  return LaneToReal(LaneFloatOf(RT_TRIANGLE_LANE)) - LaneSplat(origin_c);
#undef RT_TRIANGLE_LANE
}

RT_DEVICE LaneInt IntersectTriangleLanes(RT_PRIVATE const TriangleRay* tr,
                                         RT_GLOBAL const Triangle* tris, int count, real tmax,
                                         int cull, RT_PRIVATE TriangleLanes* out) {
  // Each lane's triangle as floats (a Triangle is three float3, 12 floats).
  RT_GLOBAL const float* f[RT_BVH_WIDTH];
  for (int i = 0; i < RT_BVH_WIDTH; ++i) f[i] = (RT_GLOBAL const float*)&tris[i < count ? i : 0];
  LaneReal ax = GatherTriangleLanes(f, tr->kx, tr->ox);
  LaneReal ay = GatherTriangleLanes(f, tr->ky, tr->oy);
  LaneReal az_ = GatherTriangleLanes(f, tr->kz, tr->oz);
  LaneReal bx = GatherTriangleLanes(f, 4 + tr->kx, tr->ox);
  LaneReal by = GatherTriangleLanes(f, 4 + tr->ky, tr->oy);
  LaneReal bz_ = GatherTriangleLanes(f, 4 + tr->kz, tr->oz);
  LaneReal cx = GatherTriangleLanes(f, 8 + tr->kx, tr->ox);
  LaneReal cy = GatherTriangleLanes(f, 8 + tr->ky, tr->oy);
  LaneReal cz_ = GatherTriangleLanes(f, 8 + tr->kz, tr->oz);
  LaneReal sx = LaneSplat(tr->sx), sy = LaneSplat(tr->sy), sz = LaneSplat(tr->sz);
  ax = ax - sx * az_;
  ay = ay - sy * az_;
  bx = bx - sx * bz_;
  by = by - sy * bz_;
  cx = cx - sx * cz_;
  cy = cy - sy * cz_;
  LaneReal u = cx * by - cy * bx;
  LaneReal v = ax * cy - ay * cx;
  LaneReal w = bx * ay - by * ax;
  LaneReal zero = LaneSplat(0.0f);
  LaneMask out_of_edges =
      ((u < zero) | (v < zero) | (w < zero)) & ((u > zero) | (v > zero) | (w > zero));
  LaneReal det = u + v + w;
  LaneMask rejected = out_of_edges | (det == zero);
  if (cull) rejected = rejected | (det < zero);
  LaneReal tscaled = u * (sz * az_) + v * (sz * bz_) + w * (sz * cz_);
  LaneReal tmax_det = LaneSplat(tmax) * det;
  rejected = rejected | ((det < zero) & ((tscaled >= zero) | (tscaled < tmax_det)));
  rejected = rejected | ((det > zero) & ((tscaled <= zero) | (tscaled > tmax_det)));
  out->v = v;
  out->w = w;
  out->det = det;
  out->tscaled = tscaled;
#define RT_LANE_INDEX(i) (i)
  LaneInt lane = LaneIntOf(RT_LANE_INDEX);
#undef RT_LANE_INDEX
  return LaneMaskToInt(~rejected) & (lane < count);
}

// Intersects the unit sphere at the origin. The discriminant is formed from the squared
// distance between the centre and the ray's line (Haines et al., Ray Tracing Gems
// ch. 7), which avoids the cancellation of b^2 - 4ac for distant or large spheres.
RT_DEVICE int IntersectUnitSphere(real3 o, real3 d, real tmax, RT_PRIVATE real* t) {
  real a = Dot(d, d);
  real tc = -Dot(o, d) / a;
  real3 l = o + d * tc;
  real disc = (1.0f - Dot(l, l)) / a;
  if (disc < 0.0f) return 0;
  real root = sqrt(disc);
  // The root farther from tc is exact; the other follows from the product of the roots.
  real q = tc >= 0.0f ? tc + root : tc - root;
  real c = (Dot(o, o) - 1.0f) / a;
  real t0 = q, t1 = q != 0.0f ? c / q : 0.0f;
  real tnear = fmin(t0, t1), tfar = fmax(t0, t1);
  if (tnear > 0.0f && tnear < tmax) {
    *t = tnear;
    return 1;
  }
  if (tfar > 0.0f && tfar < tmax) {
    *t = tfar;
    return 1;
  }
  return 0;
}

#endif  // RT_SHAPES_H
