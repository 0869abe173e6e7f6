// The course's reflection model: Lambertian diffuse plus a Blinn-Phong specular lobe.
#ifndef RT_MATERIAL_BLINN_PHONG_H
#define RT_MATERIAL_BLINN_PHONG_H

#include "../scene_types.h"
#include "../util/math.h"

// Diffuse plus Blinn-Phong specular for irradiance `e` arriving from unit direction wi
// at a point with unit normal n, seen from unit direction wo. `m` is the material as
// evaluated at the point (EvaluateMaterial).
RT_DEVICE real3 BlinnPhong(RT_PRIVATE const Material* m, real3 n, real3 wo, real3 wi, real3 e) {
  real cos_i = Dot(n, wi);
  if (cos_i <= 0.0f) return Vec3(0.0f);
  real3 h = Normalize(wi + wo);
  real cos_h = fmax(RT_R(0.0), Dot(n, h));
  real spec = cos_h > 0.0f ? PowF(cos_h, m->phong_exponent) : 0.0f;
  return (ToReal3(m->diffuse) * cos_i + ToReal3(m->specular) * spec) * e;
}

#endif  // RT_MATERIAL_BLINN_PHONG_H
