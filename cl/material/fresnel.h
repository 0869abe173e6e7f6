// Fresnel reflectance of dielectrics and conductors, refraction, and absorption inside a
// dielectric (Beer-Lambert).
#ifndef RT_MATERIAL_FRESNEL_H
#define RT_MATERIAL_FRESNEL_H

#include "../util/math.h"
#include "../util/transcendental.h"

// Unpolarized Fresnel reflectance of a dielectric interface for light going from index
// eta_i to eta_t; cos_i > 0 is the cosine on the incident side. Total internal
// reflection returns 1 and *cos_t = 0.
RT_DEVICE real FrDielectric(real cos_i, real eta_i, real eta_t, RT_PRIVATE real* cos_t) {
  // cos_t^2 = 1 - eta^2 (1 - cos_i^2), grouped so that matched indices give cos_t = cos_i
  // instead of cancelling in 1 - (1 - cos_i^2) (which reports total internal reflection
  // below cos_i ~ 2.4e-4).
  real eta2 = (eta_i / eta_t) * (eta_i / eta_t);
  real cos2_t = (1.0f - eta2) + eta2 * (cos_i * cos_i);
  if (cos2_t <= 0.0f) {
    *cos_t = 0.0f;
    return 1.0f;
  }
  real ct = sqrt(cos2_t);
  *cos_t = ct;
  real r_par = (eta_t * cos_i - eta_i * ct) / (eta_t * cos_i + eta_i * ct);
  real r_perp = (eta_i * cos_i - eta_t * ct) / (eta_i * cos_i + eta_t * ct);
  return 0.5f * (r_par * r_par + r_perp * r_perp);
}

// Fresnel reflectance of a conductor with complex index eta + i k seen from air, in the
// form the course uses (the common approximation that drops the small cross terms).
RT_DEVICE real FrConductor(real cos_i, real eta, real k) {
  real c2 = cos_i * cos_i;
  real nk2 = eta * eta + k * k;
  real two_n_c = 2.0f * eta * cos_i;
  real rs = (nk2 - two_n_c + c2) / (nk2 + two_n_c + c2);
  real rp = (nk2 * c2 - two_n_c + 1.0f) / (nk2 * c2 + two_n_c + 1.0f);
  return 0.5f * (rs + rp);
}

// Refracted direction of unit incident direction d through unit normal n facing the
// incident side, given eta = eta_i / eta_t and cos_t from FrDielectric.
RT_DEVICE real3 Refract(real3 d, real3 n, real eta, real cos_i, real cos_t) {
  return Normalize(d * eta + n * (eta * cos_i - cos_t));
}

// e^x, skipping the call where x is zero (a channel the medium does not absorb), whose
// result is exactly 1 in every exponential.
RT_DEVICE real ExpUnlessZero(real x) { return x == 0.0f ? 1.0f : ExpR(x); }

// Beer-Lambert attenuation over a path of length `distance` inside a medium. `portable`
// takes util/transcendental.h's exponential, which both devices round alike; both
// integrators take it: glibc's expf and PoCL's exp differ in the last bit for some
// arguments, which moved the ray tree's EXR and moment values between the devices (the
// course scenes' 8-bit images stayed the same). The library's (ExpR) remains for the tests
// that compare the two.
RT_DEVICE real3 BeerLambert(real3 absorption, real distance, int portable) {
  real3 a = absorption * (-distance);
  if (portable) return make_real3(Exp(a.x), Exp(a.y), Exp(a.z));
  return make_real3(ExpUnlessZero(a.x), ExpUnlessZero(a.y), ExpUnlessZero(a.z));
}

#endif  // RT_MATERIAL_FRESNEL_H
