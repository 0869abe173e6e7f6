// The path tracer of the course's assignment 6 (hw6/SPEC.txt, section 3.3), chosen per
// camera by <Renderer>PathTracing</Renderer>, after pbrt-v4's PathIntegrator, with the
// conventions the course's reference images show (docs/path_tracing.md has the evidence).
//
// A camera sample follows one path in a loop (no recursion in OpenCL C) with its weight.
// Each vertex takes four steps, as Cycles' integrate_surface: emission (what the surface
// emits), light samples (with NextEventEstimation, one sample of every light through the
// reflection model), survival (the bound on bounces, or Russian roulette) and continuation
// along the material's lobes:
// one direction of the reflection model (uniform over the hemisphere, or shaped by the
// BRDF with ImportanceSampling), the delta lobes of mirrors, conductors and dielectrics.
// Like the course's recursive renderer, a path splits where a material has more than one
// lobe (a dielectric's reflection and refraction, weighted by Fresnel, and its Phong
// part): the other branches wait on a small stack, and when it is full the path picks
// one lobe at random instead (unbiased either way).
//
// With next-event estimation, light reached by a non-specular bounce was already counted
// by the light sample at the vertex before, so its emission is left out there (the
// specification's "discard its contribution"); the camera ray and rays after a delta lobe
// count it, since light sampling cannot reach them.
//
// Bounces: MaxRecursionDepth bounds the scatterings of a path, so emission is found by at
// most MaxRecursionDepth + 1 segments; light samples are taken at every vertex, the last
// one included, so next-event estimation reaches one bounce further, as the course's
// references show (glass_next.exr is 5.0 % brighter than glass.exr: the share of the
// fourth bounce). RussianRoulette replaces the bound, as the course's references do
// ("only the direct application of Russian roulette"); see RouletteSurvives.
//
// --path-estimator mis (RT_FLAG_MIS) changes three of these conventions: with next-event
// estimation, emission and the environment that a non-specular bounce finds count too,
// weighed against the light samples by multiple importance sampling (mis.h); the bounce
// from the last vertex is still traced, to collect the emission it finds (as Cycles'
// last bounce), so that both strategies reach the same MaxRecursionDepth + 1 scatterings;
// and a path follows one lobe per vertex, with pbrt-v4's unbiased roulette.
#ifndef RT_INTEGRATOR_PATH_H
#define RT_INTEGRATOR_PATH_H

#include "../bvh/intersect.h"
#include "../camera/camera.h"
#include "../geometry/surface.h"
#include "../light/emission.h"
#include "../material/material.h"
#include "../sampling/dimensions.h"
#include "direct_lighting.h"
#include "escaped.h"
#include "mis.h"
#include "primary_info.h"

#if RT_COMPILED(RT_FEATURE_PATH_TRACING)

// The longest a path may grow under Russian roulette, a guard against runaway paths.
#define RT_MAX_PATH_BOUNCES 64

// Pending branches of a split path. Only materials with delta lobes split: a kernel
// compiled without them keeps room for the camera path alone.
#if defined(__OPENCL_C_VERSION__) && \
    !(RT_KERNEL_FEATURES & (RT_FEATURE_MIRROR | RT_FEATURE_CONDUCTOR | RT_FEATURE_DIELECTRIC))
#define RT_PATH_STACK 1
#else
#define RT_PATH_STACK 8
#endif

// One path of the tree, from the vertex its ray will hit.
typedef struct PathState {
  Ray ray;
  real3 weight;    // What the path finds is multiplied by this (f cos / pdf products).
  real3 roulette;  // The course's roulette throughput: the product of BRDF values.
  real3 medium;    // Absorption of the dielectric the path travels in.
  uint key;        // Keys the random dimensions of the vertex.
  int bounce;      // Scatterings so far.
  int inside;      // 1 while inside a dielectric.
  int specular;    // The last scattering was a delta lobe (the camera ray counts as one).
  // Multiple importance sampling: the vertex the ray left, its unit shading normal, and the
  // density with which the bounce drew the ray's direction (BsdfPdf).
  real3 from;
  real3 from_n;
  real pdf;
} PathState;

// Radiance the surface at s emits back along s->wo: object lights (LightMesh,
// LightSphere, cl/light/emission.h) on their emitting side. The point, spot, directional
// and area lights of this renderer are not part of the geometry, so a path finds them
// only by light sampling. s must not be face-forwarded yet.
RT_DEVICE real3 SurfaceEmission(RT_PRIVATE const SceneData* sd, RT_PRIVATE const SurfacePoint* s) {
  if (RT_HAS(sd, RT_FEATURE_OBJECT_LIGHTS)) return EmittedRadiance(sd, s);
  return Vec3(0.0f);
}

// Russian roulette: the path goes on with probability q = the largest component of
// `throughput` (at most 1); a survivor's weight is then divided by q, and *survival
// receives 1 / q (it keeps 1 where no roulette is played or the path ends).
//
// The course's roulette, as its reference images show it (docs/path_tracing.md: the
// quantized values of glass_importance_russian.exr give it away), is played at a hit
// before its light is added, with the product of the BRDF values met so far as throughput
// (1 at the camera's hit): a surviving path divides what it finds from this hit on, this
// hit's emission and light samples included, by q, while a path that dies keeps this hit's
// light, undivided. The expected emission of a hit is then L (2 - q): the course's
// references are brighter than the converged image.
//
// --russian-roulette unbiased plays pbrt-v4's: after the hit's light is added, with the
// path's weight as throughput, so the expectation is unchanged and paths of low weight end
// early.
RT_DEVICE int RouletteSurvives(real3 throughput, RaySampler rs, RT_PRIVATE real* survival) {
  real q = fmin(RT_R(1.0), MaxComponent(throughput));
  if (q >= 1.0f) return 1;
  if (!(q > 0.0f) || RaySample1D(&rs, RT_DIM_RUSSIAN_ROULETTE) >= q) return 0;
  *survival = 1.0f / q;
  return 1;
}

// The branch of lobe `bs` from vertex s of path p.
RT_DEVICE PathState BranchPath(RT_PRIVATE const SceneData* sd, RT_PRIVATE const PathState* p,
                               RT_PRIVATE const SurfacePoint* s, RT_PRIVATE const Material* m,
                               BsdfSample bs) {
  PathState c = *p;
  c.ray = SpawnRay(sd, s, bs.wi, bs.transmit);
  c.weight = p->weight * bs.weight;
  c.roulette = p->roulette * bs.brdf;
  c.key = HashCombine(p->key, RT_PATH_NEXT_VERTEX + (uint)bs.lobe);
  c.bounce = p->bounce + 1;
  c.specular = bs.specular;
  if (bs.transmit) {
    c.inside = s->front;
    c.medium = s->front ? ToReal3(m->absorption) : Vec3(0.0f);
  }
  return c;
}

// The radiance an escaping path sees. With next-event estimation the environment light
// was sampled at the hit before, unless the path left by a delta lobe (as for emission at
// hits): the course's estimator drops it, mis weighs it against that sample.
RT_DEVICE real3 PathEscapedRadiance(RT_PRIVATE const SceneData* sd, RT_PRIVATE const PathState* p,
                                    real2 pixel_uv, int nee, int mis) {
  int sampled =
      nee && !p->specular && RT_HAS(sd, RT_LIGHT_ENVIRONMENT) && sd->header->environment >= 0;
  if (!EscapedRaySees(sd, p->bounce) || (sampled && !mis)) return Vec3(0.0f);
  real3 l = p->weight * EscapedRadiance(sd, p->ray.direction, pixel_uv);
  if (sampled) l = l * EnvironmentWeight(sd, p->ray.direction, p->from_n, p->pdf);
  return l;
}

// Continuation: replaces *p by the path along one lobe of the material at s and pushes the
// other lobes' branches; returns whether *p goes on. The path splits into every lobe while
// the stack has room for the extra branches, else (or with `choose`: the mis estimator)
// follows one lobe, chosen at random; with --dielectric choose a dielectric never splits
// either (one lobe, Fresnel picking between its reflected and refracted rays).
RT_KERNEL_INLINE int ContinuePath(RT_PRIVATE const SceneData* sd, RT_PRIVATE PathState* p,
                                  RT_PRIVATE const SurfacePoint* s, RT_PRIVATE const Material* m,
                                  RaySampler rs, int importance, int choose,
                                  RT_PRIVATE PathState* stack, RT_PRIVATE int* pending) {
  BsdfSample lobes[RT_LOBE_COUNT];
  int n = 0;
  choose = choose || ((sd->header->flags & RT_FLAG_FRESNEL_CHOICE) != 0 && IsTransmissive(sd, m));
  if (RT_PATH_STACK > 1 && !choose && HasSpecularLobe(sd, m))
    n = SampleBsdfLobes(sd, m, s, rs, importance, lobes);
  if (n == 0 || *pending + n - 1 > RT_PATH_STACK) {
    lobes[0] = SampleBsdf(sd, m, s, rs, importance);
    n = lobes[0].valid;
  }
  for (int l = 1; l < n; ++l) stack[(*pending)++] = BranchPath(sd, p, s, m, lobes[l]);
  if (!(n > 0 && MaxComponent(lobes[0].weight) > 0.0f)) return 0;
  *p = BranchPath(sd, p, s, m, lobes[0]);
  return 1;
}

RT_DEVICE real3 PathLi(RT_PRIVATE const SceneData* sd, SampleKey sk, Ray camera_ray, real2 pixel_uv,
                       RT_PRIVATE PrimaryInfo* info, RT_PRIVATE uint* rays) {
  RT_GLOBAL const SceneHeader* h = sd->header;
  int flags = h->flags;
  int nee = (flags & RT_FLAG_NEXT_EVENT) != 0;
  int importance = (flags & RT_FLAG_IMPORTANCE_SAMPLING) != 0;
  int roulette = (flags & RT_FLAG_RUSSIAN_ROULETTE) != 0;
  int mis = (flags & RT_FLAG_MIS) != 0;
  int course_roulette = roulette && (flags & RT_FLAG_UNBIASED_ROULETTE) == 0 && !mis;
  int max_bounces = roulette ? RT_MAX_PATH_BOUNCES : h->max_depth;
  // mis with light samples traces one bounce past the last light sample, for its emission.
  int last_bounce = max_bounces + (mis && nee);
  real3 radiance = Vec3(0.0f);
  PathState stack[RT_PATH_STACK];
  int pending = 0;
  PathState p;
  p.ray = camera_ray;
  p.weight = Vec3(1.0f);
  p.roulette = Vec3(1.0f);
  p.medium = Vec3(0.0f);
  p.key = RT_DIM_FIRST_FREE;
  p.bounce = 0;
  p.inside = 0;
  p.specular = 1;
  p.from = camera_ray.origin;
  p.from_n = Vec3(0.0f);
  p.pdf = 0.0f;
  RecordPrimaryMiss(info);
  for (;;) {
    Hit hit;
    *rays += 1u;
    int cull = (flags & RT_FLAG_CULL_BACK_FACES) != 0 && p.bounce == 0;
    int continues = 0;  // Whether p goes on from this hit.
    if (!IntersectClosest(sd, p.ray, cull, &hit)) {
      radiance += PathEscapedRadiance(sd, &p, pixel_uv, nee, mis);
    } else {
      SurfacePoint s = ComputeSurface(sd, p.ray, hit);
      if (p.bounce == 0) RecordPrimaryHit(info, hit, s.n);
      if (RT_HAS(sd, RT_FEATURE_DIELECTRIC) && p.inside)
        p.weight = p.weight * BeerLambert(p.medium, hit.t * Length(p.ray.direction), 1);
      Material m = EvaluateMaterial(sd, &s);
      // Emission: what the surface sends along the path, where light sampling did not count
      // it already; a replace_all texture shows its colour, unshaded, and ends the path.
      real3 found = (!nee || p.specular) ? SurfaceEmission(sd, &s) : Vec3(0.0f);
      if (mis && nee && !p.specular) {
        found = SurfaceEmission(sd, &s);
        if (MaxComponent(found) > 0.0f) found = found * EmissionWeight(sd, p.from, p.pdf, &s);
      }
      int unlit = RT_HAS(sd, RT_FEATURE_TEXTURES) && m.unlit;
      if (unlit) found = found + ToReal3(m.diffuse);
      // Unlike the ray tree's direct lighting, the path sees every surface from the side it
      // arrives on, so light samples and continuations agree on which side is lit.
      FaceForward(&s);
      RaySampler rs = MakeRaySampler(sk, p.key, p.bounce == 0);
      // Light samples: next-event estimation through the reflection model (none at the
      // vertex past the last bounce, which only collects emission).
      int beyond = p.bounce > max_bounces;
      if (!unlit && nee && !beyond && ReflectionShare(sd, &m, &s) > 0.0f)
        found = AddLightSamples(sd, &s, &m, &rs, found, mis, importance, rays);
      // Survival: the bound on bounces, then the roulette, played once; the course's divides
      // this hit's light by its probability too, pbrt-v4's only what the path finds later.
      real survival = 1.0f;
      continues = !unlit && p.bounce < last_bounce;
      if (continues && roulette)
        continues = RouletteSurvives(course_roulette ? p.roulette : p.weight, rs, &survival);
      if (course_roulette) p.weight = p.weight * survival;
      radiance += p.weight * found;
      if (roulette && !course_roulette) p.weight = p.weight * survival;
      // Continuation along the material's lobes.
      if (continues) continues = ContinuePath(sd, &p, &s, &m, rs, importance, mis, stack, &pending);
      if (continues && mis) {
        p.from = s.p;
        p.from_n = s.n;
        p.pdf = p.specular ? 0.0f : BsdfPdf(sd, &m, &s, p.ray.direction, importance);
      }
    }
    if (continues) continue;
    if (pending == 0) break;
    p = stack[--pending];
  }
  return radiance;
}

#endif  // RT_COMPILED(RT_FEATURE_PATH_TRACING)
#endif  // RT_INTEGRATOR_PATH_H
