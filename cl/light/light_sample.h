// What sampling a light returns, and the shading point it is sampled from (pbrt-v4's
// LightSampleContext and LightLiSample; Cycles' LightSample).
#ifndef RT_LIGHT_SAMPLE_H
#define RT_LIGHT_SAMPLE_H

#include "../scene_types.h"
#include "../util/math.h"

// The point being lit, as a light's sampling sees it.
typedef struct LightSampleContext {
  real3 p;   // World-space position.
  real3 n;   // Unit shading normal.
  real3 ng;  // Unit geometric normal.
} LightSampleContext;

RT_DEVICE LightSampleContext MakeLightSampleContext(real3 p, real3 n, real3 ng) {
  LightSampleContext ctx;
  ctx.p = p;
  ctx.n = n;
  ctx.ng = ng;
  return ctx;
}

// One sample of a light as seen from a shading point.
typedef struct LightSample {
  real3 p_light;  // The sampled point of the light: the shadow segment ends there.
  real3 wi;       // Unit direction from the shading point towards p_light.
  // Irradiance the sample delivers to a surface facing wi (before the receiver's cosine,
  // which is the reflection model's), already divided by the sample's density.
  real3 irradiance;
  // Density of wi per unit solid angle, the light's side of multiple importance sampling
  // (weighing a light sample against the BSDF's sampling of the same direction, with
  // EmitterPdf and EnvironmentSamplePdf for the other side; cl/integrator/mis.h). 0 for the
  // lights that sample a single direction (point, spot, directional), which a ray never
  // finds.
  real pdf;
  int valid;  // 0 when the light sends nothing (the shading point lies on the light).
} LightSample;

// The sample of a light that radiates `power` (intensity, or radiance times the area
// that is sampled) from q towards p, falling off as 1 / d^2.
RT_DEVICE LightSample LightSampleTowards(real3 p, real3 q, real3 power) {
  LightSample ls;
  real3 to_light = q - p;
  real dist2 = Dot(to_light, to_light);
  ls.p_light = q;
  ls.valid = !(dist2 <= 0.0f);
  ls.wi = Vec3(0.0f);
  ls.irradiance = Vec3(0.0f);
  ls.pdf = 0.0f;
  if (!ls.valid) return ls;
  ls.wi = to_light * (1.0f / sqrt(dist2));
  ls.irradiance = power * (1.0f / dist2);
  return ls;
}

#endif  // RT_LIGHT_SAMPLE_H
