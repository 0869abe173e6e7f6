// An environment light (hw5's SphericalDirectionalLight): radiance L(d) arriving from
// infinitely far away in every direction d, read from an HDR map (environment_map.h). Rays
// that leave the scene see it (EnvironmentRadiance); direct lighting draws one direction
// per shading point and returns L(d) / p(d) as the irradiance of that sample, the
// specification's estimate L^ = 2 pi L(d) when p is its uniform hemisphere density.
//
// The map's texels are sd->env_texels (row-major, top row first). Importance sampling
// reads two cumulative distributions the host builds (src/prepare/flat_environment.cpp) from
// f(x, y) = luminance(texel) * (solid angle per unit map area at the texel's centre): the
// marginal over rows, H + 1 values in sd->env_marginal_cdf, and for each row the
// conditional over its columns, W + 1 values per row in sd->env_conditional_cdf.
#ifndef RT_LIGHT_ENVIRONMENT_H
#define RT_LIGHT_ENVIRONMENT_H

#include "environment_map.h"
#include "light_sample.h"

RT_DEVICE real3 EnvTexel(RT_PRIVATE const SceneData* sd, int index) {
  float4 t = sd->env_texels[index];
  return make_real3(t.x, t.y, t.z);
}

// The radiance arriving along -dir, for a ray travelling along dir (any length).
RT_DEVICE real3 EnvironmentRadiance(RT_PRIVATE const SceneData* sd, RT_GLOBAL const Light* light,
                                    real3 dir) {
  real2 uv = EnvDirectionToUV(RT_ENV_MAPPING(light), Normalize(dir));
  return EnvTexel(sd, EnvTexelIndex(uv, (int)RT_ENV_WIDTH(light), (int)RT_ENV_HEIGHT(light)));
}

// The density, over the map, of the texel importance sampling draws.
RT_DEVICE real EnvTexelDensity(RT_PRIVATE const SceneData* sd, RT_GLOBAL const Light* light, int x,
                               int y) {
  int w = (int)RT_ENV_WIDTH(light), h = (int)RT_ENV_HEIGHT(light);
  RT_GLOBAL const float* marginal = sd->env_marginal_cdf;
  RT_GLOBAL const float* row = sd->env_conditional_cdf + y * (w + 1);
  return (marginal[y + 1] - marginal[y]) * (real)h * ((row[x + 1] - row[x]) * (real)w);
}

// The solid-angle density with which importance sampling draws unit direction d (0 where
// the map is black), for tests and for combining with other strategies.
RT_DEVICE real EnvironmentPdf(RT_PRIVATE const SceneData* sd, RT_GLOBAL const Light* light,
                              real3 d) {
  if (RT_ENV_INTEGRAL(light) <= 0.0f) return 0.0f;
  int w = (int)RT_ENV_WIDTH(light), h = (int)RT_ENV_HEIGHT(light);
  real2 uv = EnvDirectionToUV(RT_ENV_MAPPING(light), d);
  int texel = EnvTexelIndex(uv, w, h);
  real jacobian;
  EnvUVToDirection(RT_ENV_MAPPING(light), uv, &jacobian);
  if (!(jacobian > 0.0f)) return 0.0f;
  return EnvTexelDensity(sd, light, texel % w, texel / w) / jacobian;
}

// A direction in the hemisphere around unit n from u in [0, 1)^2: uniform (density
// 1 / (2 pi)) or cosine-weighted (cos / pi), returning that density in *pdf.
RT_DEVICE real3 SampleHemisphere(real3 n, real2 u, int cosine, RT_PRIVATE real* pdf) {
  real z = cosine ? sqrt(1.0f - u.x) : u.x;
  real r = sqrt(MaxF(0.0f, 1.0f - z * z));
  *pdf = cosine ? z * (1.0f / RT_PI) : 0.5f / RT_PI;
  return SphericalDirection(n, r, z, u.y);
}

// The solid-angle density with which SampleEnvironmentLight, at a point of unit shading
// normal n, draws unit direction d, whichever the light's sampler.
RT_DEVICE real EnvironmentSamplePdf(RT_PRIVATE const SceneData* sd, RT_GLOBAL const Light* light,
                                    real3 d, real3 n) {
  if (RT_ENV_SAMPLING(light) == RT_ENV_SAMPLE_IMPORTANCE) return EnvironmentPdf(sd, light, d);
  real cos_t = Dot(d, n);
  if (!(cos_t > 0.0f)) return 0.0f;
  return RT_ENV_SAMPLING(light) == RT_ENV_SAMPLE_COSINE ? cos_t * (1.0f / RT_PI) : 0.5f / RT_PI;
}

RT_DEVICE LightSample SampleEnvironmentLight(RT_PRIVATE const SceneData* sd,
                                             RT_GLOBAL const Light* light,
                                             RT_PRIVATE const LightSampleContext* ctx, real2 u) {
  LightSample ls;
  ls.valid = 0;
  ls.pdf = 0.0f;
  ls.irradiance = Vec3(0.0f);
  ls.wi = ctx->n;
  ls.p_light = ctx->p;
  real pdf = 0.0f;
  real3 radiance = Vec3(0.0f);
  if (RT_ENV_SAMPLING(light) == RT_ENV_SAMPLE_IMPORTANCE) {
    if (RT_ENV_INTEGRAL(light) <= 0.0f) return ls;  // A black map sends nothing.
    int w = (int)RT_ENV_WIDTH(light), h = (int)RT_ENV_HEIGHT(light);
    real dv, du;
    int y = SampleCdf(sd->env_marginal_cdf, h, u.y, &dv);
    int x = SampleCdf(sd->env_conditional_cdf + y * (w + 1), w, u.x, &du);
    real jacobian;
    real2 uv = make_real2(((real)x + du) / (real)w, ((real)y + dv) / (real)h);
    ls.wi = EnvUVToDirection(RT_ENV_MAPPING(light), uv, &jacobian);
    if (!(jacobian > 0.0f)) return ls;
    pdf = EnvTexelDensity(sd, light, x, y) / jacobian;
    // The texel drawn, not the one wi maps back to: rounding could cross a texel edge, and
    // the density is that of the texel drawn.
    radiance = EnvTexel(sd, y * w + x);
  } else {
    ls.wi = SampleHemisphere(ctx->n, u, RT_ENV_SAMPLING(light) == RT_ENV_SAMPLE_COSINE, &pdf);
    radiance = EnvironmentRadiance(sd, light, ls.wi);
  }
  if (!(pdf > 0.0f)) return ls;
  // The shadow segment leaves the scene's bounding box, as a directional light's.
  ls.p_light = ctx->p + ls.wi * RT_LIGHT_REACH(light);
  ls.irradiance = radiance * (1.0f / pdf);
  ls.pdf = pdf;
  ls.valid = 1;
  return ls;
}

#endif  // RT_LIGHT_ENVIRONMENT_H
