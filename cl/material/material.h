// Materials as one dispatch point. At a hit, EvaluateMaterial gathers the material's
// parameters at the surface point (pbrt-v4's Material::GetBxDF); direct lighting reflects
// light through them (EvaluateBsdf) and Scatter pushes the rays the material spawns, one
// function per type in this folder (pbrt-v4's BxDF::Sample_f; Cycles' closure/bsdf.h).
#ifndef RT_MATERIAL_H
#define RT_MATERIAL_H

#include "../texture/texturing.h"
#include "blinn_phong.h"
#include "brdf.h"
#include "conductor.h"
#include "dielectric.h"
#include "mirror.h"

// The parameters shading reads at this point, as a private copy: textures replace values
// here (diffuse and specular from texels) and perturb s->n, and nothing downstream changes.
RT_DEVICE Material EvaluateMaterial(RT_PRIVATE const SceneData* sd, RT_PRIVATE SurfacePoint* s) {
  Material m = sd->materials[s->material];
  if (RT_HAS(sd, RT_FEATURE_TEXTURES)) ApplyTextures(sd, s, &m);
  return m;
}

// The hw6 reflection model of a material (BRDF="id"): its kd, ks, exponent and complex index.
RT_DEVICE BrdfParams MaterialBrdf(RT_PRIVATE const Material* m) {
  BrdfParams b;
  b.kd = ToReal3(m->diffuse);
  b.ks = ToReal3(m->specular);
  b.exponent = m->phong_exponent;
  b.model = m->brdf;
  b.flags = m->brdf_flags;
  b.eta = m->refraction_index;
  b.kappa = m->absorption_index;
  return b;
}

// Light of irradiance e arriving from wi, reflected towards wo: the course's Blinn-Phong, or
// the material's BRDF of assignment 6 (whose original Blinn-Phong is the same shading).
RT_DEVICE real3 EvaluateBsdf(RT_PRIVATE const SceneData* sd, RT_PRIVATE const Material* m, real3 n,
                             real3 wo, real3 wi, real3 e) {
  if (RT_HAS(sd, RT_FEATURE_BRDF) && m->brdf != RT_BRDF_ORIGINAL_BLINN_PHONG) {
    BrdfParams b = MaterialBrdf(m);
    return BrdfFCos(&b, n, wo, wi) * e;
  }
  return BlinnPhong(m, n, wo, wi, e);
}

// 1 for materials light passes through: no light reaches their inner side directly.
RT_DEVICE int IsTransmissive(RT_PRIVATE const SceneData* sd, RT_PRIVATE const Material* m) {
  return RT_HAS(sd, RT_MATERIAL_DIELECTRIC) && m->type == RT_MATERIAL_DIELECTRIC;
}

// Pushes the rays the material sends on from s (facing the incoming ray); plain
// Blinn-Phong surfaces send none.
RT_DEVICE void Scatter(RT_PRIVATE const SceneData* sd, RT_PRIVATE const Material* m,
                       RT_PRIVATE const SurfacePoint* s, RT_PRIVATE const RayTask* task,
                       RaySampler rs, RT_PRIVATE RayStack* stack) {
  if (RT_HAS(sd, RT_MATERIAL_MIRROR) && m->type == RT_MATERIAL_MIRROR)
    ScatterMirror(sd, m, s, task, rs, stack);
  else if (RT_HAS(sd, RT_MATERIAL_CONDUCTOR) && m->type == RT_MATERIAL_CONDUCTOR)
    ScatterConductor(sd, m, s, task, rs, stack);
  else if (RT_HAS(sd, RT_MATERIAL_DIELECTRIC) && m->type == RT_MATERIAL_DIELECTRIC)
    ScatterDielectric(sd, m, s, task, rs, stack);
}

#endif  // RT_MATERIAL_H
