// A parallelogram of uniform radiance L, sampled uniformly by area: a point q at (s, t)
// sends L * A * |cos_light| / d^2, an unbiased estimate of the irradiance from the whole
// parallelogram. The course's square lights are two orthogonal edges of length Size.
#ifndef RT_LIGHT_AREA_H
#define RT_LIGHT_AREA_H

#include "light_sample.h"

RT_DEVICE LightSample SampleAreaLight(RT_GLOBAL const Light* light,
                                      RT_PRIVATE const LightSampleContext* ctx, real2 u) {
  real3 q = ToReal3(light->position) + ToReal3(light->edge1) * u.x + ToReal3(light->edge2) * u.y;
  LightSample ls =
      LightSampleTowards(ctx->p, q, ToReal3(light->emission) * RT_LIGHT_SURFACE_AREA(light));
  // Both faces emit, as the course's reference images show (cornellbox_area's ceiling).
  real cos_light = fabs(Dot(ToReal3(light->normal), ls.wi));
  ls.irradiance = ls.irradiance * cos_light;
  real3 to_light = q - ctx->p;
  if (cos_light > 0.0f)
    ls.pdf = Dot(to_light, to_light) / (RT_LIGHT_SURFACE_AREA(light) * cos_light);
  return ls;
}

#endif  // RT_LIGHT_AREA_H
