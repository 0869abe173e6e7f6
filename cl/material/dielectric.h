// Glass and water: exact dielectric Fresnel, refraction, and Beer-Lambert absorption
// inside (applied by the integrators over the distance a ray travels inside).
#ifndef RT_MATERIAL_DIELECTRIC_H
#define RT_MATERIAL_DIELECTRIC_H

#include "../integrator/ray_tree.h"
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
  frost.key = HashCombine(rs.key, 3u);
  real3 t = Refract(-s->wo, s->n, e.eta_i / e.eta_t, e.cos_o, e.cos_t);
  return GlossyDirection(sd, m, t, frost);
}

// Either both rays are followed, weighted by Fresnel (the course's splitting), or one is
// chosen with probability Fresnel (RT_FLAG_FRESNEL_CHOICE: unbiased, one ray per bounce).
RT_DEVICE void ScatterDielectric(RT_PRIVATE const SceneData* sd, RT_PRIVATE const Material* m,
                                 RT_PRIVATE const SurfacePoint* s, RT_PRIVATE const RayTask* task,
                                 RaySampler rs, RT_PRIVATE RayStack* stack) {
  int front = s->front;
  DielectricEvent e = DielectricFresnel(m, s);
  real fr = e.fr;
  int choose = (sd->header->flags & RT_FLAG_FRESNEL_CHOICE) != 0;
  real pick = choose ? RaySample1D(&rs, RT_DIM_FRESNEL_CHOICE) : 0.0f;
  int do_reflect = !choose || pick < fr;
  int do_refract = fr < 1.0f && (!choose || pick >= fr);
  real3 w = task->weight;
  if (do_reflect) {
    real3 r = MirrorDirection(sd, m, s, rs);
    PushRay(stack, ChildTask(task, SpawnRay(sd, s, r, 0), choose ? w : w * fr,
                             front ? Vec3(0.0f) : task->medium, RT_CHILD_REFLECTED, !front));
  }
  if (do_refract) {
    real3 t = DielectricRefraction(sd, m, s, e, rs);
    PushRay(stack,
            ChildTask(task, SpawnRay(sd, s, t, 1), choose ? w : w * (1.0f - fr),
                      front ? ToReal3(m->absorption) : Vec3(0.0f), RT_CHILD_REFRACTED, front));
  }
}

// One of the two rays for the path tracer: the reflected one (weight Fresnel) or the
// refracted one (1 - Fresnel), both when it splits the path as the course's renderer
// does; with `choose`, one picked with the Fresnel probability, of weight 1 (pbrt-v4's
// DielectricBxDF::Sample_f). A ray of weight 0 (no refraction under total internal
// reflection) is not valid.
RT_DEVICE BsdfSample SampleDielectric(RT_PRIVATE const SceneData* sd, RT_PRIVATE const Material* m,
                                      RT_PRIVATE const SurfacePoint* s, RaySampler rs, int transmit,
                                      int choose) {
  DielectricEvent e = DielectricFresnel(m, s);
  if (choose) transmit = RaySample1D(&rs, RT_DIM_FRESNEL_CHOICE) >= e.fr;
  real w = choose ? 1.0f : (transmit ? 1.0f - e.fr : e.fr);
  if (!(w > 0.0f)) return NoBsdfSample();
  real3 wi = transmit ? DielectricRefraction(sd, m, s, e, rs) : MirrorDirection(sd, m, s, rs);
  return SpecularBsdfSample(wi, Vec3(w), transmit);
}

#endif  // RT_MATERIAL_DIELECTRIC_H
