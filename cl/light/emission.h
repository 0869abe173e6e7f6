// What a path finds when it hits an object light (LightMesh, LightSphere), for any
// integrator: the radiance the surface emits back along the ray, and the density with
// which sampling that light (SampleLight) would have chosen the same point, for weighting
// a hit against a light sample.
#ifndef RT_LIGHT_EMISSION_H
#define RT_LIGHT_EMISSION_H

#include "../features.h"
#include "../geometry/surface.h"
#include "mesh_light.h"
#include "sphere_light.h"

// The index in sd->lights of the object light the hit instance is, or -1.
RT_DEVICE int HitLightIndex(RT_PRIVATE const SceneData* sd, Hit hit) {
  if (!RT_HAS(sd, RT_FEATURE_OBJECT_LIGHTS) || hit.instance < 0) return -1;
  return sd->instance_lights[hit.instance];
}

// Radiance leaving s along s->wo: the light's radiance on its emitting side (the front of
// a mesh's faces, the outside of a sphere), else none. s must not be face-forwarded yet.
RT_DEVICE real3 EmittedRadiance(RT_PRIVATE const SceneData* sd, RT_PRIVATE const SurfacePoint* s) {
  int l = HitLightIndex(sd, s->hit);
  if (l < 0 || !s->front) return Vec3(0.0f);
  return ToReal3(sd->lights[l].emission);
}

// The solid-angle density with which SampleLight, from the point p, picks the point s of
// the object light s lies on; 0 for a point it never picks (another object, a face turned
// away from p). s must not be face-forwarded yet. It is the emitter's side of multiple
// importance sampling (weighing a BSDF-sampled hit of a light against light sampling,
// LightSample.pdf; cl/integrator/mis.h); the tests check it against sampling.
RT_DEVICE real EmitterPdf(RT_PRIVATE const SceneData* sd, real3 p,
                          RT_PRIVATE const SurfacePoint* s) {
  int l = HitLightIndex(sd, s->hit);
  if (l < 0) return 0.0f;
  RT_GLOBAL const Light* light = &sd->lights[l];
  if (RT_HAS(sd, RT_LIGHT_MESH) && light->type == RT_LIGHT_MESH)
    return MeshLightPdf(light, p, s->p, s->ng);
  if (RT_HAS(sd, RT_LIGHT_SPHERE) && light->type == RT_LIGHT_SPHERE)
    return SphereLightPdf(sd, light, p, s->p);
  return 0.0f;
}

#endif  // RT_LIGHT_EMISSION_H
