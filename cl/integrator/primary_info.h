// Deterministic facts about a pixel's first camera ray, for exact comparisons; every
// integrator records them.
#ifndef RT_INTEGRATOR_PRIMARY_INFO_H
#define RT_INTEGRATOR_PRIMARY_INFO_H

#include "../ray.h"

typedef struct PrimaryInfo {
  float t;
  int instance;
  int primitive;
  float3 normal;
} PrimaryInfo;

RT_DEVICE void RecordPrimaryHit(RT_PRIVATE PrimaryInfo* info, Hit hit, float3 normal) {
  info->t = hit.t;
  info->instance = hit.instance;
  info->primitive = hit.primitive;
  info->normal = normal;
}

#endif  // RT_INTEGRATOR_PRIMARY_INFO_H
