// Materials as one dispatch point. At a hit, EvaluateMaterial gathers the material's
// parameters at the surface point (pbrt-v4's Material::GetBxDF); direct lighting reflects
// light through them (EvaluateBsdf) and Scatter pushes the rays the material spawns, one
// function per type in this folder (pbrt-v4's BxDF::Sample_f; Cycles' closure/bsdf.h).
#ifndef RT_MATERIAL_H
#define RT_MATERIAL_H

#include "../texture/texturing.h"
#include "blinn_phong.h"
#include "brdf.h"
#include "bsdf_sample.h"
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
RT_DEVICE int IsTransmissiveType(RT_PRIVATE const SceneData* sd, int type) {
  return RT_HAS(sd, RT_MATERIAL_DIELECTRIC) && type == RT_MATERIAL_DIELECTRIC;
}

RT_DEVICE int IsTransmissive(RT_PRIVATE const SceneData* sd, RT_PRIVATE const Material* m) {
  return IsTransmissiveType(sd, m->type);
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

// 1 for the materials whose scattering is a delta lobe (mirror, conductor, dielectric).
RT_DEVICE int HasSpecularLobe(RT_PRIVATE const SceneData* sd, RT_PRIVATE const Material* m) {
  int specular = IsTransmissive(sd, m);
  if (RT_HAS(sd, RT_MATERIAL_MIRROR)) specular |= m->type == RT_MATERIAL_MIRROR;
  if (RT_HAS(sd, RT_MATERIAL_CONDUCTOR)) specular |= m->type == RT_MATERIAL_CONDUCTOR;
  return specular;
}

// The probability that the path tracer follows the reflection model (kd, ks: the part
// that light sampling can reach) rather than the delta lobe. Mirrors, conductors and
// dielectrics keep the course's Blinn-Phong or BRDF part beside their delta lobe, as the
// ray tree shades them; the share is in proportion to the largest reflectance of each,
// and 0 on the inner side of a dielectric, which no light reaches directly (as in Li).
RT_DEVICE real ReflectionShare(RT_PRIVATE const SceneData* sd, RT_PRIVATE const Material* m,
                               RT_PRIVATE const SurfacePoint* s) {
  if (!HasSpecularLobe(sd, m)) return 1.0f;
  if (IsTransmissive(sd, m) && !s->front) return 0.0f;
  real g = MaxComponent(ToReal3(m->diffuse)) + MaxComponent(ToReal3(m->specular));
  if (!(g > 0.0f)) return 0.0f;
  real d = IsTransmissive(sd, m) ? 1.0f : MaxComponent(ToReal3(m->mirror));
  return g / (g + d);
}

// A direction of the reflection model drawn uniformly or, with `importance`,
// cosine-weighted (bsdf_sample.h), with weight f cos / pdf.
RT_DEVICE BsdfSample SampleReflectionLobe(RT_PRIVATE const SceneData* sd,
                                          RT_PRIVATE const Material* m,
                                          RT_PRIVATE const SurfacePoint* s, RaySampler rs,
                                          int importance) {
  real pdf;
  real3 wi = SampleReflectionDirection(s, RaySample2D(&rs, RT_DIM_BSDF_DIRECTION), importance, &pdf);
  real cos_i = Dot(wi, s->n);
  // A direction below the geometric surface would leak through it.
  if (!(pdf > 0.0f) || !(cos_i > 0.0f) || Dot(wi, s->ng) <= 0.0f) return NoBsdfSample();
  real3 f_cos = EvaluateBsdf(sd, m, s->n, s->wo, wi, Vec3(1.0f));
  BsdfSample bs = NoBsdfSample();
  bs.wi = wi;
  bs.weight = f_cos * (1.0f / pdf);
  bs.brdf = f_cos * (1.0f / cos_i);
  bs.valid = 1;
  return bs;
}

// Lobe `lobe` (RT_LOBE_*) of the material at s (normals facing s->wo) with its full
// weight, for a path that splits into every lobe as the course's recursive renderer
// does; not valid where the material has no such lobe.
RT_DEVICE BsdfSample SampleBsdfLobe(RT_PRIVATE const SceneData* sd, RT_PRIVATE const Material* m,
                                    RT_PRIVATE const SurfacePoint* s, RaySampler rs, int importance,
                                    int lobe) {
  if (lobe == RT_LOBE_REFLECTION)
    return ReflectionShare(sd, m, s) > 0.0f ? SampleReflectionLobe(sd, m, s, rs, importance)
                                            : NoBsdfSample();
  if (RT_HAS(sd, RT_MATERIAL_DIELECTRIC) && m->type == RT_MATERIAL_DIELECTRIC)
    return SampleDielectric(sd, m, s, rs, lobe == RT_LOBE_SPECULAR_TRANSMISSION, 0);
  if (lobe == RT_LOBE_SPECULAR_TRANSMISSION) return NoBsdfSample();
  if (RT_HAS(sd, RT_MATERIAL_MIRROR) && m->type == RT_MATERIAL_MIRROR)
    return SampleMirror(sd, m, s, rs);
  if (RT_HAS(sd, RT_MATERIAL_CONDUCTOR) && m->type == RT_MATERIAL_CONDUCTOR)
    return SampleConductor(sd, m, s, rs);
  return NoBsdfSample();
}

// One continuation of a path at s, pbrt-v4's BSDF::Sample_f: the delta lobes with
// probability 1 - ReflectionShare (a dielectric's two chosen by Fresnel), else the
// reflection model; the weight is divided by the probability of the choice.
RT_DEVICE BsdfSample SampleBsdf(RT_PRIVATE const SceneData* sd, RT_PRIVATE const Material* m,
                                RT_PRIVATE const SurfacePoint* s, RaySampler rs, int importance) {
  real share = ReflectionShare(sd, m, s);
  BsdfSample bs;
  if (share < 1.0f && (share <= 0.0f || RaySample1D(&rs, RT_DIM_BSDF_LOBE) >= share)) {
    if (RT_HAS(sd, RT_MATERIAL_DIELECTRIC) && m->type == RT_MATERIAL_DIELECTRIC)
      bs = SampleDielectric(sd, m, s, rs, 0, 1);
    else
      bs = SampleBsdfLobe(sd, m, s, rs, importance, RT_LOBE_SPECULAR_REFLECTION);
    bs.weight = bs.weight * (1.0f / (1.0f - share));
  } else {
    bs = SampleReflectionLobe(sd, m, s, rs, importance);
    bs.weight = bs.weight * (1.0f / share);
  }
  return bs;
}

#endif  // RT_MATERIAL_H
