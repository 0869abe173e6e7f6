// Rays, hit records and the robust spawning of secondary rays.
#ifndef RT_RAY_H
#define RT_RAY_H

#include "util/math.h"

typedef struct Ray {
  float3 origin;
  float3 direction;  // Not necessarily unit length: t is shared by world and object space.
  float tmax;
  float time;  // Shutter time in [0, 1] for motion blur.
} Ray;

typedef struct Hit {
  float t;
  int instance;   // -1 when nothing was hit.
  int primitive;  // Triangle index, or -1 for a sphere.
  float b1, b2;   // Barycentric coordinates of v1 and v2 on a triangle.
} Hit;

RT_DEVICE Ray MakeRay(float3 origin, float3 direction, float tmax, float time) {
  Ray r;
  r.origin = origin;
  r.direction = direction;
  r.tmax = tmax;
  r.time = time;
  return r;
}

RT_DEVICE float3 RayAt(Ray r, float t) { return r.origin + r.direction * t; }

// The origin of a ray leaving surface point p on the side that unit normal n points to:
// first the scene's own epsilon along n (as the course's files ask), then 8 float ulps of
// `scale`, the largest coordinate magnitude p was computed from (its triangle's vertices
// or its sphere, in world space; at least |p|). The rounding error of p, and of the next
// intersection test near it, is a few ulps of that magnitude whatever the scene's size
// and wherever it lies, so no absolute floor is needed near the origin.
RT_DEVICE float3 OffsetRayOrigin(float3 p, float3 n, float scene_epsilon, float scale) {
  const float kRelative = 8.0f / 8388608.0f;
  float m = MaxF(MaxComponent(Abs3(p)), scale);
  return p + n * (scene_epsilon + kRelative * m);
}

#endif  // RT_RAY_H
