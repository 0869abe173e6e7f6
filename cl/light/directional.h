// A directional light (hw5): radiance L arriving along one direction from infinitely far
// away, so the irradiance on a surface facing it is L whatever its position (the
// specification's "no distance based attenuation").
#ifndef RT_LIGHT_DIRECTIONAL_H
#define RT_LIGHT_DIRECTIONAL_H

#include "light_sample.h"

RT_DEVICE LightSample SampleDirectionalLight(RT_GLOBAL const Light* light,
                                             RT_PRIVATE const LightSampleContext* ctx) {
  LightSample ls;
  ls.wi = -ToReal3(light->normal);
  // The shadow segment ends beyond the scene: the reach exceeds its bounding box's
  // diagonal, so from any point inside the box the segment leaves it.
  ls.p_light = ctx->p + ls.wi * RT_LIGHT_REACH(light);
  ls.irradiance = ToReal3(light->emission);
  ls.pdf = 0.0f;
  ls.valid = 1;
  return ls;
}

#endif  // RT_LIGHT_DIRECTIONAL_H
