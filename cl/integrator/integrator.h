// The per-sample integrators: Whitted-style recursion (mirrors, conductors, dielectrics
// with Fresnel and Beer's law) extended with the distribution effects of the course's
// third assignment, over the explicit ray tree of ray_tree.h; and, for cameras that ask
// for it, the path tracer of path.h.
#ifndef RT_INTEGRATOR_H
#define RT_INTEGRATOR_H

#include "../bvh/intersect.h"
#include "../camera/camera.h"
#include "../film/film_types.h"
#include "../geometry/surface.h"
#include "../light/emission.h"
#include "../material/material.h"
#include "direct_lighting.h"
#include "escaped.h"
#include "path.h"
#include "primary_info.h"
#include "ray_tree.h"

// What shading reads of the surface point of `hit` (RT_SURFACE_* parts). A last hit (no ray
// continues from it) in a scene without lights, textures or emitters is lit by the ambient
// term alone, which reads the material only; it needs the normals where the primary-hit
// facts are recorded (`record`) or where a transmissive surface must know its side.
RT_DEVICE int SurfacePartsRead(RT_PRIVATE const SceneData* sd, RT_PRIVATE const RayTask* task,
                               int max_depth, Hit hit, int record) {
  if (task->depth < max_depth || sd->header->num_lights > 0 ||
      RT_HAS(sd, RT_FEATURE_TEXTURES | RT_FEATURE_OBJECT_LIGHTS))
    return RT_SURFACE_ALL;
  int material = sd->instances[hit.instance].material;
  if (record || IsTransmissiveType(sd, sd->materials[material].type)) return RT_SURFACE_NORMALS;
  return 0;
}

// Radiance along the camera ray of `cs` through the film at pixel_uv (where a background
// texture is looked up); *rays counts every ray cast (camera, secondary, shadow).
// Per ray of the tree: intersect, build the surface point, attenuate inside a medium,
// evaluate the material, add direct light, scatter.
RT_DEVICE_INLINE real3 Li(RT_PRIVATE const SceneData* sd, RT_PRIVATE const CameraSample* cs,
                          real2 pixel_uv, RT_PRIVATE PrimaryInfo* info, RT_PRIVATE uint* rays) {
  RT_GLOBAL const SceneHeader* h = sd->header;
  int max_depth = h->max_depth < RT_TREE_DEPTH ? h->max_depth : RT_TREE_DEPTH;
  RayStack stack;
  stack.size = 0;
  // The camera ray is the first task; later ones come from the stack (NextRay).
  RayTask task = MakeTask(cs->ray, Vec3(1.0f), Vec3(0.0f), RT_DIM_FIRST_FREE, 0, 0);
  real3 radiance = Vec3(0.0f);
  RecordPrimaryMiss(info);
  do {
    Hit hit;
    *rays += 1u;
    int cull = (h->flags & RT_FLAG_CULL_BACK_FACES) != 0 && task.depth == 0;
    // The camera ray is read from the sample rather than from the task just built from it:
    // the task's copy was stored a few instructions earlier by stores narrower than the
    // loads that pass it on, and such a load waits for those stores to retire (failed
    // store-to-load forwarding).
    if (!IntersectClosest(sd, task.depth == 0 ? cs->ray : task.ray, cull, &hit)) {
      if (EscapedRaySees(sd, task.depth))
        radiance += task.weight * EscapedRadiance(sd, task.ray.direction, pixel_uv);
      continue;
    }
    int record = info != 0 && task.depth == 0;
    int parts = SurfacePartsRead(sd, &task, max_depth, hit, record);
    if (RT_HAS(sd, RT_FEATURE_DIELECTRIC) && task.inside)
      task.weight = task.weight * BeerLambert(task.medium, hit.t * Length(task.ray.direction), 1);
    if (parts == 0) {
      // A last hit lit by the ambient term alone (SurfacePartsRead), as DirectLighting would
      // light it: neither the surface point nor a copy of the material is made.
      int material = sd->instances[hit.instance].material;
      radiance += task.weight * AmbientRadiance(sd, sd->materials[material].ambient);
      continue;
    }
    SurfacePoint s = ComputeSurfaceParts(sd, &task.ray, &hit, parts);
    if (record) RecordPrimaryHit(info, hit, s.n);
    // An object light seen by this ray (a camera ray, or one a mirror or glass continued).
    if (RT_HAS(sd, RT_FEATURE_OBJECT_LIGHTS)) radiance += task.weight * EmittedRadiance(sd, &s);
    Material m = EvaluateMaterial(sd, &s);
    RaySampler rs = MakeRaySampler(cs->key, task.key, task.depth == 0);
    // Opaque surfaces are shaded with the normal as modelled, also when seen from behind,
    // as the course's renderer does: thin sheets such as grass blades are lit from either
    // side. No light reaches the inner side of a dielectric directly.
    if (!IsTransmissive(sd, &m) || s.front)
      radiance += task.weight * DirectLighting(sd, &s, &m, rs, rays);
    if (task.depth >= max_depth) continue;
    FaceForward(&s);
    Scatter(sd, &m, &s, &task, rs, &stack);
  } while (NextRay(&stack, &task));
  return radiance;
}

// The radiance of camera sample `cs` (GeneratePixelSample) of pixel `cp`, and its
// reconstruction-filter weight in *weight. `info` (may be null) receives the facts of the
// first camera ray.
RT_DEVICE_INLINE real3 RenderSample(RT_PRIVATE const SceneData* sd,
                                    RT_PRIVATE const CameraPixel* cp,
                                    RT_PRIVATE const CameraSample* cs, RT_PRIVATE real* weight,
                                    RT_PRIVATE PrimaryInfo* info, RT_PRIVATE uint* rays) {
  RT_GLOBAL const SceneHeader* h = sd->header;
  *weight = 1.0f;
  if (h->filter == RT_FILTER_GAUSSIAN) {
    // util/transcendental.h's exponential, which both devices round alike: glibc's expf and
    // PoCL's exp differ in the last bit for some of these arguments.
    real dx = cs->film.x - 0.5f, dy = cs->film.y - 0.5f;
    *weight = Exp(-(dx * dx + dy * dy) / (2.0f * h->filter_sigma * h->filter_sigma));
  }
#if RT_COMPILED(RT_FEATURE_PATH_TRACING)
  if (RT_HAS(sd, RT_FEATURE_PATH_TRACING) && (h->flags & RT_FLAG_PATH_TRACING) != 0)
    return PathLi(sd, cs->key, cs->ray, cp->uv, info, rays);
#endif
  return Li(sd, cs, cp->uv, info, rays);
}

#endif  // RT_INTEGRATOR_H
