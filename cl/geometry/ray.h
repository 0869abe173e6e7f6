// Rays, hit records and the robust spawning of secondary rays.
#ifndef RT_RAY_H
#define RT_RAY_H

#include "../util/math.h"

typedef struct Ray {
  real3 origin;
  real3 direction;  // Not necessarily unit length: t is shared by world and object space.
  real tmax;
  real time;  // Shutter time in [0, 1] for motion blur.
} Ray;

typedef struct Hit {
  real t;
  int instance;   // -1 when nothing was hit.
  int primitive;  // Triangle index, or -1 for a sphere.
  real b1, b2;    // Barycentric coordinates of v1 and v2 on a triangle.
} Hit;

RT_DEVICE Ray MakeRay(real3 origin, real3 direction, real tmax, real time) {
  Ray r;
  r.origin = origin;
  r.direction = direction;
  r.tmax = tmax;
  r.time = time;
  return r;
}

RT_DEVICE real3 RayAt(Ray r, real t) { return r.origin + r.direction * t; }

// The origin of a ray leaving surface point p on the side that unit normal n points to.
// By default (robust == 0) it is the scene's own epsilon along n and nothing more, as the
// course's renderer offsets its rays: its images keep shadow and reflection edges where
// that offset puts them (hw1 spheres_mirror, hw2 grass_desert match them so). robust
// adds 8 float ulps of `scale`, the largest coordinate magnitude p was computed from (its
// triangle's vertices or its sphere, in world space; at least |p|): the rounding error of
// p, and of the next intersection test near it, is a few ulps of that magnitude whatever
// the scene's size and wherever it lies, so no absolute floor is needed near the origin.
// Without a scene epsilon (zero, or --no-scene-epsilon) that step is taken either way.
RT_DEVICE real3 OffsetRayOrigin(real3 p, real3 n, real scene_epsilon, real scale, int robust) {
  if (!robust && scene_epsilon > 0.0f) return p + n * scene_epsilon;
  const real kRelative = 8.0f / 8388608.0f;
  real m = MaxF(MaxComponent(Abs3(p)), scale);
  return p + n * (scene_epsilon + kRelative * m);
}

#endif  // RT_RAY_H
