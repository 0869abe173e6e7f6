// Rays, hit records and the robust spawning of secondary rays.
#ifndef RT_RAY_H
#define RT_RAY_H

#include "util/math.h"

typedef struct Ray {
  float3 origin;
  float3 direction;  // Not necessarily unit length: t is shared by world and object space.
  float tmax;
  float time;        // Shutter time in [0, 1] for motion blur.
} Ray;

typedef struct Hit {
  float t;
  int instance;  // -1 when nothing was hit.
  int primitive; // Triangle index, or -1 for a sphere.
  float b1, b2;  // Barycentric coordinates of v1 and v2 on a triangle.
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

RT_DEVICE float OffsetComponent(float p, float n) {
  // Moves p by a fixed number of float ulps in the direction of n, so the offset scales
  // with the magnitude of p (Wächter and Binder, Ray Tracing Gems ch. 6).
  const float kIntScale = 256.0f;
  int offset = (int)(kIntScale * n);
  float moved = rt_int_as_float(rt_float_as_int(p) + (p < 0.0f ? -offset : offset));
  // Near the origin ulps become tiny, so a small absolute offset takes over.
  const float kOrigin = 1.0f / 32.0f;
  const float kFloatScale = 1.0f / 65536.0f;
  return fabs(p) < kOrigin ? p + kFloatScale * n : moved;
}

// The origin of a ray leaving surface point p on the side that unit normal n points to:
// first the scene's own epsilon along n (as the course's files ask), then a scale-aware
// offset that keeps the ray off the surface even where that epsilon is too small for the
// magnitude of p.
RT_DEVICE float3 OffsetRayOrigin(float3 p, float3 n, float scene_epsilon) {
  // Intersection tests near p round in proportion to its largest coordinate, not to the
  // coordinates along n (a plane y = 0 far out along x): move 256 ulps of that first.
  const float kRelative = 256.0f / 8388608.0f;
  float3 q = p + n * (scene_epsilon + kRelative * MaxComponent(Abs3(p)));
  return make_float3(OffsetComponent(q.x, n.x), OffsetComponent(q.y, n.y),
                     OffsetComponent(q.z, n.z));
}

#endif  // RT_RAY_H
