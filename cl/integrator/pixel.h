// The pixel loop, shared by the CPU reference and the kernel: a pixel's camera samples,
// each traced by the integrator its camera asks for and added to the film in order, so
// both devices sum alike and agree to the bit when their samples do.
#ifndef RT_INTEGRATOR_PIXEL_H
#define RT_INTEGRATOR_PIXEL_H

#include "../camera/camera_batch.h"
#include "../film/film.h"
#include "integrator.h"

// A pixel's camera samples are made RT_CAMERA_BATCH at a time before any of them is traced.
// Making one is a chain of dependent hashes, multiplies, divisions and a square root
// (cl/camera/camera.h, cl/sampling/sampler.h), and no sample's chain needs another's
// result: made together, the chains overlap in a CPU core's out-of-order window, where made
// each between two traversals each chain's latency is paid in full. A GPU hides latency
// with other work-items instead, and each sample held costs it registers: one at a time
// there. An OpenCL device on a CPU (RT_CL_CPU_DEVICE, set by the host: PoCL) runs a
// work-item's samples on one core as the reference does, and batches as it does.
#if defined(__OPENCL_C_VERSION__) && !defined(RT_CL_CPU_DEVICE)
#define RT_CAMERA_BATCH 1
#else
#define RT_CAMERA_BATCH RT_PERMUTATION_BATCH  // 8
#endif

// Runs samples [begin, end) of pixel (x, y) into *acc, in order. The first sample of a
// pixel also records its deterministic primary-hit facts.
RT_DEVICE void AccumulatePixel(RT_PRIVATE const SceneData* sd, int x, int y, int begin, int end,
                               RT_GLOBAL PixelAccum* acc, RT_GLOBAL PrimaryInfo* primary) {
  PixelAccum a = *acc;
  uint rays = 0u;
  CameraPixel cp = MakeCameraPixel(sd, x, y);
#if RT_CAMERA_BATCH > 1
  // The batch's film and lens strata are made at once (PermutationElements): one at a time,
  // each sample's walk ends in a branch mispredicted about every other sample, and its
  // division lies on the chain to the ray.
  int film_strata = RT_HAS(sd, RT_FEATURE_MULTISAMPLE) && cp.key.strata > 1u;
  int lens_strata = RT_HAS(sd, RT_FEATURE_DEPTH_OF_FIELD) && cp.key.strata > 1u;
  uint stratum[RT_PERMUTATION_BATCH], lens_stratum[RT_PERMUTATION_BATCH];
  for (int k = 0; k < RT_PERMUTATION_BATCH; ++k) stratum[k] = lens_stratum[k] = 0u;
  int batch_rays = CameraBatchRaysMade(sd);
  int sobol = cp.key.sobol != 0u;
#endif
  for (int first = begin; first < end; first += RT_CAMERA_BATCH) {
    int n = end - first < RT_CAMERA_BATCH ? end - first : RT_CAMERA_BATCH;
    CameraSample batch[RT_CAMERA_BATCH];
#if RT_CAMERA_BATCH > 1
    if (sobol) {
      // The Sobol sampler's camera samples have no strata to batch: one at a time.
      for (int k = 0; k < n; ++k) batch[k] = GeneratePixelSample(sd, &cp, (uint)(first + k));
    } else {
      if (film_strata) PermutationElements((uint)first, n, cp.key.samples, cp.film_strata, stratum);
      if (lens_strata)
        PermutationElements((uint)first, n, cp.key.samples, cp.lens_strata, lens_stratum);
      uint prefix[RT_PERMUTATION_BATCH];
      real point[4 * RT_PERMUTATION_BATCH];
      CameraBatchPoints(sd, cp.key, (uint)first, stratum, lens_stratum, prefix, point);
      real ray[6 * RT_PERMUTATION_BATCH];
      if (batch_rays) CameraBatchRays(sd, &cp, point, ray);
      for (int k = 0; k < n; ++k) {
        const int b = RT_PERMUTATION_BATCH;
        batch[k] =
            CameraSampleOf(sd, &cp, PixelSampleKeyOf(cp.key, (uint)(first + k), prefix[k]),
                           make_real2(point[k], point[b + k]),
                           make_real2(point[2 * b + k], point[3 * b + k]), batch_rays ? ray : 0, k);
      }
    }
#else
    for (int k = 0; k < n; ++k) batch[k] = GeneratePixelSample(sd, &cp, (uint)(first + k));
#endif
    for (int k = 0; k < n; ++k) {
      int s = first + k;
      real w;
      PrimaryInfo info;
      real3 l = RenderSample(sd, &cp, &batch[k], &w, s == 0 ? &info : 0, &rays);
      if (s == 0) *primary = info;
      AddFilmSample(&a, l, w);
    }
  }
  a.rays += rays;
  *acc = a;
}

#endif  // RT_INTEGRATOR_PIXEL_H
