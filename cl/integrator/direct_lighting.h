// Direct lighting at a surface point: ambient, plus one sample of every light, each
// checked by a shadow ray and reflected through the material.
#ifndef RT_INTEGRATOR_DIRECT_LIGHTING_H
#define RT_INTEGRATOR_DIRECT_LIGHTING_H

#include "../bvh/intersect.h"
#include "../geometry/surface.h"
#include "../light/light.h"
#include "../material/material.h"
#include "mis.h"

// 1 when nothing lies between origin and origin + segment (exclusive).
RT_DEVICE int Unoccluded(RT_PRIVATE const SceneData* sd, real3 origin, real3 segment, real time,
                         RT_PRIVATE uint* rays) {
  *rays += 1u;
  return !IntersectOccluded(sd, MakeRay(origin, segment, 1.0f, time));
}

// The light sample's contribution towards s->wo: none from below the shading normal or
// when the shadow segment is blocked.
RT_DEVICE real3 ShadeLightSample(RT_PRIVATE const SceneData* sd, RT_PRIVATE const SurfacePoint* s,
                                 RT_PRIVATE const Material* m, LightSample ls,
                                 RT_PRIVATE uint* rays) {
  if (!ls.valid || Dot(s->n, ls.wi) <= 0.0f) return Vec3(0.0f);
  // The course's renderer offsets the shadow ray along the shading normal (on a smooth mesh
  // the interpolated one): near a terminator the origin can fall behind the triangle, which
  // shadows the point, and in a crease it can clear a neighbouring triangle, which lights it;
  // its images show both. --shadow-offset geometric uses the triangle's.
  real3 along = (sd->header->flags & RT_FLAG_GEOMETRIC_OFFSET) != 0 ? s->ng : s->n;
  real3 origin =
      OffsetRayOrigin(s->p, along, sd->header->shadow_epsilon, s->scale, RT_ROBUST_OFFSET(sd));
  if (!Unoccluded(sd, origin, ls.p_light - origin, s->time, rays)) return Vec3(0.0f);
  return EvaluateBsdf(sd, m, s->n, s->wo, ls.wi, ls.irradiance);
}

// l plus one sample of every light, summed in the lights' array order (cl/scene_types.h,
// Light), which fixes the last bit of the result. `rs` draws the area lights'
// samples; it comes by pointer, as to RaySample2D (a by-value copy, stored field by field by
// the caller and reloaded in 16-byte halves here, stalled on store-to-load forwarding). The
// path tracer's next-event estimation is this sum; with `mis` each sample is weighed
// against the path's bounce, drawn with `importance` (mis.h).
RT_DEVICE real3 AddLightSamples(RT_PRIVATE const SceneData* sd, RT_PRIVATE const SurfacePoint* s,
                                RT_PRIVATE const Material* m, RT_PRIVATE const RaySampler* rs,
                                real3 l, int mis, int importance, RT_PRIVATE uint* rays) {
  LightSampleContext ctx = MakeLightSampleContext(s->p, s->n, s->ng);
  // Summed per component, in the same order as l += c: the CPU reference receives l in two
  // registers, and reassembling it whole went through memory (a store-forwarding stall).
  real x = l.x, y = l.y, z = l.z;
  for (int i = 0; i < sd->header->num_lights; ++i) {
    RT_GLOBAL const Light* light = &sd->lights[i];
    LightSample ls = SampleLight(sd, light, &ctx, rs);
    real w = mis ? LightSampleWeight(sd, light, ls, s, m, importance) : 1.0f;
    if (!(w > 0.0f)) continue;  // No shadow ray for a sample of weight 0.
    real3 c = ShadeLightSample(sd, s, m, ls, rays);
    if (mis) c = c * w;
    x += c.x;
    y += c.y;
    z += c.z;
  }
  return make_real3(x, y, z);
}

// The ambient term of a material of ambient reflectance ka (Li reads ka alone where nothing
// else of the material is needed).
RT_DEVICE real3 AmbientRadiance(RT_PRIVATE const SceneData* sd, float3 ka) {
  return ToReal3(ka * sd->header->ambient_light);
}

// The ray tree's shading: ambient plus the lights. A surface whose Blinn-Phong is black
// (a mirror, metal or glass lit only through the rays it scatters) would add an exact zero
// per light sample, so it takes no samples and casts no shadow rays: the image is the same
// to the bit (a sample of infinite irradiance, which would turn the sample into NaN and drop
// it, is the one exception: a point light closer than about 1e-17), and hw3's tap and
// metal_glass_plates cast far fewer rays. Random numbers are keyed, so no other draw moves.
RT_DEVICE real3 DirectLighting(RT_PRIVATE const SceneData* sd, RT_PRIVATE const SurfacePoint* s,
                               RT_PRIVATE const Material* m, RaySampler rs, RT_PRIVATE uint* rays) {
  if (RT_HAS(sd, RT_FEATURE_TEXTURES) && m->unlit) return ToReal3(m->diffuse);
  real3 ambient = AmbientRadiance(sd, m->ambient);
  // Without lights, the ambient term alone: not even the light context is made.
  if (sd->header->num_lights == 0) return ambient;
  int blinn_phong = !RT_HAS(sd, RT_FEATURE_BRDF) || m->brdf == RT_BRDF_ORIGINAL_BLINN_PHONG;
  if (blinn_phong && BlinnPhongIsBlack(m)) return ambient;
  return AddLightSamples(sd, s, m, &rs, ambient, 0, 0, rays);
}

#endif  // RT_INTEGRATOR_DIRECT_LIGHTING_H
