// Glass and water: exact dielectric Fresnel, refraction, and Beer-Lambert absorption
// inside (applied by Li over the distance a ray travels with inside = 1).
#ifndef RT_MATERIAL_DIELECTRIC_H
#define RT_MATERIAL_DIELECTRIC_H

#include "../integrator/ray_tree.h"
#include "../surface.h"
#include "fresnel.h"
#include "glossy.h"

// Either both rays are followed, weighted by Fresnel (the course's splitting), or one is
// chosen with probability Fresnel (RT_FLAG_FRESNEL_CHOICE: unbiased, one ray per bounce).
// `s` faces the side the ray came from; s->front tells whether that is outside.
RT_DEVICE void ScatterDielectric(RT_PRIVATE const SceneData* sd, RT_PRIVATE const Material* m,
                                 RT_PRIVATE const SurfacePoint* s, RT_PRIVATE const RayTask* task,
                                 RaySampler rs, RT_PRIVATE RayStack* stack) {
  int front = s->front;
  real cos_o = Dot(s->n, s->wo);
  real eta_i = front ? 1.0f : m->refraction_index;
  real eta_t = front ? m->refraction_index : 1.0f;
  real cos_t;
  real fr = FrDielectric(fmax(cos_o, RT_R(0.0)), eta_i, eta_t, &cos_t);
  int choose = (sd->header->flags & RT_FLAG_FRESNEL_CHOICE) != 0;
  real pick = choose ? RaySample1D(rs, 4u) : 0.0f;
  int do_reflect = !choose || pick < fr;
  int do_refract = fr < 1.0f && (!choose || pick >= fr);
  real3 w = task->weight;
  if (do_reflect) {
    real3 r = GlossyDirection(sd, m, Reflect(s->wo, s->n), rs);
    PushRay(stack, ChildTask(task, SpawnRay(sd, s, r, 0), choose ? w : w * fr,
                             front ? Vec3(0.0f) : task->medium, RT_CHILD_REFLECTED, !front));
  }
  if (do_refract) {
    // Roughness frosts the glass too: the course's images blur what is seen through it.
    RaySampler frost = rs;
    frost.key = HashCombine(rs.key, 3u);
    real3 t = GlossyDirection(sd, m, Refract(-s->wo, s->n, eta_i / eta_t, cos_o, cos_t), frost);
    PushRay(stack,
            ChildTask(task, SpawnRay(sd, s, t, 1), choose ? w : w * (1.0f - fr),
                      front ? ToReal3(m->absorption) : Vec3(0.0f), RT_CHILD_REFRACTED, front));
  }
}

#endif  // RT_MATERIAL_DIELECTRIC_H
