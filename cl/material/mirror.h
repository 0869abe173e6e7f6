// A perfect (or, with roughness, glossy) mirror of reflectance MirrorReflectance.
#ifndef RT_MATERIAL_MIRROR_H
#define RT_MATERIAL_MIRROR_H

#include "../integrator/ray_tree.h"
#include "../surface.h"
#include "bsdf_sample.h"
#include "glossy.h"

// The reflected direction at s (facing the incoming ray), perturbed by the roughness.
RT_DEVICE real3 MirrorDirection(RT_PRIVATE const SceneData* sd, RT_PRIVATE const Material* m,
                                RT_PRIVATE const SurfacePoint* s, RaySampler rs) {
  return GlossyDirection(sd, m, Reflect(s->wo, s->n), rs);
}

RT_DEVICE void ScatterMirror(RT_PRIVATE const SceneData* sd, RT_PRIVATE const Material* m,
                             RT_PRIVATE const SurfacePoint* s, RT_PRIVATE const RayTask* task,
                             RaySampler rs, RT_PRIVATE RayStack* stack) {
  real3 r = MirrorDirection(sd, m, s, rs);
  PushRay(stack, ChildTask(task, SpawnRay(sd, s, r, 0), task->weight * ToReal3(m->mirror),
                           task->medium, RT_CHILD_REFLECTED, 0));
}

RT_DEVICE BsdfSample SampleMirror(RT_PRIVATE const SceneData* sd, RT_PRIVATE const Material* m,
                                  RT_PRIVATE const SurfacePoint* s, RaySampler rs) {
  return SpecularBsdfSample(MirrorDirection(sd, m, s, rs), ToReal3(m->mirror), 0);
}

#endif  // RT_MATERIAL_MIRROR_H
