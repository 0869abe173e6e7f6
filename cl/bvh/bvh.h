// Two-level wide-BVH traversal in one loop. Each node tests all its children's boxes as
// one vector operation (cl/bvh/simd.h) and visits the hits nearest first. Top-level leaves
// hold one instance each; entering a mesh instance moves the ray into object space and
// continues in the mesh's own BVH, and a sentinel on the stack marks where to return to
// world space. Instances share
// their mesh's BVH and triangles; nothing is copied per instance.
#ifndef RT_BVH_H
#define RT_BVH_H

#include "../features.h"
#include "../geometry/shapes.h"
#include "../geometry/transform.h"
#include "../util/lanes.h"

// The stack entries a traversal needs, for a top level of `top` node levels and meshes of
// at most `mesh` node levels (a tree of one node has one level), `width` children a node.
// Why: a visited node pushes its hit children but the one it visits next (the nearest, or
// a shadow ray's first hit): at most width - 1 entries, a group. A node is visited only as
// the stack's top or as its parent's next child, so every group above the one it came from
// is gone by then: the groups on the stack are those of distinct ancestors of the node
// being visited, one per level above it. After a node of level l (the root's is 1) pushes
// its own, at most (width - 1) * l entries are held. Entering a mesh from a top-level leaf
// pushes one sentinel above the top level's groups, and the mesh's groups follow:
// (width - 1) * (top + mesh) + 1 at most, for closest-hit and shadow rays alike.
#define RT_BVH_STACK_NEEDED(width, top, mesh) (((width)-1) * ((top) + (mesh)) + 1)
// Deep enough for a binned-SAH BVH of any mesh the build accepts: the builder caps the
// binary depth of each level at RT_BVH_MAX_DEPTH (src/bvh/bvh_build.cpp checks it), and
// collapsing never deepens a tree. The host refuses a scene that needs more
// (src/device/kernel_config.cpp).
#define RT_BVH_MAX_DEPTH 64
#define RT_BVH_STACK_MAX(width) (2 * ((width)-1) * RT_BVH_MAX_DEPTH + 2)
// The kernel's stack: the host sizes it from the scene's trees (-DRT_BVH_STACK, a bucket of
// RT_BVH_STACK_NEEDED); the CPU reference and a kernel built without it take the bound above.
#ifndef RT_BVH_STACK
#define RT_BVH_STACK RT_BVH_STACK_MAX(RT_BVH_WIDTH)
#endif
#define RT_STACK_RETURN_TO_WORLD (-1)
// No node index or leaf reference takes this value; it asks the loop to pop the stack.
#define RT_BVH_POP (-2147483647 - 1)

// The ray as the node test sees it: origin, reciprocal direction, and for each axis which
// of a node's bounds (BvhNode.bounds) the ray meets first: the low face when the
// direction is positive, the high face when negative (Williams et al. 2005). Origin and
// reciprocal direction are kept broadcast to every lane, so the node test is lane
// operations only (broadcasting per node went through memory in the double build).
typedef struct NodeRay {
  RayLane ox, oy, oz, ix, iy, iz;
  // Byte offsets of the faces into BvhNode.bounds (RT_NODE_BOUND): unsigned, so the address
  // is the node's plus the offset, without a sign extension or a scaling shift.
  uint near_x, near_y, near_z, far_x, far_y, far_z;
} NodeRay;

// The bound lanes at byte offset `offset` of a node's bounds.
#define RT_NODE_BOUND(node, offset) \
  LaneToReal(*(RT_GLOBAL const LaneFloat*)((RT_GLOBAL const char*)(node)->bounds + (offset)))

// Sets the origin alone, keeping what depends on the direction (see SetTriangleRayOrigin).
RT_DEVICE void SetNodeRayOrigin(RT_PRIVATE NodeRay* r, real3 o) {
  r->ox = RayLaneOf(o.x);
  r->oy = RayLaneOf(o.y);
  r->oz = RayLaneOf(o.z);
}

// The node ray of origin o and reciprocal direction inv_d.
RT_DEVICE NodeRay MakeNodeRayInv(real3 o, real3 inv_d) {
  NodeRay r;
  SetNodeRayOrigin(&r, o);
  r.ix = RayLaneOf(inv_d.x);
  r.iy = RayLaneOf(inv_d.y);
  r.iz = RayLaneOf(inv_d.z);
  const uint bound = (uint)sizeof(LaneFloat);
  r.near_x = (inv_d.x < 0.0f ? 3 : 0) * bound;
  r.near_y = (inv_d.y < 0.0f ? 4 : 1) * bound;
  r.near_z = (inv_d.z < 0.0f ? 5 : 2) * bound;
  r.far_x = 3 * bound - r.near_x;
  r.far_y = 5 * bound - r.near_y;
  r.far_z = 7 * bound - r.near_z;
  return r;
}

// A zero component gives +-inf, which the node test handles; -0 keeps its sign.
RT_DEVICE real3 ReciprocalDirection(real3 d) {
  return make_real3(1.0f / d.x, 1.0f / d.y, 1.0f / d.z);
}

RT_DEVICE NodeRay MakeNodeRay(real3 o, real3 d) {
  return MakeNodeRayInv(o, ReciprocalDirection(d));
}

// Slab test of every child box of a node at once; lane i of *tnear gets the entry distance
// and the result's lane i is non-zero where the ray enters child i before tmax. The far
// distance is enlarged by 2 * gamma(3) (pbrt-v4, Bounds3::IntersectP) so rounding never
// culls a box the ray actually touches.
RT_DEVICE LaneInt IntersectChildBoxes(RT_GLOBAL const BvhNode* node, RT_PRIVATE const NodeRay* r,
                                      real tmax, RT_PRIVATE LaneReal* tnear) {
  LaneReal nx = (RT_NODE_BOUND(node, r->near_x) - RayLaneRead(r->ox)) * RayLaneRead(r->ix);
  LaneReal ny = (RT_NODE_BOUND(node, r->near_y) - RayLaneRead(r->oy)) * RayLaneRead(r->iy);
  LaneReal nz = (RT_NODE_BOUND(node, r->near_z) - RayLaneRead(r->oz)) * RayLaneRead(r->iz);
  LaneReal fx = (RT_NODE_BOUND(node, r->far_x) - RayLaneRead(r->ox)) * RayLaneRead(r->ix);
  LaneReal fy = (RT_NODE_BOUND(node, r->far_y) - RayLaneRead(r->oy)) * RayLaneRead(r->iy);
  LaneReal fz = (RT_NODE_BOUND(node, r->far_z) - RayLaneRead(r->oz)) * RayLaneRead(r->iz);
  // A ray in the plane of a face (zero direction component, origin on the face) gives
  // 0 * inf = NaN there. It stays inside that slab for every t, so the slab must constrain
  // nothing, and it does not: the other face gives -inf as an entry or +inf as an exit,
  // and a NaN enters LaneMax / LaneMin as the first operand, which they drop (they return
  // the second operand when either is NaN).
  LaneReal tn = LaneMax(nx, LaneMax(ny, LaneMax(nz, LaneSplat(0.0f))));
  LaneReal tf = LaneMin(fx, LaneMin(fy, LaneMin(fz, LaneSplat(tmax))));
  tf = tf * 1.0000004f;
  *tnear = tn;
  // Empty lanes hold inverted boxes (src/bvh/bvh_wide.cpp) and always miss.
  return LaneMaskToInt(tn <= tf);
}

// Tests a node's children and returns the nearest child hit (RT_BVH_POP if none), pushing
// the others farthest first so they pop nearest first. Equal distances keep lane order,
// the same on both devices. A shadow ray (any_hit) asks only whether something lies before
// tmax, which no order changes, so its children are not sorted: the first lane hit is
// visited next and the others pushed. Most nodes have one or two children hit, which are
// ordered without the general sort.
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
  RT_KERNEL_UNROLL
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

// What a transform whose linear part is exactly the identity (RT_INSTANCE_TRANSLATION)
// makes of a point before adding its translation: TransformPoint's RowDot with rows of 1
// and +0, the same operations in the same order (1 * x is x exactly), so adding an
// instance's translation to it gives TransformPoint's result bit for bit.
RT_DEVICE real3 IdentityLinearPart(real3 p) {
  return make_real3((p.x + 0.0f * p.y) + 0.0f * p.z, (0.0f * p.x + p.y) + 0.0f * p.z,
                    (0.0f * p.x + 0.0f * p.y) + p.z);
}

// 1 when such a linear part leaves the direction whose reciprocal is inv_d exactly as it
// is: each row computes (1 * x + 0 * y) + 0 * z, where 0 * y is a zero of y's sign (y
// finite) and x plus a zero is x unless x is itself a zero, when +0 plus either zero is +0.
// So every component must be finite (inv_d not +-0 or NaN) and not -0 (inv_d not -inf);
// a tiny negative component whose reciprocal overflows is refused too, which only costs a
// node ray of its own.
RT_DEVICE int IdentityKeepsDirection(real3 inv_d) {
  // Evaluated whole (& rather than &&): six compares without branches.
  return (inv_d.x > -RT_INFINITY) & (inv_d.x != 0.0f) & (inv_d.y > -RT_INFINITY) &
         (inv_d.y != 0.0f) & (inv_d.z > -RT_INFINITY) & (inv_d.z != 0.0f);
}

// Whether a closest-hit candidate at distance t <= hit->t, on primitive `primitive` of
// instance `instance` (-1 for a sphere), replaces *hit: when it is nearer, or at the same
// distance with a smaller (instance, primitive). Ties are settled by index rather than by
// which was found first, so the closest hit is the same whatever the order of the tree's
// visits: the same for 4- and 8-wide nodes, and so on every device whichever width it
// traverses (two triangles sharing an edge both report a ray through it, at equal t).
RT_DEVICE int ClosestHitWins(RT_PRIVATE const Hit* hit, real t, int instance, int primitive) {
  if (t < hit->t) return 1;
  if (hit->instance < 0 || t != hit->t) return 0;  // No hit yet: t == ray.tmax is a miss.
  return instance < hit->instance || (instance == hit->instance && primitive < hit->primitive);
}

// World-space origin of an instance's ray at the ray's time.
RT_DEVICE real3 InstanceRayOrigin(RT_GLOBAL const Instance* inst, Ray ray) {
  real3 o = ray.origin;
  if ((inst->flags & RT_INSTANCE_MOVING) != 0) o = o - ToReal3(inst->motion) * ray.time;
  return o;
}

// Finds the closest hit (any_hit = 0) or any hit at all (any_hit = 1, for shadow rays)
// with t < ray->tmax. Returns 1 on a hit and fills *hit.
// The ray comes by pointer and is read a component at a time: passed by value, the caller
// copied it into the call's stack area in 16-byte pieces right after writing its
// components one by one, and each such copy stalled on store-to-load forwarding (the
// shadow ray's copy was a quarter of AddLightSamples' own time in hw3 spheres_dof).
RT_KERNEL_INLINE int IntersectScene(RT_PRIVATE const SceneData* sd, RT_PRIVATE const Ray* ray_in,
                                    int any_hit, int cull, RT_PRIVATE Hit* hit) {
  real3 ray_origin = make_real3(ray_in->origin.x, ray_in->origin.y, ray_in->origin.z);
  real3 ray_direction = make_real3(ray_in->direction.x, ray_in->direction.y, ray_in->direction.z);
#if RT_GPU_FORMS
  RT_PRIVATE int* stack = sd->bvh_stack;
#else
  int stack[RT_BVH_STACK];
#endif
  int sp = 0;
  int ref = sd->header->tlas_root;  // A node index, or a leaf reference (RtLeafRef).
  int instance = -1;                // The instance whose BVH we are in, or -1 at the top level.
  // The world's node ray is set up once. An instance that sees the world's direction (one
  // that is not transformed, or is translated while the ray keeps its direction through a
  // translation) moves only its origin into object space, restored on return; any other
  // instance makes its own node ray, and the pointer switches back on return. Triangles lie
  // only inside instances, so only an instance's triangle ray is ever made; while
  // instances see the world's direction, its direction-dependent part is made once.
  real3 inv_d = ReciprocalDirection(ray_direction);
  NodeRay world_nr = MakeNodeRayInv(ray_origin, inv_d);
#if !RT_GPU_FORMS
  NodeRay object_nr;
#endif
  TriangleRay object_tr;
  int tr_has_world_direction = 0;
  // Whether a translation keeps the ray's direction (IdentityKeepsDirection), and the
  // ray's origin through the identity, to which each translation is added.
  int translation_keeps_direction = 0;
  real3 identity_origin = ray_origin;
  if (RT_HAS(sd, RT_FEATURE_TRANSFORMS)) {
    translation_keeps_direction = IdentityKeepsDirection(inv_d);
    identity_origin = IdentityLinearPart(ray_origin);
  }
  RT_PRIVATE const NodeRay* nr = &world_nr;
  real tmax = ray_in->tmax;
  hit->instance = -1;
  hit->t = tmax;
  if (ref < 0) return 0;
  for (;;) {
    if (ref >= 0) {
      ref = VisitChildren(&sd->nodes[ref], nr, tmax, any_hit, stack, &sp);
      if (ref != RT_BVH_POP) continue;
    } else if (instance < 0) {
      // A top-level leaf: exactly one instance.
      int ii = RtLeafFirst(ref);
      RT_GLOBAL const Instance* inst = &sd->instances[ii];
      int flags = inst->flags;
      int moving = RT_HAS(sd, RT_FEATURE_MOTION_BLUR) && (flags & RT_INSTANCE_MOVING) != 0;
      int transformed = RT_HAS(sd, RT_FEATURE_TRANSFORMS) && (flags & RT_INSTANCE_TRANSFORMED) != 0;
      int translated = transformed && (flags & RT_INSTANCE_TRANSLATION) != 0;
      real3 io = ray_origin;
      if (translated && !moving) {
        RT_GLOBAL const float4* m = inst->world_to_object;
        io = make_real3(identity_origin.x + m[0].w, identity_origin.y + m[1].w,
                        identity_origin.z + m[2].w);
      } else {
        if (moving) io = InstanceRayOrigin(inst, *ray_in);
        if (transformed) io = TransformPoint(inst->world_to_object, io);
      }
      // The kernel has this path only for a scene with such meshes (RT_COMPILED; the CPU
      // reference always has it). Inlined, the direction part of MakeTriangleRay depends on
      // the ray alone, and PoCL's compiler (LLVM's loop-invariant code motion) moves its
      // divisions to the start of every traversal, so a scene whose meshes are all rotated
      // or scaled (hw3's metal_glass_plates) would pay them on every ray, shadow rays
      // included. Where such meshes exist, almost every ray does that work anyway, and moved
      // it costs less than a call that cannot be moved. GCC moves nothing there.
      int world_direction = RT_COMPILED(RT_FEATURE_WORLD_MESHES) &&
                            (!transformed || (translated && translation_keeps_direction));
      if (RT_HAS(sd, RT_FEATURE_SPHERES) && inst->kind == RT_INSTANCE_SPHERE) {
        real3 id =
            transformed ? TransformVector(inst->world_to_object, ray_direction) : ray_direction;
        real t;
        // A closest-hit query takes the sphere's nearest t > 0 and leaves the comparison with
        // tmax, ties included, to ClosestHitWins (the far root is nearer than tmax only when
        // the near one is, or lies behind the origin).
        if (IntersectUnitSphere(io, id, any_hit ? tmax : RT_INFINITY, &t) &&
            (any_hit || ClosestHitWins(hit, t, ii, -1))) {
          tmax = t;
          hit->t = t;
          hit->instance = ii;
          hit->primitive = -1;
          if (any_hit) return 1;
        }
      } else if (RT_HAS(sd, RT_FEATURE_TRIANGLES)) {
        instance = ii;
        if (world_direction) {
          if (moving || transformed) SetNodeRayOrigin(&world_nr, io);
          if (tr_has_world_direction) {
            SetTriangleRayOrigin(&object_tr, io);
          } else {
            object_tr = MakeTriangleRay(io, ray_direction);
            tr_has_world_direction = 1;
          }
        } else {
          real3 id = TransformVector(inst->world_to_object, ray_direction);
#if RT_GPU_FORMS
          // On a GPU one node ray, remade on return: a pointer to either of two would
          // keep both in private memory.
          world_nr = MakeNodeRay(io, id);
#else
          object_nr = MakeNodeRay(io, id);
          nr = &object_nr;
#endif
          object_tr = MakeTriangleRay(io, id);
          tr_has_world_direction = 0;
        }
        stack[sp++] = RT_STACK_RETURN_TO_WORLD;
        ref = inst->blas_root;
        continue;
      }
    } else {
      // A bottom-level leaf: its triangles in blocks, tested a block at a time in order.
      RT_GLOBAL const TriangleBlock* block = &sd->triangle_blocks[RtLeafFirst(ref)];
      for (int n = RtLeafCount(ref); n > 0; n -= RT_BVH_WIDTH, ++block) {
        real t, b1, b2;
        int lane = IntersectTriangleBlock(block, &object_tr, tmax, cull, any_hit, &t, &b1, &b2);
        if (lane >= 0 && (any_hit || ClosestHitWins(hit, t, instance, block->first + lane))) {
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
    // The next node to visit, back in world space past an instance's sentinel.
    for (;;) {
      if (sp == 0) return hit->instance >= 0;
      ref = stack[--sp];
      if (ref != RT_STACK_RETURN_TO_WORLD) break;
      instance = -1;
#if RT_GPU_FORMS
      world_nr = MakeNodeRayInv(ray_origin, inv_d);
#else
      if (nr == &world_nr) {
        SetNodeRayOrigin(&world_nr, ray_origin);
      } else {
        nr = &world_nr;
      }
#endif
    }
  }
}

#endif  // RT_BVH_H
