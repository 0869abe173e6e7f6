// An isotropic point light of intensity I: irradiance I / d^2 from a single direction.
#ifndef RT_LIGHT_POINT_H
#define RT_LIGHT_POINT_H

#include "light_sample.h"

RT_DEVICE LightSample SamplePointLight(RT_GLOBAL const Light* light,
                                       RT_PRIVATE const LightSampleContext* ctx) {
  return LightSampleTowards(ctx->p, ToReal3(light->position), ToReal3(light->emission));
}

#endif  // RT_LIGHT_POINT_H
