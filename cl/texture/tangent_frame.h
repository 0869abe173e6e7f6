// Texture coordinates and their derivatives at a surface point: the course's sphere
// parameterization, per-vertex coordinates on triangles, and the tangents dp/du, dp/dv
// that bump and normal maps perturb the normal in.
#ifndef RT_TANGENT_FRAME_H
#define RT_TANGENT_FRAME_H

#include "../util/transcendental.h"
#include "texture_types.h"

typedef struct TextureFrame {
  real3 dpdu, dpdv;          // World-space tangents (not normalized).
  real3 dpdu_obj, dpdv_obj;  // The same in object space.
  real3 p_obj;               // Object-space position (the unit sphere for spheres).
  real2 uv;
} TextureFrame;

// The course's sphere coordinates of a point p on the unit sphere (object space):
// theta = acos(y) from the north pole, phi = atan2(z, x); u = (pi - phi) / (2 pi) and
// v = theta / pi, so v = 0 at the top of the image.
RT_DEVICE real2 SphereUV(real3 p) {
  real theta = SafeACos(p.y);
  real phi = Atan2(p.z, p.x);
  return make_real2((RT_PI - phi) / (2.0f * RT_PI), theta / RT_PI);
}

// dp/du and dp/dv of the parameterization above, at p = (sin t cos f, cos t, sin t sin f):
// du = -dphi / (2 pi) and dv = dtheta / pi.
RT_DEVICE void SphereTangents(real3 p, RT_PRIVATE real3* dpdu, RT_PRIVATE real3* dpdv) {
  real r = sqrt(p.x * p.x + p.z * p.z);  // sin(theta)
  real cos_phi = r > 0.0f ? p.x / r : 1.0f, sin_phi = r > 0.0f ? p.z / r : 0.0f;
  *dpdu = make_real3(p.z, 0.0f, -p.x) * (2.0f * RT_PI);
  *dpdv = make_real3(p.y * cos_phi, -r, p.y * sin_phi) * RT_PI;
}

// Tangents of a triangle from its edges and the differences of its texture coordinates:
// e1 = dpdu du1 + dpdv dv1 and e2 = dpdu du2 + dpdv dv2, solved for dpdu and dpdv. A
// degenerate mapping (all corners at one u or v) gives zero tangents.
RT_DEVICE void TriangleTangents(real3 p0, real3 p1, real3 p2, real2 t0, real2 t1, real2 t2,
                                RT_PRIVATE real3* dpdu, RT_PRIVATE real3* dpdv) {
  real3 e1 = p1 - p0, e2 = p2 - p0;
  real du1 = t1.x - t0.x, dv1 = t1.y - t0.y, du2 = t2.x - t0.x, dv2 = t2.y - t0.y;
  real det = du1 * dv2 - du2 * dv1;
  if (det == 0.0f) {
    *dpdu = Vec3(0.0f);
    *dpdv = Vec3(0.0f);
    return;
  }
  real inv = 1.0f / det;
  *dpdu = (e1 * dv2 - e2 * dv1) * inv;
  *dpdv = (e2 * du1 - e1 * du2) * inv;
}

// A tangent-space normal (x along dp/du, y along dp/dv, z along n) taken to world space
// through the frame made orthonormal around n.
RT_DEVICE real3 TangentToWorld(real3 n, real3 dpdu, real3 dpdv, real3 t) {
  real3 tu = dpdu - n * Dot(n, dpdu);
  real lu = Length(tu);
  if (!(lu > 0.0f)) return n;
  tu = tu * (1.0f / lu);
  real3 tv = Cross(n, tu);
  if (Dot(tv, dpdv) < 0.0f) tv = -tv;  // Keep v's direction when the mapping is mirrored.
  return Normalize(tu * t.x + tv * t.y + n * t.z);
}

// The normal of the displaced surface p + h n, from the height's derivatives along u and
// v (the change of n itself is neglected, as usual for bump maps); oriented like n.
RT_DEVICE real3 BumpedNormal(real3 n, real3 dpdu, real3 dpdv, real dhdu, real dhdv) {
  real3 qu = dpdu + n * dhdu, qv = dpdv + n * dhdv;
  real3 b = Cross(qu, qv);
  real len = Length(b);
  if (!(len > 0.0f)) return n;
  b = b * (1.0f / len);
  return Dot(b, n) < 0.0f ? -b : b;
}

// The normal of p + h(p) n for a height field defined in space, from its gradient g:
// only the part of g along the surface tilts the normal.
RT_DEVICE real3 GradientBumpedNormal(real3 n, real3 g) {
  real3 tangential = g - n * Dot(g, n);
  real3 b = n - tangential;
  real len = Length(b);
  return len > 0.0f ? b * (1.0f / len) : n;
}

#endif  // RT_TANGENT_FRAME_H
