// Ray-shape intersection: the watertight ray-triangle test and a numerically careful
// unit-sphere test (spheres and ellipsoids are unit spheres seen through a transform).
#ifndef RT_SHAPES_H
#define RT_SHAPES_H

#include "ray.h"
#include "../scene_types.h"
#include "../util/lanes.h"

// Per-ray constants of the watertight test (Woop, Benthin and Wald 2013): the ray is
// sheared so it runs along +z, which makes the edge functions exact in sign.
typedef struct TriangleRay {
  real3 origin;
  int kx, ky, kz;
  real sx, sy, sz;
#ifndef RT_REAL_DOUBLE
  Quad origin_quad;  // The origin and (kx, ky, kz) as vector lanes for TrianglePoint.
  QuadIndex axes;
#endif
  // The permuted origin and the shear broadcast to every lane, for IntersectTriangleBlock,
  // and kx, ky, kz as byte offsets into a block's vertex lanes (RT_BLOCK_LANES).
  RayLane lane_ox, lane_oy, lane_oz, lane_sx, lane_sy, lane_sz;
  uint off_x, off_y, off_z;
} TriangleRay;

// Axis a of vertex k of a block's triangles (TriangleBlock.v[3 * k + a]), `offset` being
// a's byte offset (TriangleRay.off_x and the others).
#define RT_BLOCK_LANES(block, k, offset) \
  LaneToReal(                            \
      *(RT_GLOBAL const LaneFloat*)((RT_GLOBAL const char*)((block)->v + 3 * (k)) + (offset)))

// Sets the origin alone: what depends on the direction (the axes and the shear) is kept, so
// rays that share a direction and differ in origin share those divisions.
RT_DEVICE void SetTriangleRayOrigin(RT_PRIVATE TriangleRay* tr, real3 origin) {
  tr->origin = origin;
#ifndef RT_REAL_DOUBLE
  tr->origin_quad = QuadFrom3(origin);
#endif
  tr->lane_ox = RayLaneOf(Component(origin, tr->kx));
  tr->lane_oy = RayLaneOf(Component(origin, tr->ky));
  tr->lane_oz = RayLaneOf(Component(origin, tr->kz));
}

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
#ifndef RT_REAL_DOUBLE
  tr.axes = QuadIndexOf(tr.kx, tr.ky, tr.kz, 3);
#endif
  tr.off_x = (uint)tr.kx * (uint)sizeof(LaneFloat);
  tr.off_y = (uint)tr.ky * (uint)sizeof(LaneFloat);
  tr.off_z = (uint)tr.kz * (uint)sizeof(LaneFloat);
  tr.lane_sx = RayLaneOf(tr.sx);
  tr.lane_sy = RayLaneOf(tr.sy);
  tr.lane_sz = RayLaneOf(tr.sz);
  SetTriangleRayOrigin(&tr, origin);
  return tr;
}

// A vertex relative to the ray's origin, its axes permuted to (kx, ky, kz). In float the
// subtraction and the permutation are vector operations, lane by lane the same roundings
// as the scalar form used in double (where the vertex is widened first).
RT_DEVICE real3 TrianglePoint(RT_PRIVATE const TriangleRay* tr, real3 p) {
#ifdef RT_REAL_DOUBLE
  return Permute3(p - tr->origin, tr->kx, tr->ky, tr->kz);
#else
  Quad q = QuadPermute(QuadFrom3(p) - tr->origin_quad, tr->axes);
  return make_real3(QuadLane(q, 0), QuadLane(q, 1), QuadLane(q, 2));
#endif
}

// Returns 1 and sets *t, *b1, *b2 when the ray hits the triangle with 0 < t < tmax.
// Edge functions that are exactly zero count as inside for both triangles sharing the
// edge, so a ray through a shared edge or vertex never slips through a closed mesh.
// Back faces (det < 0: the ray sees the vertices clockwise) are skipped when cull is set.
RT_DEVICE int IntersectTriangle(RT_PRIVATE const TriangleRay* tr, real3 p0, real3 p1, real3 p2,
                                real tmax, int cull, RT_PRIVATE real* t, RT_PRIVATE real* b1,
                                RT_PRIVATE real* b2) {
  real3 a = TrianglePoint(tr, p0);
  real3 b = TrianglePoint(tr, p1);
  real3 c = TrianglePoint(tr, p2);
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
  // Only the sign is checked before the division: a test of tscaled against tmax * det
  // rounds differently from t against tmax, and could refuse a t just below tmax.
  if (det < 0.0f ? tscaled >= 0.0f : tscaled <= 0.0f) return 0;
  real inv_det = 1.0f / det;
  *t = tscaled * inv_det;
  *b1 = v * inv_det;
  *b2 = w * inv_det;
  return *t > 0.0f && *t < tmax;
}

// IntersectTriangle on the RT_BVH_WIDTH triangles of a block at once, lane by lane the same
// operations in the same order, so every lane rounds as the scalar test does. Returns the
// lane of least t among the hits (the first of equal ones), or -1 for none, and sets *t,
// *b1, *b2. A hit has 0 < t < tmax, or t <= tmax for a closest-hit query (!any_hit): a
// triangle at exactly the distance of the hit found so far is a tie, which the traversal
// settles by index (ClosestHitWins in cl/bvh/bvh.h), so that the closest hit does not depend on
// the order triangles are tested in. With any_hit the first lane hit is returned.
#if RT_GPU_FORMS
// On a GPU, a lane at a time: a block's vectors would take four registers for each of the
// test's values, and its arrays (the best lane's t and barycentrics) would be indexed
// registers. Each lane computes what its lane of the vector form computes, and the best
// lane is chosen by the same rule.
#define RT_BLOCK_LANE(block, k, offset, i) \
  ((real)((RT_GLOBAL const float*)((RT_GLOBAL const char*)((block)->v + 3 * (k)) + (offset)))[i])
RT_DEVICE int IntersectTriangleBlock(RT_GLOBAL const TriangleBlock* block,
                                     RT_PRIVATE const TriangleRay* tr, real tmax, int cull,
                                     int any_hit, RT_PRIVATE real* t, RT_PRIVATE real* b1,
                                     RT_PRIVATE real* b2) {
  int best = -1;
  real best_t = 0.0f, best_v = 0.0f, best_w = 0.0f, best_inv = 0.0f;
  for (int i = 0; i < RT_BVH_WIDTH; ++i) {
    real az = RT_BLOCK_LANE(block, 0, tr->off_z, i) - tr->lane_oz;
    real bz = RT_BLOCK_LANE(block, 1, tr->off_z, i) - tr->lane_oz;
    real cz = RT_BLOCK_LANE(block, 2, tr->off_z, i) - tr->lane_oz;
    real ax = (RT_BLOCK_LANE(block, 0, tr->off_x, i) - tr->lane_ox) - tr->lane_sx * az;
    real ay = (RT_BLOCK_LANE(block, 0, tr->off_y, i) - tr->lane_oy) - tr->lane_sy * az;
    real bx = (RT_BLOCK_LANE(block, 1, tr->off_x, i) - tr->lane_ox) - tr->lane_sx * bz;
    real by = (RT_BLOCK_LANE(block, 1, tr->off_y, i) - tr->lane_oy) - tr->lane_sy * bz;
    real cx = (RT_BLOCK_LANE(block, 2, tr->off_x, i) - tr->lane_ox) - tr->lane_sx * cz;
    real cy = (RT_BLOCK_LANE(block, 2, tr->off_y, i) - tr->lane_oy) - tr->lane_sy * cz;
    real u = cx * by - cy * bx;
    real vv = ax * cy - ay * cx;
    real w = bx * ay - by * ax;
    int miss = ((u < 0.0f) | (vv < 0.0f) | (w < 0.0f)) & ((u > 0.0f) | (vv > 0.0f) | (w > 0.0f));
    real det = u + vv + w;
    miss |= det == 0.0f;
    if (cull) miss |= det < 0.0f;
    if (miss) continue;
    real tscaled = u * (tr->lane_sz * az) + vv * (tr->lane_sz * bz) + w * (tr->lane_sz * cz);
    real inv_det = 1.0f / det;
    real lane_t = tscaled * inv_det;
    int in_range = any_hit ? lane_t < tmax : lane_t <= tmax;
    if (!(lane_t > 0.0f) || !in_range || (best >= 0 && !(lane_t < best_t))) continue;
    best = i;
    best_t = lane_t;
    best_v = vv;
    best_w = w;
    best_inv = inv_det;
    if (any_hit) break;
  }
  if (best < 0) return -1;
  *t = best_t;
  *b1 = best_v * best_inv;
  *b2 = best_w * best_inv;
  return best;
}
#else
RT_DEVICE int IntersectTriangleBlock(RT_GLOBAL const TriangleBlock* block,
                                     RT_PRIVATE const TriangleRay* tr, real tmax, int cull,
                                     int any_hit, RT_PRIVATE real* t, RT_PRIVATE real* b1,
                                     RT_PRIVATE real* b2) {
  LaneReal az = RT_BLOCK_LANES(block, 0, tr->off_z) - RayLaneRead(tr->lane_oz);
  LaneReal bz = RT_BLOCK_LANES(block, 1, tr->off_z) - RayLaneRead(tr->lane_oz);
  LaneReal cz = RT_BLOCK_LANES(block, 2, tr->off_z) - RayLaneRead(tr->lane_oz);
  LaneReal ax = (RT_BLOCK_LANES(block, 0, tr->off_x) - RayLaneRead(tr->lane_ox)) -
                RayLaneRead(tr->lane_sx) * az;
  LaneReal ay = (RT_BLOCK_LANES(block, 0, tr->off_y) - RayLaneRead(tr->lane_oy)) -
                RayLaneRead(tr->lane_sy) * az;
  LaneReal bx = (RT_BLOCK_LANES(block, 1, tr->off_x) - RayLaneRead(tr->lane_ox)) -
                RayLaneRead(tr->lane_sx) * bz;
  LaneReal by = (RT_BLOCK_LANES(block, 1, tr->off_y) - RayLaneRead(tr->lane_oy)) -
                RayLaneRead(tr->lane_sy) * bz;
  LaneReal cx = (RT_BLOCK_LANES(block, 2, tr->off_x) - RayLaneRead(tr->lane_ox)) -
                RayLaneRead(tr->lane_sx) * cz;
  LaneReal cy = (RT_BLOCK_LANES(block, 2, tr->off_y) - RayLaneRead(tr->lane_oy)) -
                RayLaneRead(tr->lane_sy) * cz;
  LaneReal u = cx * by - cy * bx;
  LaneReal vv = ax * cy - ay * cx;
  LaneReal w = bx * ay - by * ax;
  LaneReal zero = LaneSplat(0.0f);
  LaneRealMask miss =
      ((u < zero) | (vv < zero) | (w < zero)) & ((u > zero) | (vv > zero) | (w > zero));
  LaneReal det = u + vv + w;
  miss |= det == zero;
  if (cull) miss |= det < zero;
  LaneReal tscaled = u * (RayLaneRead(tr->lane_sz) * az) + vv * (RayLaneRead(tr->lane_sz) * bz) +
                     w * (RayLaneRead(tr->lane_sz) * cz);
  LaneReal inv_det = LaneSplat(1.0f) / det;
  LaneReal lane_t = tscaled * inv_det;
  // t > 0 also refuses the lanes whose tscaled has det's opposite sign (or is zero).
  LaneRealMask in_range = any_hit ? lane_t < LaneSplat(tmax) : lane_t <= LaneSplat(tmax);
  LaneRealMask found = ~miss & (lane_t > zero) & in_range;
  int hits = LaneBits(LaneMaskToInt(found));
  if (hits == 0) return -1;
  real ts[RT_BVH_WIDTH];
  LaneStoreR(lane_t, ts);
  int best = LowestLane(hits);
  if (!any_hit)
    for (hits &= hits - 1; hits != 0; hits &= hits - 1) {
      int i = LowestLane(hits);
      if (ts[i] < ts[best]) best = i;
    }
  real invs[RT_BVH_WIDTH], vs[RT_BVH_WIDTH], ws[RT_BVH_WIDTH];
  LaneStoreR(inv_det, invs);
  LaneStoreR(vv, vs);
  LaneStoreR(w, ws);
  *t = ts[best];
  *b1 = vs[best] * invs[best];
  *b2 = ws[best] * invs[best];
  return best;
}
#endif

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
