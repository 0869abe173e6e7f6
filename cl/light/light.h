// Sampling any light of the scene's tagged array: one function per type (in this
// folder), chosen here by the light's type. A type the kernel was compiled without is
// never sampled (its code is compiled out; the host only omits features no light uses).
#ifndef RT_LIGHT_H
#define RT_LIGHT_H

#include "../features.h"
#include "../sampling/sampler.h"
#include "area.h"
#include "directional.h"
#include "environment.h"
#include "mesh_light.h"
#include "point.h"
#include "sphere_light.h"
#include "spot.h"

// The random dimension of a light's sample at a ray, offset from the ray's key (the
// course's first bounce stratifies it; see RaySampler).
RT_DEVICE uint LightSampleOffset(RT_GLOBAL const Light* light) {
  return RT_OFFSET_LIGHT + (uint)light->sample_index;
}

// Inlined whatever GCC's size heuristics say: kept out of line, AddLightSamples shrank
// enough to be inlined into the pixel loop (AccumulatePixel), which then outgrew the
// limits that keep MakeTriangleRay and PermutationElement inlined.
RT_DEVICE_INLINE LightSample SampleLight(RT_PRIVATE const SceneData* sd,
                                         RT_GLOBAL const Light* light,
                                         RT_PRIVATE const LightSampleContext* ctx,
                                         RT_PRIVATE const RaySampler* rs) {
  if (RT_HAS(sd, RT_LIGHT_POINT) && light->type == RT_LIGHT_POINT)
    return SamplePointLight(light, ctx);
  if (RT_HAS(sd, RT_LIGHT_AREA) && light->type == RT_LIGHT_AREA)
    return SampleAreaLight(light, ctx, RaySample2D(rs, LightSampleOffset(light)));
  if (RT_HAS(sd, RT_LIGHT_DIRECTIONAL) && light->type == RT_LIGHT_DIRECTIONAL)
    return SampleDirectionalLight(light, ctx);
  if (RT_HAS(sd, RT_LIGHT_SPOT) && light->type == RT_LIGHT_SPOT) return SampleSpotLight(light, ctx);
  if (RT_HAS(sd, RT_LIGHT_MESH) && light->type == RT_LIGHT_MESH)
    return SampleMeshLight(sd, light, ctx, RaySample2D(rs, LightSampleOffset(light)));
  if (RT_HAS(sd, RT_LIGHT_SPHERE) && light->type == RT_LIGHT_SPHERE)
    return SampleSphereLight(sd, light, ctx, RaySample2D(rs, LightSampleOffset(light)));
  if (RT_HAS(sd, RT_LIGHT_ENVIRONMENT) && light->type == RT_LIGHT_ENVIRONMENT)
    return SampleEnvironmentLight(sd, light, ctx, RaySample2D(rs, LightSampleOffset(light)));
  LightSample none = LightSampleTowards(ctx->p, ctx->p, Vec3(0.0f));  // Not valid.
  return none;
}

#endif  // RT_LIGHT_H
