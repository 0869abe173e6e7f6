// A perfect (or, with roughness, glossy) mirror of reflectance MirrorReflectance.
#ifndef RT_MATERIAL_MIRROR_H
#define RT_MATERIAL_MIRROR_H

#include "../geometry/surface.h"
#include "bsdf_sample.h"
#include "glossy.h"

// The reflected direction at s (facing the incoming ray), perturbed by the roughness.
// Inlined in the kernel: conductors and dielectrics call it too, and out of line each call
// copied the sampler.
RT_KERNEL_INLINE real3 MirrorDirection(RT_PRIVATE const SceneData* sd, RT_PRIVATE const Material* m,
                                       RT_PRIVATE const SurfacePoint* s, RaySampler rs) {
  return GlossyDirection(sd, m, Reflect(s->wo, s->n), rs);
}

// The mirror's one lobe at s (facing the incoming ray).
RT_DEVICE BsdfSample SampleMirror(RT_PRIVATE const SceneData* sd, RT_PRIVATE const Material* m,
                                  RT_PRIVATE const SurfacePoint* s, RaySampler rs) {
  return SpecularBsdfSample(MirrorDirection(sd, m, s, rs), ToReal3(m->mirror), 1.0f, 0);
}

#endif  // RT_MATERIAL_MIRROR_H
