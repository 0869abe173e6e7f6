// Two-level BVH traversal in one loop. Top-level leaves hold one instance each; entering
// a mesh instance moves the ray into object space and continues in the mesh's own BVH,
// and a sentinel on the stack marks where to return to world space. Instances share
// their mesh's BVH and triangles; nothing is copied per instance.
#ifndef RT_BVH_H
#define RT_BVH_H

#include "features.h"
#include "shapes.h"
#include "transform.h"

// Deep enough for a binned-SAH BVH of any mesh the build accepts: the builder caps the
// depth of each level at RT_BVH_MAX_DEPTH (src/bvh_build.cpp checks it).
#define RT_BVH_MAX_DEPTH 64
#define RT_BVH_STACK (2 * RT_BVH_MAX_DEPTH + 2)
#define RT_STACK_RETURN_TO_WORLD (-1)

// Slab test; returns the entry distance or RT_INFINITY on a miss. The far distance is
// enlarged by 2 * gamma(3) (pbrt-v4, Bounds3::IntersectP) so rounding never culls a box
// the ray actually touches.
RT_DEVICE float IntersectBox(RT_GLOBAL const BvhNode* node, float3 o, float3 inv_d, float tmax) {
  float tx0 = (node->lo[0] - o.x) * inv_d.x, tx1 = (node->hi[0] - o.x) * inv_d.x;
  float ty0 = (node->lo[1] - o.y) * inv_d.y, ty1 = (node->hi[1] - o.y) * inv_d.y;
  float tz0 = (node->lo[2] - o.z) * inv_d.z, tz1 = (node->hi[2] - o.z) * inv_d.z;
  // A ray in the plane of a face (zero direction component, origin on the face) gives
  // 0 * inf = NaN there and +-inf at the other face. It stays inside that slab for every t,
  // so the NaN becomes the opposite infinity and the slab constrains nothing.
  tx0 = tx0 != tx0 ? -tx1 : tx0;
  tx1 = tx1 != tx1 ? -tx0 : tx1;
  ty0 = ty0 != ty0 ? -ty1 : ty0;
  ty1 = ty1 != ty1 ? -ty0 : ty1;
  tz0 = tz0 != tz0 ? -tz1 : tz0;
  tz1 = tz1 != tz1 ? -tz0 : tz1;
  float tnear = MaxF(MaxF(MinF(tx0, tx1), MinF(ty0, ty1)), MaxF(MinF(tz0, tz1), 0.0f));
  float tfar = MinF(MinF(MaxF(tx0, tx1), MaxF(ty0, ty1)), MinF(MaxF(tz0, tz1), tmax));
  tfar *= 1.0000004f;
  return tnear <= tfar ? tnear : RT_INFINITY;
}

RT_DEVICE float3 SafeInverse(float3 d) {
  // A zero component gives +-inf, which the slab test handles; -0 keeps its sign.
  return make_float3(1.0f / d.x, 1.0f / d.y, 1.0f / d.z);
}

// World-space origin of an instance's ray at the ray's time.
RT_DEVICE float3 InstanceRayOrigin(RT_GLOBAL const Instance* inst, Ray ray) {
  float3 o = ray.origin;
  if ((inst->flags & RT_INSTANCE_MOVING) != 0) o = o - inst->motion * ray.time;
  return o;
}

// Finds the closest hit (any_hit = 0) or any hit at all (any_hit = 1, for shadow rays)
// with t < ray.tmax. Returns 1 on a hit and fills *hit.
RT_DEVICE int IntersectScene(RT_PRIVATE const SceneData* sd, Ray ray, int any_hit, int cull,
                             RT_PRIVATE Hit* hit) {
  int stack[RT_BVH_STACK];
  int sp = 0;
  int node_index = sd->header->tlas_root;
  int instance = -1;  // The instance whose BVH we are in, or -1 at the top level.
  float3 o = ray.origin, d = ray.direction;
  float3 inv_d = SafeInverse(d);
  TriangleRay tr = MakeTriangleRay(o, d);
  float tmax = ray.tmax;
  hit->instance = -1;
  hit->t = tmax;
  if (node_index < 0) return 0;
  for (;;) {
    RT_GLOBAL const BvhNode* node = &sd->nodes[node_index];
    int next = -2;  // -2: pop the stack.
    if (IntersectBox(node, o, inv_d, tmax) < RT_INFINITY) {
      if (node->count <= 0) {
        int axis = -node->count;
        int dir_negative = Component(d, axis) < 0.0f;
        stack[sp++] = node->first + 1 - dir_negative;
        next = node->first + dir_negative;
      } else if (instance < 0) {
        // A top-level leaf: exactly one instance.
        int ii = node->first;
        RT_GLOBAL const Instance* inst = &sd->instances[ii];
        float3 io = RT_HAS(sd, RT_FEATURE_MOTION_BLUR) ? InstanceRayOrigin(inst, ray) : ray.origin;
        float3 id = ray.direction;
        if (RT_HAS(sd, RT_FEATURE_TRANSFORMS) && (inst->flags & RT_INSTANCE_TRANSFORMED) != 0) {
          io = TransformPoint(inst->world_to_object, io);
          id = TransformVector(inst->world_to_object, id);
        }
        if (RT_HAS(sd, RT_FEATURE_SPHERES) && inst->kind == RT_INSTANCE_SPHERE) {
          float t;
          if (IntersectUnitSphere(io, id, tmax, &t)) {
            tmax = t;
            hit->t = t;
            hit->instance = ii;
            hit->primitive = -1;
            if (any_hit) return 1;
          }
        } else if (RT_HAS(sd, RT_FEATURE_TRIANGLES)) {
          instance = ii;
          o = io;
          d = id;
          inv_d = SafeInverse(d);
          tr = MakeTriangleRay(o, d);
          stack[sp++] = RT_STACK_RETURN_TO_WORLD;
          next = inst->blas_root;
        }
      } else {
        for (int i = node->first; i < node->first + node->count; ++i) {
          RT_GLOBAL const Triangle* tri = &sd->triangles[i];
          float t, b1, b2;
          if (IntersectTriangle(&tr, tri->v0, tri->v1, tri->v2, tmax, cull, &t, &b1, &b2)) {
            tmax = t;
            hit->t = t;
            hit->instance = instance;
            hit->primitive = i;
            hit->b1 = b1;
            hit->b2 = b2;
            if (any_hit) return 1;
          }
        }
      }
    }
    while (next == -2) {
      if (sp == 0) return hit->instance >= 0;
      next = stack[--sp];
      if (next == RT_STACK_RETURN_TO_WORLD) {
        instance = -1;
        o = ray.origin;
        d = ray.direction;
        inv_d = SafeInverse(d);
        tr = MakeTriangleRay(o, d);
        next = -2;
      }
    }
    node_index = next;
  }
}

#endif  // RT_BVH_H
