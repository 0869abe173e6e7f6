// The scene's two ray queries, by name: the closest hit along a ray, and whether anything
// blocks a shadow segment. The traversal behind both is cl/bvh/bvh.h.
#ifndef RT_INTERSECT_H
#define RT_INTERSECT_H

#include "bvh.h"

// The traversal compiled once per query, any_hit a constant in each copy. GCC makes such a
// copy itself (IntersectScene.constprop); PoCL's compiler kept one IntersectScene that
// tested any_hit at every node of every ray. In the kernel each is a call of its own; on
// the CPU they are ordinary inline functions.
RT_KERNEL_NOINLINE int TraceClosest(RT_PRIVATE const SceneData* sd, RT_PRIVATE const Ray* ray,
                                    int cull, RT_PRIVATE Hit* hit) {
  return IntersectScene(sd, ray, 0, cull, hit);
}

RT_KERNEL_NOINLINE int TraceOccluded(RT_PRIVATE const SceneData* sd, RT_PRIVATE const Ray* ray) {
  Hit hit;
  return IntersectScene(sd, ray, 1, 0, &hit);
}

// Both are inlined, so the traversal reads the caller's own ray (IntersectScene).

// The closest hit with t < ray.tmax into *hit; 0 when the ray escapes. `cull` skips
// triangles facing away from the ray.
RT_DEVICE_INLINE int IntersectClosest(RT_PRIVATE const SceneData* sd, Ray ray, int cull,
                                      RT_PRIVATE Hit* hit) {
  return TraceClosest(sd, &ray, cull, hit);
}

// 1 when anything lies on the ray with t < ray.tmax; stops at the first hit found.
RT_DEVICE_INLINE int IntersectOccluded(RT_PRIVATE const SceneData* sd, Ray ray) {
  return TraceOccluded(sd, &ray);
}

#endif  // RT_INTERSECT_H
