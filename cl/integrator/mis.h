// Multiple importance sampling for the path tracer's --path-estimator mis (Veach 1997,
// chapter 9; pbrt-v4's PathIntegrator): a light that a path can hit (a LightMesh, a
// LightSphere, the environment) is found both by its light sample at a vertex and by the
// bounce from that vertex, and each finding is weighed by the power heuristic (beta = 2)
// of the two densities of its direction. Every light is sampled once per vertex (no light
// is chosen), so the two strategies for light i are its own sample, of density
// LightSample.pdf, and the bounce, of density BsdfPdf; the weights of the two sum to 1 for
// every direction either can draw, so the sum stays unbiased, and where one density is
// large (a light sample near a light, weight 1 / d^2) the other strategy takes over.
// Delta lights (point, spot, directional) and the course's area lights are not geometry:
// only their light samples find them, with weight 1.
#ifndef RT_INTEGRATOR_MIS_H
#define RT_INTEGRATOR_MIS_H

#include "../light/emission.h"
#include "../light/light.h"
#include "../material/material.h"

// The power heuristic for one sample of each of two strategies of densities f (the one
// that drew the sample) and g: f^2 / (f^2 + g^2), in a form whose squares cannot overflow.
RT_DEVICE real PowerHeuristic(real f, real g) {
  if (!(f > 0.0f)) return 0.0f;
  real r = g / f;
  return 1.0f / (1.0f + r * r);
}

// 1 for the lights a ray can hit: their samples are weighed against the bounce.
RT_DEVICE int LightIsHittable(RT_PRIVATE const SceneData* sd, RT_GLOBAL const Light* light) {
  return (RT_HAS(sd, RT_LIGHT_MESH) && light->type == RT_LIGHT_MESH) ||
         (RT_HAS(sd, RT_LIGHT_SPHERE) && light->type == RT_LIGHT_SPHERE) ||
         (RT_HAS(sd, RT_LIGHT_ENVIRONMENT) && light->type == RT_LIGHT_ENVIRONMENT);
}

// The weight of the sample ls of `light` at s against the bounce that the path draws there
// (SampleBsdf, of density BsdfPdf); 1 for a light no ray can hit.
RT_DEVICE real LightSampleWeight(RT_PRIVATE const SceneData* sd, RT_GLOBAL const Light* light,
                                 LightSample ls, RT_PRIVATE const SurfacePoint* s,
                                 RT_PRIVATE const Material* m, int importance) {
  if (!ls.valid || !LightIsHittable(sd, light)) return 1.0f;
  return PowerHeuristic(ls.pdf, BsdfPdf(sd, m, s, ls.wi, importance));
}

// The weight of emission a bounce from point p (of density bsdf_pdf) finds at the object
// light point s, against that light's sample from p (s not face-forwarded yet).
RT_DEVICE real EmissionWeight(RT_PRIVATE const SceneData* sd, real3 p, real bsdf_pdf,
                              RT_PRIVATE const SurfacePoint* s) {
  return PowerHeuristic(bsdf_pdf, EmitterPdf(sd, p, s));
}

// The weight of the environment a bounce (of density bsdf_pdf) from a point of unit shading
// normal n finds along unit direction d, against the environment's light sample there.
RT_DEVICE real EnvironmentWeight(RT_PRIVATE const SceneData* sd, real3 d, real3 n, real bsdf_pdf) {
  RT_GLOBAL const Light* env = &sd->lights[sd->header->environment];
  return PowerHeuristic(bsdf_pdf, EnvironmentSamplePdf(sd, env, d, n));
}

#endif  // RT_INTEGRATOR_MIS_H
