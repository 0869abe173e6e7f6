// The camera batch of a CPU device, the reference's or an OpenCL CPU device's (cl/integrator/pixel.h,
// RT_CAMERA_BATCH): the keys, film and lens positions and course-camera rays of
// RT_PERMUTATION_BATCH samples of a pixel, made as loops over the batch that GCC makes
// eight lanes wide (PoCL keeps them scalar; the batch still overlaps the samples' chains). Each
// value is the one the one-at-a-time path (GeneratePixelSample, cl/camera/camera.h) makes, to the bit: the
// loops call that path's per-axis steps (CourseFilmAxis, LensOffsetAxis, StratumRow) in its order
// (tests/camera/camera_batch_test.cpp).
#ifndef RT_CAMERA_BATCH_H
#define RT_CAMERA_BATCH_H

#include "camera.h"

// Whether CameraBatchRays makes a batch's rays: the course camera's, through a pinhole or
// the square lens (the disk lens's sines and the exact camera stay per sample).
// The double build (--precision double) keeps them per sample: with them, GCC inlined its
// traversal otherwise and warned of a field it cannot see is set (-Wmaybe-uninitialized).
RT_DEVICE int CameraBatchRaysMade(RT_PRIVATE const SceneData* sd) {
#ifdef RT_REAL_DOUBLE
  (void)sd;
  return 0;
#else
  RT_GLOBAL const Camera* cam = &sd->header->camera;
  // The disk lens's test first: where the kernel is built without depth of field, RT_HAS is
  // a constant 0, and clang warns of a constant right operand of &&.
  return !(RT_HAS(sd, RT_FEATURE_DEPTH_OF_FIELD) && cam->aperture > 0.0f &&
           cam->lens == RT_LENS_DISK) &&
         (sd->header->flags & RT_FLAG_COURSE_CAMERA) != 0;
#endif
}

// GenerateCameraRay for a batch of film and lens positions (point, as CameraBatchPoints
// makes them), where CameraBatchRaysMade: ray[B * c + k] is component c of sample k's
// origin (c = 0..2) and direction (3..5). Each operation is GenerateCameraRay's, in its
// order, on its operands, so each value is the same to the bit; as loops over the batch,
// the compiler makes the two square roots and four divisions of each ray eight lanes wide,
// where one ray's were a chain no other work overlapped.
RT_DEVICE_INLINE void CameraBatchRays(RT_PRIVATE const SceneData* sd,
                                      RT_PRIVATE const CameraPixel* cp,
                                      RT_PRIVATE const real* point, RT_PRIVATE real* ray) {
  RT_GLOBAL const Camera* cam = &sd->header->camera;
  const int b = RT_PERMUTATION_BATCH;
  real3 q = ToReal3(cam->course_q), u = ToReal3(cam->course_u), v = ToReal3(cam->course_v);
  real3 eye = ToReal3(cam->course_eye), pos = ToReal3(cam->position);
  real2 size = cp->course_pixel_size;
  // The square roots are taken in a loop of their own: GCC keeps sqrt's errno check, which
  // leaves a loop with one scalar, and the divisions are then eight lanes wide.
  real len[RT_PERMUTATION_BATCH];
  for (int k = 0; k < b; ++k) {  // CourseCameraDirection.
    real su = size.x * ((real)cp->x + point[k]);
    real sv = size.y * ((real)cp->y + point[b + k]);
    real dx = CourseFilmAxis(q.x, u.x, v.x, eye.x, su, sv);
    real dy = CourseFilmAxis(q.y, u.y, v.y, eye.y, su, sv);
    real dz = CourseFilmAxis(q.z, u.z, v.z, eye.z, su, sv);
    ray[k] = pos.x;
    ray[b + k] = pos.y;
    ray[2 * b + k] = pos.z;
    ray[3 * b + k] = dx;
    ray[4 * b + k] = dy;
    ray[5 * b + k] = dz;
    len[k] = dx * dx + dy * dy + dz * dz;
  }
  for (int k = 0; k < b; ++k) len[k] = sqrt(len[k]);
  for (int k = 0; k < b; ++k) {
    ray[3 * b + k] = ray[3 * b + k] / len[k];
    ray[4 * b + k] = ray[4 * b + k] / len[k];
    ray[5 * b + k] = ray[5 * b + k] / len[k];
  }
  if (!(RT_HAS(sd, RT_FEATURE_DEPTH_OF_FIELD) && cam->aperture > 0.0f)) return;
  real3 nw = -ToReal3(cam->w), cu = ToReal3(cam->u), cv = ToReal3(cam->v);
  real aperture = cam->aperture, focus = cam->focus_distance;
  for (int k = 0; k < b; ++k) {  // The thin lens, square.
    real dx = ray[3 * b + k], dy = ray[4 * b + k], dz = ray[5 * b + k];
    real tfocus = focus / (dx * nw.x + dy * nw.y + dz * nw.z);
    real2 l = make_real2(point[2 * b + k] - 0.5f, point[3 * b + k] - 0.5f);
    real ox = LensOffsetAxis(cu.x, cv.x, l, aperture);
    real oy = LensOffsetAxis(cu.y, cv.y, l, aperture);
    real oz = LensOffsetAxis(cu.z, cv.z, l, aperture);
    ray[k] = pos.x + ox;
    ray[b + k] = pos.y + oy;
    ray[2 * b + k] = pos.z + oz;
    real tx = dx * tfocus - ox, ty = dy * tfocus - oy, tz = dz * tfocus - oz;
    ray[3 * b + k] = tx;
    ray[4 * b + k] = ty;
    ray[5 * b + k] = tz;
    len[k] = tx * tx + ty * ty + tz * tz;
  }
  for (int k = 0; k < b; ++k) len[k] = sqrt(len[k]);
  for (int k = 0; k < b; ++k) {  // Normalize.
    real inv = 1.0f / len[k];
    ray[3 * b + k] = ray[3 * b + k] * inv;
    ray[4 * b + k] = ray[4 * b + k] * inv;
    ray[5 * b + k] = ray[5 * b + k] * inv;
  }
}

// The stratified points (Stratified2DKeyed) of a batch: jitter xi[k], xi[B + k] in stratum
// stratum[k] of the pixel's pattern, into out[k], out[B + k] (B = RT_PERMUTATION_BATCH).
RT_DEVICE_INLINE void BatchStratumPoints(PixelKey p, RT_PRIVATE const uint* stratum,
                                         RT_PRIVATE real* xi, RT_PRIVATE real* out) {
  if (p.strata <= 1u) {
    for (int k = 0; k < 2 * RT_PERMUTATION_BATCH; ++k) out[k] = xi[k];
    return;
  }
  real inv = 1.0f / (real)p.strata;
  uint row[RT_PERMUTATION_BATCH];
  // Two loops, so the magic multiply's is vectorized: with the division as its alternative
  // (StratumRow), GCC left it scalar.
  if (p.strata_magic != 0u) {
    for (int k = 0; k < RT_PERMUTATION_BATCH; ++k)
      row[k] = StratumRow(stratum[k], p.strata, p.strata_magic);
  } else {
    for (int k = 0; k < RT_PERMUTATION_BATCH; ++k) row[k] = stratum[k] / p.strata;
  }
  for (int k = 0; k < RT_PERMUTATION_BATCH; ++k) {
    out[k] = StratumCoordinate((int)(stratum[k] - row[k] * p.strata), xi[k], inv);
    out[RT_PERMUTATION_BATCH + k] =
        StratumCoordinate((int)row[k], xi[RT_PERMUTATION_BATCH + k], inv);
  }
}

// The prefixes and film and lens positions of samples first .. first + B - 1 of the pixel
// (B = RT_PERMUTATION_BATCH), as GeneratePixelSample makes them, for a CPU device's
// camera batch (cl/integrator/pixel.h): prefix[k], film (point[k], point[B + k]), lens (point[2B + k],
// point[3B + k]); film_stratum and lens_stratum as PermutationElements makes them. A
// sample's prefix and jitters are seven hash rounds, one sample's a chain of scalar
// multiplies and shifts: as loops over the batch, the compiler makes each eight lanes wide.
RT_DEVICE_INLINE void CameraBatchPoints(RT_PRIVATE const SceneData* sd, PixelKey p, uint first,
                                        RT_PRIVATE const uint* film_stratum,
                                        RT_PRIVATE const uint* lens_stratum,
                                        RT_PRIVATE uint* prefix, RT_PRIVATE real* point) {
  for (int k = 0; k < RT_PERMUTATION_BATCH; ++k) prefix[k] = PixelSamplePrefix(p, first + (uint)k);
  real xi[2 * RT_PERMUTATION_BATCH];
  for (int k = 0; k < 4 * RT_PERMUTATION_BATCH; ++k) point[k] = 0.5f;
  if (CameraFilmDrawn(sd)) {
    for (int k = 0; k < RT_PERMUTATION_BATCH; ++k) {
      xi[k] = RandomOfPrefix(prefix[k], RT_DIM_PIXEL);
      xi[RT_PERMUTATION_BATCH + k] = RandomOfPrefix(prefix[k], RT_DIM_SECOND(RT_DIM_PIXEL));
    }
    BatchStratumPoints(p, film_stratum, xi, point);
  }
  if (RT_CAMERA_LENS_DRAWN(sd)) {
    for (int k = 0; k < RT_PERMUTATION_BATCH; ++k) {
      xi[k] = RandomOfPrefix(prefix[k], RT_DIM_LENS);
      xi[RT_PERMUTATION_BATCH + k] = RandomOfPrefix(prefix[k], RT_DIM_SECOND(RT_DIM_LENS));
    }
    BatchStratumPoints(p, lens_stratum, xi, point + 2 * RT_PERMUTATION_BATCH);
  }
}

#endif  // RT_CAMERA_BATCH_H
