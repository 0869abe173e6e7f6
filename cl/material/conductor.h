// A metal: a mirror whose reflectance is scaled by the conductor Fresnel term of its
// complex index RefractionIndex + i AbsorptionIndex.
#ifndef RT_MATERIAL_CONDUCTOR_H
#define RT_MATERIAL_CONDUCTOR_H

#include "../geometry/surface.h"
#include "fresnel.h"
#include "mirror.h"

RT_DEVICE real ConductorFresnel(RT_PRIVATE const Material* m, RT_PRIVATE const SurfacePoint* s) {
  // MaxF, not fmax, as in DielectricFresnel.
  return FrConductor(MaxF(Dot(s->n, s->wo), RT_R(0.0)), m->refraction_index, m->absorption_index);
}

// The conductor's one lobe at s (facing the incoming ray).
RT_DEVICE BsdfSample SampleConductor(RT_PRIVATE const SceneData* sd, RT_PRIVATE const Material* m,
                                     RT_PRIVATE const SurfacePoint* s, RaySampler rs) {
  return SpecularBsdfSample(MirrorDirection(sd, m, s, rs), ToReal3(m->mirror),
                            ConductorFresnel(m, s), 0);
}

#endif  // RT_MATERIAL_CONDUCTOR_H
