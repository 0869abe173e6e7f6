// Glass and water: exact dielectric Fresnel, refraction, and Beer-Lambert absorption
// inside (applied by the integrators over the distance a ray travels inside).
#ifndef RT_MATERIAL_DIELECTRIC_H
#define RT_MATERIAL_DIELECTRIC_H

#include "../geometry/surface.h"
#include "bsdf_sample.h"
#include "fresnel.h"
#include "glossy.h"
#include "mirror.h"

// The two directions light takes at a dielectric's surface point and their Fresnel split.
typedef struct DielectricEvent {
  real fr;  // Reflectance; 1 under total internal reflection.
  real eta_i, eta_t, cos_o, cos_t;
} DielectricEvent;

// `s` faces the side the ray came from; s->front tells whether that is outside.
RT_DEVICE DielectricEvent DielectricFresnel(RT_PRIVATE const Material* m,
                                            RT_PRIVATE const SurfacePoint* s) {
  DielectricEvent e;
  e.cos_o = Dot(s->n, s->wo);
  e.eta_i = s->front ? 1.0f : m->refraction_index;
  e.eta_t = s->front ? m->refraction_index : 1.0f;
  // MaxF rather than fmax (a library call on the CPU): both give 0 for NaN, and -0 for +0
  // changes no bit of the reflectance, whose only use of the cosine is products and sums.
  e.fr = FrDielectric(MaxF(e.cos_o, RT_R(0.0)), e.eta_i, e.eta_t, &e.cos_t);
  return e;
}

RT_DEVICE real3 DielectricRefraction(RT_PRIVATE const SceneData* sd, RT_PRIVATE const Material* m,
                                     RT_PRIVATE const SurfacePoint* s, DielectricEvent e,
                                     RaySampler rs) {
  // Roughness frosts the glass too: the course's images blur what is seen through it.
  RaySampler frost = rs;
  frost.key = HashCombine(rs.key, RT_KEY_FROSTED_REFRACTION);
  real3 t = Refract(-s->wo, s->n, e.eta_i / e.eta_t, e.cos_o, e.cos_t);
  return GlossyDirection(sd, m, t, frost);
}

// The lobe of the reflected (or, with `transmit`, the refracted) ray of weight w.
RT_DEVICE BsdfSample DielectricLobe(RT_PRIVATE const SceneData* sd, RT_PRIVATE const Material* m,
                                    RT_PRIVATE const SurfacePoint* s, DielectricEvent e,
                                    RaySampler rs, int transmit, real w) {
  real3 wi = transmit ? DielectricRefraction(sd, m, s, e, rs) : MirrorDirection(sd, m, s, rs);
  return SpecularBsdfSample(wi, Vec3(1.0f), w, transmit);
}

// The dielectric's lobes at s (facing the incoming ray) into lobes[], the reflected ray
// before the refracted one; returns how many. Either both, weighted by Fresnel (the
// course's splitting), or, with `choose`, the one picked with the Fresnel probability, of
// weight 1 (pbrt-v4's DielectricBxDF::Sample_f: unbiased, one ray per bounce). A ray of
// weight 0 (no refraction under total internal reflection) is left out.
RT_DEVICE int SampleDielectric(RT_PRIVATE const SceneData* sd, RT_PRIVATE const Material* m,
                               RT_PRIVATE const SurfacePoint* s, RaySampler rs, int choose,
                               RT_PRIVATE BsdfSample* lobes) {
  DielectricEvent e = DielectricFresnel(m, s);
  if (choose) {
    lobes[0] =
        DielectricLobe(sd, m, s, e, rs, RaySample1D(&rs, RT_DIM_FRESNEL_CHOICE) >= e.fr, 1.0f);
    return 1;
  }
  int n = 0;
  if (e.fr > 0.0f) lobes[n++] = DielectricLobe(sd, m, s, e, rs, 0, e.fr);
  if (1.0f - e.fr > 0.0f) lobes[n++] = DielectricLobe(sd, m, s, e, rs, 1, 1.0f - e.fr);
  return n;
}

#endif  // RT_MATERIAL_DIELECTRIC_H
