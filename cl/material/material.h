// Materials as one dispatch point. At a hit, EvaluateMaterial gathers the material's
// parameters at the surface point (pbrt-v4's Material::GetBxDF); direct lighting reflects
// light through them (EvaluateBsdf), and both integrators continue through the lobes
// SampleDeltaLobes and SampleReflectionLobe return, one sampling function per type in this
// folder (pbrt-v4's BxDF::Sample_f; Cycles' bsdf_sample): the ray tree follows every delta
// lobe, the path tracer splits into the lobes or picks one (SampleBsdf).
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

// The delta lobes of the material at s (normals facing s->wo) into lobes[] (room for
// RT_DELTA_LOBES), reflection before refraction; returns how many: none for plain
// Blinn-Phong surfaces. `choose`: a dielectric returns one lobe, picked by Fresnel.
RT_DEVICE int SampleDeltaLobes(RT_PRIVATE const SceneData* sd, RT_PRIVATE const Material* m,
                               RT_PRIVATE const SurfacePoint* s, RaySampler rs, int choose,
                               RT_PRIVATE BsdfSample* lobes) {
  if (RT_HAS(sd, RT_MATERIAL_MIRROR) && m->type == RT_MATERIAL_MIRROR) {
    lobes[0] = SampleMirror(sd, m, s, rs);
    return 1;
  }
  if (RT_HAS(sd, RT_MATERIAL_CONDUCTOR) && m->type == RT_MATERIAL_CONDUCTOR) {
    lobes[0] = SampleConductor(sd, m, s, rs);
    return 1;
  }
  if (RT_HAS(sd, RT_MATERIAL_DIELECTRIC) && m->type == RT_MATERIAL_DIELECTRIC)
    return SampleDielectric(sd, m, s, rs, choose, lobes);
  return 0;
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
  real3 wi =
      SampleReflectionDirection(s, RaySample2D(&rs, RT_DIM_BSDF_DIRECTION), importance, &pdf);
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

// Every lobe of the material at s (normals facing s->wo) into lobes[] (room for
// RT_LOBE_COUNT) with its full weight, for a path that splits into every lobe as the
// course's recursive renderer does: the reflection model where ReflectionShare is not 0,
// then the delta lobes. Returns how many.
RT_DEVICE int SampleBsdfLobes(RT_PRIVATE const SceneData* sd, RT_PRIVATE const Material* m,
                              RT_PRIVATE const SurfacePoint* s, RaySampler rs, int importance,
                              RT_PRIVATE BsdfSample* lobes) {
  int n = 0;
  if (ReflectionShare(sd, m, s) > 0.0f) {
    lobes[0] = SampleReflectionLobe(sd, m, s, rs, importance);
    n = lobes[0].valid;
  }
  return n + SampleDeltaLobes(sd, m, s, rs, 0, lobes + n);
}

// One continuation of a path at s, pbrt-v4's BSDF::Sample_f: the delta lobes with
// probability 1 - ReflectionShare (a dielectric's two chosen by Fresnel), else the
// reflection model; the weight is divided by the probability of the choice.
RT_DEVICE BsdfSample SampleBsdf(RT_PRIVATE const SceneData* sd, RT_PRIVATE const Material* m,
                                RT_PRIVATE const SurfacePoint* s, RaySampler rs, int importance) {
  real share = ReflectionShare(sd, m, s);
  BsdfSample bs;
  if (share < 1.0f && (share <= 0.0f || RaySample1D(&rs, RT_DIM_BSDF_LOBE) >= share)) {
    BsdfSample delta[RT_DELTA_LOBES];
    bs = SampleDeltaLobes(sd, m, s, rs, 1, delta) > 0 ? delta[0] : NoBsdfSample();
    bs.weight = bs.weight * (1.0f / (1.0f - share));
  } else {
    bs = SampleReflectionLobe(sd, m, s, rs, importance);
    bs.weight = bs.weight * (1.0f / share);
  }
  return bs;
}

// The solid-angle density with which SampleBsdf draws the direction wi at s (normals facing
// s->wo): the reflection model's density (ReflectionDirectionPdf) times the probability of
// choosing it; none below the geometric surface, which SampleReflectionLobe never returns,
// and none from the delta lobes, which hit wi with probability 0. The path tracer's
// multiple importance sampling weighs light samples and bounces by it (cl/integrator/mis.h).
RT_DEVICE real BsdfPdf(RT_PRIVATE const SceneData* sd, RT_PRIVATE const Material* m,
                       RT_PRIVATE const SurfacePoint* s, real3 wi, int importance) {
  real share = ReflectionShare(sd, m, s);
  real cos_i = Dot(wi, s->n);
  if (!(share > 0.0f) || !(cos_i > 0.0f) || Dot(wi, s->ng) <= 0.0f) return 0.0f;
  return share * ReflectionDirectionPdf(cos_i, importance);
}

#endif  // RT_MATERIAL_H
