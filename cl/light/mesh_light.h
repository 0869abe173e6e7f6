// A LightMesh (hw6): a triangle mesh that emits radiance L from the front of each face,
// the side (v1 - v0) x (v2 - v0) points to (every face of the course's mesh lights points
// into the room, which its reference images light). It is sampled uniformly by world-space
// area: a triangle with the probability of its share of the area (a binary search of the
// cumulative areas the host stores in light_cdf), then a point uniformly inside it, so
// every point of the mesh has density 1 / A. One 2D sample drives both choices, so the
// strata of a camera ray's light sample spread over the whole mesh.
#ifndef RT_LIGHT_MESH_LIGHT_H
#define RT_LIGHT_MESH_LIGHT_H

#include "../geometry/ray.h"
#include "../geometry/transform.h"
#include "light_sample.h"

// The triangle whose cumulative-area interval holds *u, which is rescaled to [0, 1)
// within that interval so it can place the point inside the triangle.
RT_DEVICE int PickMeshLightTriangle(RT_PRIVATE const SceneData* sd, RT_GLOBAL const Light* light,
                                    RT_PRIVATE real* u) {
  RT_GLOBAL const float* cdf = sd->light_cdf + RT_MESH_CDF(light);
  int lo = 0, hi = RT_MESH_COUNT(light) - 1;
  while (lo < hi) {
    int mid = (lo + hi) / 2;
    if (cdf[mid] <= *u)
      lo = mid + 1;
    else
      hi = mid;
  }
  real below = lo > 0 ? cdf[lo - 1] : 0.0f;
  real width = cdf[lo] - below;
  *u = width > 0.0f ? MinF((*u - below) / width, 0.99999994f) : 0.5f;
  return lo;
}

// World-space vertices and unit normal of triangle k of the mesh light. The normal is the
// object-space face normal through the inverse transpose, as ComputeSurface turns it, so
// the side a ray sees as front is the side that emits.
RT_DEVICE void MeshLightTriangle(RT_PRIVATE const SceneData* sd, RT_GLOBAL const Light* light,
                                 int k, RT_PRIVATE real3* v, RT_PRIVATE real3* n) {
  RT_GLOBAL const Instance* inst = &sd->instances[RT_LIGHT_INSTANCE(light)];
  RT_GLOBAL const Triangle* tri = &sd->triangles[RT_MESH_FIRST(light) + k];
  v[0] = ToReal3(tri->v0);
  v[1] = ToReal3(tri->v1);
  v[2] = ToReal3(tri->v2);
  real3 ng = Cross(v[1] - v[0], v[2] - v[0]);
  if (RT_HAS(sd, RT_FEATURE_TRANSFORMS) && (inst->flags & RT_INSTANCE_TRANSFORMED) != 0) {
    for (int i = 0; i < 3; ++i) v[i] = TransformPoint(inst->object_to_world, v[i]);
    ng = TransformNormalByInverse(inst->world_to_object, ng);
  }
  *n = Normalize(ng);
}

// Density per unit solid angle, seen from p, of the light's point q with unit normal n:
// d^2 / (A cos), or 0 when q's face turns away from p (it sends nothing there).
RT_DEVICE real MeshLightPdf(RT_GLOBAL const Light* light, real3 p, real3 q, real3 n) {
  real3 to_p = p - q;
  real dist2 = Dot(to_p, to_p);
  real cos_light = Dot(n, to_p) / sqrt(dist2);
  if (!(cos_light > 0.0f)) return 0.0f;
  return dist2 / (RT_LIGHT_SURFACE_AREA(light) * cos_light);
}

RT_DEVICE LightSample SampleMeshLight(RT_PRIVATE const SceneData* sd, RT_GLOBAL const Light* light,
                                      RT_PRIVATE const LightSampleContext* ctx, real2 u) {
  real ux = u.x;  // OpenCL C cannot take the address of a vector's component.
  int k = PickMeshLightTriangle(sd, light, &ux);
  real3 v[3], n;
  MeshLightTriangle(sd, light, k, v, &n);
  // Uniform barycentrics (the square-root warp), continuous in u.
  real su = sqrt(ux);
  real b1 = (1.0f - u.y) * su, b2 = u.y * su;
  real3 q = v[0] * (1.0f - su) + v[1] * b1 + v[2] * b2;
  LightSample ls =
      LightSampleTowards(ctx->p, q, ToReal3(light->emission) * RT_LIGHT_SURFACE_AREA(light));
  real cos_light = -Dot(n, ls.wi);
  if (!ls.valid || !(cos_light > 0.0f)) {
    ls.valid = 0;
    return ls;
  }
  ls.irradiance = ls.irradiance * cos_light;
  ls.pdf = MeshLightPdf(light, ctx->p, q, n);
  // The shadow segment stops just off the light, on the side that faces p, so the
  // light's own triangle cannot block it.
  real scale =
      fmax(MaxComponent(Abs3(v[0])), fmax(MaxComponent(Abs3(v[1])), MaxComponent(Abs3(v[2]))));
  ls.p_light = OffsetRayOrigin(q, n, sd->header->shadow_epsilon, scale, RT_ROBUST_OFFSET(sd));
  return ls;
}

#endif  // RT_LIGHT_MESH_LIGHT_H
