// Fresnel reflectance of dielectrics and conductors, refraction, and absorption inside a
// dielectric (Beer-Lambert).
#ifndef RT_MATERIAL_FRESNEL_H
#define RT_MATERIAL_FRESNEL_H

#include "../util/math.h"
#include "../util/trig.h"

// Unpolarized Fresnel reflectance of a dielectric interface for light going from index
// eta_i to eta_t; cos_i > 0 is the cosine on the incident side. Total internal
// reflection returns 1 and *cos_t = 0.
RT_DEVICE float FrDielectric(float cos_i, float eta_i, float eta_t, RT_PRIVATE float* cos_t) {
  // cos_t^2 = 1 - eta^2 (1 - cos_i^2), grouped so that matched indices give cos_t = cos_i
  // instead of cancelling in 1 - (1 - cos_i^2) (which reports total internal reflection
  // below cos_i ~ 2.4e-4).
  float eta2 = (eta_i / eta_t) * (eta_i / eta_t);
  float cos2_t = (1.0f - eta2) + eta2 * (cos_i * cos_i);
  if (cos2_t <= 0.0f) {
    *cos_t = 0.0f;
    return 1.0f;
  }
  float ct = sqrt(cos2_t);
  *cos_t = ct;
  float r_par = (eta_t * cos_i - eta_i * ct) / (eta_t * cos_i + eta_i * ct);
  float r_perp = (eta_i * cos_i - eta_t * ct) / (eta_i * cos_i + eta_t * ct);
  return 0.5f * (r_par * r_par + r_perp * r_perp);
}

// Fresnel reflectance of a conductor with complex index eta + i k seen from air, in the
// form the course uses (the common approximation that drops the small cross terms).
RT_DEVICE float FrConductor(float cos_i, float eta, float k) {
  float c2 = cos_i * cos_i;
  float nk2 = eta * eta + k * k;
  float two_n_c = 2.0f * eta * cos_i;
  float rs = (nk2 - two_n_c + c2) / (nk2 + two_n_c + c2);
  float rp = (nk2 * c2 - two_n_c + 1.0f) / (nk2 * c2 + two_n_c + 1.0f);
  return 0.5f * (rs + rp);
}

// Refracted direction of unit incident direction d through unit normal n facing the
// incident side, given eta = eta_i / eta_t and cos_t from FrDielectric.
RT_DEVICE float3 Refract(float3 d, float3 n, float eta, float cos_i, float cos_t) {
  return Normalize(d * eta + n * (eta * cos_i - cos_t));
}

// Beer-Lambert attenuation over a path of length `distance` inside a medium.
RT_DEVICE float3 BeerLambert(float3 absorption, float distance) {
  return Exp3(absorption * (-distance));
}

// The same with util/trig.h's exponential, which both devices round alike: the path
// tracer's weights decide where paths go (roulette), so they must agree to the bit. The
// ray tree keeps the library's, so that its images stay as they were.
RT_DEVICE float3 BeerLambertPortable(float3 absorption, float distance) {
  float3 a = absorption * (-distance);
  return make_float3(ExpF(a.x), ExpF(a.y), ExpF(a.z));
}

#endif  // RT_MATERIAL_FRESNEL_H
