// Deterministic facts about a pixel's first camera ray, for exact comparisons; every
// integrator records them (the struct is in ../film_types.h, in float whatever the
// precision of the computation).
#ifndef RT_INTEGRATOR_PRIMARY_INFO_H
#define RT_INTEGRATOR_PRIMARY_INFO_H

#include "../film/film_types.h"
#include "../geometry/ray.h"

// `info` is null for the samples after a pixel's first, whose facts nobody reads.
RT_DEVICE void RecordPrimaryHit(RT_PRIVATE PrimaryInfo* info, Hit hit, real3 normal) {
  if (!info) return;
  info->t = hit.t;  // Rounds to the float of the output in double.
  info->instance = hit.instance;
  info->primitive = hit.primitive;
  info->normal = ToFloat3(normal);
}

// A camera ray that hits nothing, recorded before tracing so that a miss is recorded too.
RT_DEVICE void RecordPrimaryMiss(RT_PRIVATE PrimaryInfo* info) {
  Hit none;
  none.t = RT_INFINITY;
  none.instance = -1;
  none.primitive = -1;
  RecordPrimaryHit(info, none, Vec3(0.0f));
}

#endif
