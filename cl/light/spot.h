// A spot light (hw5): a point light of intensity I that shines only into a cone around its
// direction. Inside half the fall-off angle it is a plain point light; between that and
// half the coverage angle its intensity falls as
//   s = ((cos a - cos(coverage / 2)) / (cos(falloff / 2) - cos(coverage / 2)))^4
// (a: angle from the light's axis), from 1 to 0; outside, nothing. The specification prints
// cos(falloff / 2) in the numerator, which would give s = 1 at the coverage edge and make
// the light brighten towards it; the formula above, continuous at both edges, is the one
// the course's own image shows (hw5/reference/dragon_spot_light_msaa.png fades to dark at
// the edge of the cone).
#ifndef RT_LIGHT_SPOT_H
#define RT_LIGHT_SPOT_H

#include "light_sample.h"

RT_DEVICE real SpotFalloff(RT_GLOBAL const Light* light, real cos_a) {
  if (cos_a >= RT_SPOT_COS_FALLOFF(light)) return 1.0f;
  if (cos_a <= RT_SPOT_COS_COVERAGE(light)) return 0.0f;
  real t = (cos_a - RT_SPOT_COS_COVERAGE(light)) /
           (RT_SPOT_COS_FALLOFF(light) - RT_SPOT_COS_COVERAGE(light));
  real t2 = t * t;
  return t2 * t2;
}

RT_DEVICE LightSample SampleSpotLight(RT_GLOBAL const Light* light,
                                      RT_PRIVATE const LightSampleContext* ctx) {
  LightSample ls = LightSampleTowards(ctx->p, ToReal3(light->position), ToReal3(light->emission));
  if (ls.valid)
    ls.irradiance = ls.irradiance * SpotFalloff(light, -Dot(ls.wi, ToReal3(light->normal)));
  return ls;
}

#endif  // RT_LIGHT_SPOT_H
