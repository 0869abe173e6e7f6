// Direct lighting from point and area lights, with shadow rays.
#ifndef RT_LIGHTS_H
#define RT_LIGHTS_H

#include "bvh.h"
#include "materials.h"
#include "sampler.h"

// 1 when nothing lies between origin and origin + segment (exclusive).
RT_DEVICE int Unoccluded(RT_PRIVATE const SceneData* sd, float3 origin, float3 segment, float time,
                         RT_PRIVATE uint* rays) {
  Hit hit;
  *rays += 1u;
  Ray shadow = MakeRay(origin, segment, 1.0f, time);
  return !IntersectScene(sd, shadow, 1, 0, &hit);
}

// Irradiance-weighted Blinn-Phong from a light point q with irradiance scale `power`
// (intensity, or radiance * area * light cosine), falling off as 1 / d^2.
RT_DEVICE float3 ShadeFromPoint(RT_PRIVATE const SceneData* sd, RT_PRIVATE const Material* m,
                                float3 p, float scale, float3 n, float3 ng, float3 wo, float3 q,
                                float3 power, int two_sided_normal, float3 light_normal, float time,
                                RT_PRIVATE uint* rays) {
  float3 to_light = q - p;
  float dist2 = Dot(to_light, to_light);
  if (dist2 <= 0.0f) return Vec3(0.0f);
  float3 wi = to_light * (1.0f / sqrt(dist2));
  if (Dot(n, wi) <= 0.0f) return Vec3(0.0f);
  float3 e = power * (1.0f / dist2);
  if (two_sided_normal) e = e * fabs(Dot(light_normal, wi));
  float3 origin = OffsetRayOrigin(p, ng, sd->header->shadow_epsilon, scale);
  if (!Unoccluded(sd, origin, q - origin, time, rays)) return Vec3(0.0f);
  return BlinnPhong(m, n, wo, wi, e);
}

// Ambient plus every light's contribution at a surface point; `key` and `primary`
// choose the area-light samples (stratified for camera-ray hits).
RT_DEVICE float3 DirectLighting(RT_PRIVATE const SceneData* sd, RT_PRIVATE const Material* m,
                                float3 p, float scale, float3 n, float3 ng, float3 wo, float time,
                                SampleKey sk, uint key, int primary, RT_PRIVATE uint* rays) {
  RT_GLOBAL const SceneHeader* h = sd->header;
  float3 l = m->ambient * h->ambient_light;
  if (RT_HAS(sd, RT_FEATURE_POINT_LIGHTS)) {
    for (int i = 0; i < h->num_point_lights; ++i) {
      RT_GLOBAL const PointLight* pl = &sd->point_lights[i];
      l += ShadeFromPoint(sd, m, p, scale, n, ng, wo, pl->position, pl->intensity, 0, Vec3(0.0f),
                          time, rays);
    }
  }
  if (RT_HAS(sd, RT_FEATURE_AREA_LIGHTS)) {
    for (int i = 0; i < h->num_area_lights; ++i) {
      RT_GLOBAL const AreaLight* al = &sd->area_lights[i];
      uint dim = HashCombine(key, 0x1000u + (uint)i);
      float2 xi = primary ? Stratified2D(sk, dim) : Random2D(sk, dim);
      float3 q = al->corner + al->edge1 * xi.x + al->edge2 * xi.y;
      // Lights emit from both faces, as the course's reference images show.
      l += ShadeFromPoint(sd, m, p, scale, n, ng, wo, q, al->radiance * al->area, 1, al->normal,
                          time, rays);
    }
  }
  return l;
}

#endif  // RT_LIGHTS_H
