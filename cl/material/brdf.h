// The reflection models of the course's assignment 6 (hw6/SPEC.txt and its BRDF notes), as
// pure functions of the unit normal n, the unit direction towards the viewer wo and the
// unit direction towards the light wi, all in world space:
//
//   original Phong        f = kd + ks cos^p(a_r) / cos(t_i)
//   original Blinn-Phong  f = kd + ks cos^p(a_h) / cos(t_i)   (the shading of assignments 1-5)
//   modified Phong        f = kd + ks cos^p(a_r)
//   modified Blinn-Phong  f = kd + ks cos^p(a_h)
//     normalized:         kd / pi, and ks (p + 2) / (2 pi) (Phong) or (p + 8) / (8 pi) (Blinn)
//   Torrance-Sparrow      f = kd / pi + ks D(a_h) F(b) G / (4 cos(t_i) cos(t_o)),
//                         D = (p + 2) / (2 pi) cos^p(a_h), G the V-cavity masking term,
//                         F the conductor Fresnel reflectance of the complex index n + ik
//                         (fresnel.h) at the angle of incidence t_i, as the course's
//                         reference images show (not at b); `kdfresnel` weights kd by (1 - F)
//
// where a_r is the angle between wo and the mirror image of wi, a_h the angle between n and
// the half vector h. The functions return f cos(t_i), the
// factor that multiplies irradiance-like quantities (I / d^2 for point lights): the original
// models then need no division by cos(t_i) and the original Blinn-Phong rounds exactly as
// the course's shading always did. Sampling draws a mixture of a cosine-weighted diffuse
// lobe and the specular lobe (around the mirror direction for the Phong models, of the half
// vector for the others), chosen in proportion to the largest component of kd and ks.
// Valid OpenCL C 1.2 and C++17.
#ifndef RT_BRDF_H
#define RT_BRDF_H

#include "../util/transcendental.h"  // Pow.
#include "fresnel.h"                 // FrConductor.

#define RT_BRDF_ORIGINAL_BLINN_PHONG 0
#define RT_BRDF_ORIGINAL_PHONG 1
#define RT_BRDF_MODIFIED_BLINN_PHONG 2
#define RT_BRDF_MODIFIED_PHONG 3
#define RT_BRDF_TORRANCE_SPARROW 4

#define RT_BRDF_NORMALIZED 1  // Modified Phong and Blinn-Phong: the energy-normalized forms.
#define RT_BRDF_KD_FRESNEL 2  // Torrance-Sparrow: diffuse weighted by 1 - F.

typedef struct BrdfParams {
  real3 kd, ks;
  real exponent;
  int model;
  int flags;
  real eta, kappa;  // Complex refraction index of the surface (Torrance-Sparrow's F).
} BrdfParams;

RT_DEVICE int BrdfIsPhongLobe(int model) {
  return model == RT_BRDF_ORIGINAL_PHONG || model == RT_BRDF_MODIFIED_PHONG;
}

// f cos(t_i) for one pair of directions; zero when either lies below the surface.
RT_DEVICE real3 BrdfFCos(RT_PRIVATE const BrdfParams* b, real3 n, real3 wo, real3 wi) {
  real cos_i = Dot(n, wi);
  real cos_o = Dot(n, wo);
  if (cos_i <= 0.0f || cos_o <= 0.0f) return Vec3(0.0f);
  real p = b->exponent;
  int normalized = (b->flags & RT_BRDF_NORMALIZED) != 0;
  if (b->model == RT_BRDF_TORRANCE_SPARROW) {
    real3 h = Normalize(wi + wo);
    real cos_h = fmax(RT_R(0.0), Dot(n, h));
    real o_h = Dot(wo, h);
    real d = (p + 2.0f) * (1.0f / (2.0f * RT_PI)) * PowF(cos_h, p);
    real g = fmin(RT_R(1.0), fmin(2.0f * cos_h * cos_o / o_h, 2.0f * cos_h * cos_i / o_h));
    real f = FrConductor(cos_i, b->eta, b->kappa);
    real kd_scale = (b->flags & RT_BRDF_KD_FRESNEL) != 0 ? (1.0f - f) : 1.0f;
    real spec = d * f * g / (4.0f * cos_o);  // The cos(t_i) of the denominator cancels.
    return b->kd * (kd_scale * (1.0f / RT_PI) * cos_i) + b->ks * spec;
  }
  real cos_a;
  if (BrdfIsPhongLobe(b->model)) {
    cos_a = fmax(RT_R(0.0), Dot(Reflect(wi, n), wo));
  } else {
    real3 h = Normalize(wi + wo);
    cos_a = fmax(RT_R(0.0), Dot(n, h));
  }
  real spec = cos_a > 0.0f ? PowF(cos_a, p) : 0.0f;
  if (b->model == RT_BRDF_ORIGINAL_BLINN_PHONG || b->model == RT_BRDF_ORIGINAL_PHONG)
    return b->kd * cos_i + b->ks * spec;
  if (normalized) {
    real norm = BrdfIsPhongLobe(b->model) ? (p + 2.0f) * (1.0f / (2.0f * RT_PI))
                                          : (p + 8.0f) * (1.0f / (8.0f * RT_PI));
    return (b->kd * (1.0f / RT_PI) + b->ks * (norm * spec)) * cos_i;
  }
  return (b->kd + b->ks * spec) * cos_i;
}

// Probability of choosing the specular lobe when sampling.
RT_DEVICE real BrdfSpecularWeight(RT_PRIVATE const BrdfParams* b) {
  real d = MaxComponent(b->kd), s = MaxComponent(b->ks);
  return d + s > 0.0f ? s / (d + s) : 0.0f;
}

// Exponent of the cos^e lobe that sampling draws: the Phong lobe around the mirror
// direction, or the half vector's distribution (cos^(p+1) for Torrance-Sparrow, which
// samples D cos(a_h) exactly).
RT_DEVICE real BrdfLobeExponent(RT_PRIVATE const BrdfParams* b) {
  return b->model == RT_BRDF_TORRANCE_SPARROW ? b->exponent + 1.0f : b->exponent;
}

// Density of a cos^e lobe, normalized over the hemisphere around its axis.
RT_DEVICE real CosineLobePdf(real cos_a, real e) {
  return cos_a > 0.0f ? (e + 1.0f) * (1.0f / (2.0f * RT_PI)) * PowF(cos_a, e) : 0.0f;
}

// A direction of the cos^e lobe around unit axis `a` from u in [0, 1)^2. The root and the
// angle come from util/transcendental.h, not the libraries, so both devices draw the same
// direction.
RT_DEVICE real3 SampleCosineLobe(real3 a, real e, real2 u) {
  // 1 - u keeps cos_t > 0; e = 1 is the cosine-weighted hemisphere.
  real cos_t = e == 1.0f ? sqrt(1.0f - u.x) : Pow(1.0f - u.x, 1.0f / (e + 1.0f));
  real sin_t = sqrt(fmax(RT_R(0.0), 1.0f - cos_t * cos_t));
  return SphericalDirection(a, sin_t, cos_t, u.y);
}

// Solid-angle density of BrdfSample choosing wi.
RT_DEVICE real BrdfPdf(RT_PRIVATE const BrdfParams* b, real3 n, real3 wo, real3 wi) {
  real w = BrdfSpecularWeight(b);
  real cos_i = Dot(n, wi);
  real pdf = cos_i > 0.0f ? (1.0f - w) * cos_i * (1.0f / RT_PI) : 0.0f;
  if (w > 0.0f) {
    real e = BrdfLobeExponent(b);
    if (BrdfIsPhongLobe(b->model)) {
      pdf += w * CosineLobePdf(Dot(wi, Reflect(wo, n)), e);
    } else {
      real3 h = Normalize(wi + wo);
      real o_h = Dot(wo, h);
      if (o_h > 0.0f) pdf += w * CosineLobePdf(Dot(n, h), e) / (4.0f * o_h);
    }
  }
  return pdf;
}

// Draws wi for viewing direction wo from u in [0, 1)^2; returns f cos(t_i) and its density
// (a direction below the surface returns zero but keeps its density; a lost draw returns
// density 0, and the caller ends the path).
RT_DEVICE real3 BrdfSample(RT_PRIVATE const BrdfParams* b, real3 n, real3 wo, real2 u,
                           RT_PRIVATE real3* wi, RT_PRIVATE real* pdf) {
  real w = BrdfSpecularWeight(b);
  if (u.x < w) {
    real2 v = make_real2(u.x / w, u.y);  // Reuse the choice's number, rescaled.
    if (BrdfIsPhongLobe(b->model)) {
      *wi = SampleCosineLobe(Reflect(wo, n), BrdfLobeExponent(b), v);
    } else {
      real3 h = SampleCosineLobe(n, BrdfLobeExponent(b), v);
      *wi = Reflect(wo, h);
      // A half vector facing away from wo mirrors it to a direction whose own half vector
      // is -h: no lobe sample there. The draw is lost (density 0), which leaves the
      // estimator unbiased since BrdfPdf is the density of the draws that succeed.
      if (Dot(wo, h) <= 0.0f) {
        *pdf = 0.0f;
        return Vec3(0.0f);
      }
    }
  } else {
    real2 v = make_real2((u.x - w) / (1.0f - w), u.y);
    *wi = SampleCosineLobe(n, 1.0f, v);  // cos^1: the cosine-weighted hemisphere.
  }
  *pdf = BrdfPdf(b, n, wo, *wi);
  return BrdfFCos(b, n, wo, *wi);
}

#endif  // RT_BRDF_H
