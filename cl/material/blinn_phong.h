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
  // Only a positive cosine is raised (fmax with 0 would be a library call on the CPU and
  // gives the same spec: 0 for anything not above 0, NaN included).
  real cos_h = Dot(n, h);
  real spec = cos_h > 0.0f ? PowF(cos_h, m->phong_exponent) : 0.0f;
  return (ToReal3(m->diffuse) * cos_i + ToReal3(m->specular) * spec) * e;
}

// 1 when BlinnPhong gives exactly zero for every light: black diffuse and specular
// reflectances, as the course's mirrors, metals and glass often have (their light is in the
// rays they scatter). cos_i and the specular term are finite, so each product is +0.
RT_DEVICE int BlinnPhongIsBlack(RT_PRIVATE const Material* m) {
  return m->diffuse.x == 0.0f && m->diffuse.y == 0.0f && m->diffuse.z == 0.0f &&
         m->specular.x == 0.0f && m->specular.y == 0.0f && m->specular.z == 0.0f;
}

#endif  // RT_MATERIAL_BLINN_PHONG_H
