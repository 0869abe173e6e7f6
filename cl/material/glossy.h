// The course's glossy reflection (and frosted refraction): the ideal direction r is moved
// within a square of edge `roughness` spanned by an orthonormal basis around r.
#ifndef RT_MATERIAL_GLOSSY_H
#define RT_MATERIAL_GLOSSY_H

#include "../features.h"
#include "../sampling/sampler.h"
#include "../scene_types.h"

RT_DEVICE real3 PerturbDirection(real3 r, real roughness, real2 xi) {
  real3 u, v;
  CoordinateSystem(r, &u, &v);
  return Normalize(r + (u * (xi.x - 0.5f) + v * (xi.y - 0.5f)) * roughness);
}

// r itself for a smooth material, else r perturbed with the ray's glossy sample. Inlined
// in the kernel: out of line, PoCL made it a call per reflected or refracted ray that
// copied the sampler.
RT_KERNEL_INLINE real3 GlossyDirection(RT_PRIVATE const SceneData* sd, RT_PRIVATE const Material* m,
                                       real3 r, RaySampler rs) {
  if (!RT_HAS(sd, RT_FEATURE_ROUGHNESS) || m->roughness <= 0.0f) return r;
  return PerturbDirection(r, m->roughness, RaySample2D(&rs, RT_DIM_GLOSSY));
}

#endif  // RT_MATERIAL_GLOSSY_H
