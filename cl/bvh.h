// Two-level wide-BVH traversal in one loop. Each node tests all its children's boxes as
// one vector operation (cl/simd.h) and visits the hits nearest first. Top-level leaves
// hold one instance each; entering a mesh instance moves the ray into object space and
// continues in the mesh's own BVH, and a sentinel on the stack marks where to return to
// world space. Instances share
// their mesh's BVH and triangles; nothing is copied per instance.
#ifndef RT_BVH_H
#define RT_BVH_H

#include "features.h"
#include "shapes.h"
#include "transform.h"
#include "util/lanes.h"

// Deep enough for a binned-SAH BVH of any mesh the build accepts: the builder caps the
// binary depth of each level at RT_BVH_MAX_DEPTH (src/bvh_build.cpp checks it), collapsing
// never deepens a tree, and each wide level pushes at most RT_BVH_WIDTH - 1 children.
#define RT_BVH_MAX_DEPTH 64
#define RT_BVH_STACK (2 * (RT_BVH_WIDTH - 1) * RT_BVH_MAX_DEPTH + 2)
#define RT_STACK_RETURN_TO_WORLD (-1)
// No node index or leaf reference takes this value; it asks the loop to pop the stack.
#define RT_BVH_POP (-2147483647 - 1)

// The ray as the node test sees it: origin, reciprocal direction, and for each axis which
// of a node's bounds (BvhNode.bounds) the ray meets first: the low face when the
// direction is positive, the high face when negative (Williams et al. 2005). Origin and
// reciprocal direction are kept broadcast to every lane, so the node test is lane
// operations only (broadcasting per node went through memory in the double build).
typedef struct NodeRay {
  LaneReal ox, oy, oz, ix, iy, iz;
  int near_x, near_y, near_z, far_x, far_y, far_z;
} NodeRay;

RT_DEVICE NodeRay MakeNodeRay(real3 o, real3 d) {
  NodeRay r;
  // A zero component gives +-inf, which the node test handles; -0 keeps its sign.
  real3 inv_d = make_real3(1.0f / d.x, 1.0f / d.y, 1.0f / d.z);
  r.ox = LaneSplat(o.x);
  r.oy = LaneSplat(o.y);
  r.oz = LaneSplat(o.z);
  r.ix = LaneSplat(inv_d.x);
  r.iy = LaneSplat(inv_d.y);
  r.iz = LaneSplat(inv_d.z);
  r.near_x = inv_d.x < 0.0f ? 3 : 0;
  r.near_y = inv_d.y < 0.0f ? 4 : 1;
  r.near_z = inv_d.z < 0.0f ? 5 : 2;
  r.far_x = 3 - r.near_x;
  r.far_y = 5 - r.near_y;
  r.far_z = 7 - r.near_z;
  return r;
}

// Slab test of every child box of a node at once; lane i of *tnear gets the entry distance
// and the result's lane i is non-zero where the ray enters child i before tmax. The far
// distance is enlarged by 2 * gamma(3) (pbrt-v4, Bounds3::IntersectP) so rounding never
// culls a box the ray actually touches.
RT_DEVICE LaneInt IntersectChildBoxes(RT_GLOBAL const BvhNode* node, RT_PRIVATE const NodeRay* r,
                                      real tmax, RT_PRIVATE LaneReal* tnear) {
  LaneReal nx = (LaneToReal(node->bounds[r->near_x]) - r->ox) * r->ix;
  LaneReal ny = (LaneToReal(node->bounds[r->near_y]) - r->oy) * r->iy;
  LaneReal nz = (LaneToReal(node->bounds[r->near_z]) - r->oz) * r->iz;
  LaneReal fx = (LaneToReal(node->bounds[r->far_x]) - r->ox) * r->ix;
  LaneReal fy = (LaneToReal(node->bounds[r->far_y]) - r->oy) * r->iy;
  LaneReal fz = (LaneToReal(node->bounds[r->far_z]) - r->oz) * r->iz;
  // A ray in the plane of a face (zero direction component, origin on the face) gives
  // 0 * inf = NaN there. It stays inside that slab for every t, so the slab must constrain
  // nothing, and it does not: the other face gives -inf as an entry or +inf as an exit,
  // and a NaN enters LaneMax / LaneMin as the first operand, which they drop (they return
  // the second operand when either is NaN).
  LaneReal tn = LaneMax(nx, LaneMax(ny, LaneMax(nz, LaneSplat(0.0f))));
  LaneReal tf = LaneMin(fx, LaneMin(fy, LaneMin(fz, LaneSplat(tmax))));
  tf = tf * 1.0000004f;
  *tnear = tn;
  // Empty lanes hold inverted boxes (src/bvh_wide.cpp) and always miss.
  return LaneMaskToInt(tn <= tf);
}

// Tests a node's children and returns the nearest child hit (RT_BVH_POP if none), pushing
// the others farthest first so they pop nearest first. Equal distances keep lane order,
// the same on both devices. A shadow ray (any_hit) asks only whether something lies before
// tmax, which no order changes, so its children are not sorted: the first lane hit is
// visited next and the others pushed.
RT_DEVICE int VisitChildren(RT_GLOBAL const BvhNode* node, RT_PRIVATE const NodeRay* r, real tmax,
                            int any_hit, RT_PRIVATE int* stack, RT_PRIVATE int* sp) {
  LaneReal tnear;
  LaneInt hits = IntersectChildBoxes(node, r, tmax, &tnear);
  int lane_hit[RT_BVH_WIDTH], lane_child[RT_BVH_WIDTH];
  LaneStoreI(hits, lane_hit);
  LaneStoreI(node->child, lane_child);
  if (any_hit) {
    int next = RT_BVH_POP;
    for (int i = RT_BVH_WIDTH - 1; i >= 0; --i) {
      if (lane_hit[i] == 0) continue;
      if (next != RT_BVH_POP) stack[(*sp)++] = next;
      next = lane_child[i];
    }
    return next;
  }
  real lane_t[RT_BVH_WIDTH];
  LaneStoreR(tnear, lane_t);
  real sorted_t[RT_BVH_WIDTH];
  int sorted_child[RT_BVH_WIDTH];
  int n = 0;
  for (int i = 0; i < RT_BVH_WIDTH; ++i) {
    if (lane_hit[i] == 0) continue;
    int j = n++;
    for (; j > 0 && sorted_t[j - 1] > lane_t[i]; --j) {
      sorted_t[j] = sorted_t[j - 1];
      sorted_child[j] = sorted_child[j - 1];
    }
    sorted_t[j] = lane_t[i];
    sorted_child[j] = lane_child[i];
  }
  if (n == 0) return RT_BVH_POP;
  for (int k = n - 1; k > 0; --k) stack[(*sp)++] = sorted_child[k];
  return sorted_child[0];
}

// World-space origin of an instance's ray at the ray's time.
RT_DEVICE real3 InstanceRayOrigin(RT_GLOBAL const Instance* inst, Ray ray) {
  real3 o = ray.origin;
  if ((inst->flags & RT_INSTANCE_MOVING) != 0) o = o - ToReal3(inst->motion) * ray.time;
  return o;
}

// Finds the closest hit (any_hit = 0) or any hit at all (any_hit = 1, for shadow rays)
// with t < ray.tmax. Returns 1 on a hit and fills *hit.
RT_DEVICE int IntersectScene(RT_PRIVATE const SceneData* sd, Ray ray, int any_hit, int cull,
                             RT_PRIVATE Hit* hit) {
  int stack[RT_BVH_STACK];
  int sp = 0;
  int ref = sd->header->tlas_root;  // A node index, or a leaf reference (RtLeafRef).
  int instance = -1;                // The instance whose BVH we are in, or -1 at the top level.
  // The world's node ray is set up once; an instance's ray replaces it while the traversal
  // is inside the instance (unless the instance neither moves nor is transformed: its ray
  // is the world's), and the pointer switches back on return. Triangles lie only inside
  // instances, so only an instance's triangle ray is ever made.
  NodeRay world_nr = MakeNodeRay(ray.origin, ray.direction), object_nr;
  TriangleRay object_tr;
  RT_PRIVATE const NodeRay* nr = &world_nr;
  real tmax = ray.tmax;
  hit->instance = -1;
  hit->t = tmax;
  if (ref < 0) return 0;
  for (;;) {
    int next = RT_BVH_POP;
    if (ref >= 0) {
      next = VisitChildren(&sd->nodes[ref], nr, tmax, any_hit, stack, &sp);
    } else if (instance < 0) {
      // A top-level leaf: exactly one instance.
      int ii = RtLeafFirst(ref);
      RT_GLOBAL const Instance* inst = &sd->instances[ii];
      real3 io = RT_HAS(sd, RT_FEATURE_MOTION_BLUR) ? InstanceRayOrigin(inst, ray) : ray.origin;
      real3 id = ray.direction;
      int moved = RT_HAS(sd, RT_FEATURE_MOTION_BLUR) && (inst->flags & RT_INSTANCE_MOVING) != 0;
      if (RT_HAS(sd, RT_FEATURE_TRANSFORMS) && (inst->flags & RT_INSTANCE_TRANSFORMED) != 0) {
        io = TransformPoint(inst->world_to_object, io);
        id = TransformVector(inst->world_to_object, id);
        moved = 1;
      }
      if (RT_HAS(sd, RT_FEATURE_SPHERES) && inst->kind == RT_INSTANCE_SPHERE) {
        real t;
        if (IntersectUnitSphere(io, id, tmax, &t)) {
          tmax = t;
          hit->t = t;
          hit->instance = ii;
          hit->primitive = -1;
          if (any_hit) return 1;
        }
      } else if (RT_HAS(sd, RT_FEATURE_TRIANGLES)) {
        instance = ii;
        if (moved) {
          object_nr = MakeNodeRay(io, id);
          nr = &object_nr;
        }
        object_tr = MakeTriangleRay(io, id);
        stack[sp++] = RT_STACK_RETURN_TO_WORLD;
        next = inst->blas_root;
      }
    } else {
      // A bottom-level leaf: its triangles in blocks, tested a block at a time in order.
      RT_GLOBAL const TriangleBlock* block = &sd->triangle_blocks[RtLeafFirst(ref)];
      for (int n = RtLeafCount(ref); n > 0; n -= RT_BVH_WIDTH, ++block) {
        real t, b1, b2;
        int lane = IntersectTriangleBlock(block, &object_tr, tmax, cull, any_hit, &t, &b1, &b2);
        if (lane >= 0) {
          tmax = t;
          hit->t = t;
          hit->instance = instance;
          hit->primitive = block->first + lane;
          hit->b1 = b1;
          hit->b2 = b2;
          if (any_hit) return 1;
        }
      }
    }
    while (next == RT_BVH_POP) {
      if (sp == 0) return hit->instance >= 0;
      next = stack[--sp];
      if (next == RT_STACK_RETURN_TO_WORLD) {
        instance = -1;
        nr = &world_nr;
        next = RT_BVH_POP;
      }
    }
    ref = next;
  }
}

#endif  // RT_BVH_H
