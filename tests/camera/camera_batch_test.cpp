// The CPU reference's camera batch (cl/integrator/pixel.h: PermutationElements, CameraBatchPoints,
// CameraBatchRays, CameraSampleOf) makes the same camera samples, to the bit, as
// GeneratePixelSample, the one-at-a-time path of the OpenCL kernel: for square and
// non-square sample counts, partial batches, the pinhole, the square and the disk lens, the
// course and the exact camera, and motion blur.
#include <gtest/gtest.h>

#include <cstring>
#include <vector>

#include "cl/camera/camera_batch.h"

namespace {

struct Config {
  int samples;
  int features;
  int course;
  float aperture;
  int lens;
};

SceneHeader Header(const Config& c) {
  SceneHeader h;
  std::memset(&h, 0, sizeof h);
  Camera& cam = h.camera;
  cam.position = make_float3(0.0f, 5.0f, 25.0f);
  cam.u = make_float3(1.0f, 0.0f, 0.0f);
  cam.v = make_float3(0.0f, 1.0f, 0.0f);
  cam.w = make_float3(0.0f, 0.0f, 1.0f);
  cam.course_eye = cam.position;
  cam.course_q = make_float3(-1.0f, 6.0f, 24.0f);
  cam.course_u = cam.u;
  cam.course_v = cam.v;
  cam.left = -1.0f;
  cam.right = 1.0f;
  cam.bottom = -0.75f;
  cam.top = 0.75f;
  cam.near_distance = 1.0f;
  cam.aperture = c.aperture;
  cam.focus_distance = 21.0f;
  cam.lens = c.lens;
  cam.width = 16;
  cam.height = 12;
  cam.samples = c.samples;
  int strata = 0;
  while ((strata + 1) * (strata + 1) <= c.samples) ++strata;
  cam.strata = strata * strata == c.samples ? strata : 0;
  h.features = c.features;
  h.flags = c.course ? RT_FLAG_COURSE_CAMERA : 0;
  h.seed = 7u;
  return h;
}

void ExpectSameSample(const CameraSample& a, const CameraSample& b, const char* what) {
  EXPECT_EQ(a.key.prefix, b.key.prefix) << what;
  EXPECT_EQ(std::memcmp(&a.film, &b.film, sizeof a.film), 0) << what;
  EXPECT_EQ(std::memcmp(&a.ray.origin, &b.ray.origin, sizeof a.ray.origin), 0) << what;
  EXPECT_EQ(std::memcmp(&a.ray.direction, &b.ray.direction, sizeof a.ray.direction), 0) << what;
  EXPECT_EQ(std::memcmp(&a.ray.time, &b.ray.time, sizeof a.ray.time), 0) << what;
}

TEST(CameraBatch, MakesTheSamplesOfTheOneAtATimePath) {
  const int ms = RT_FEATURE_MULTISAMPLE, dof = RT_FEATURE_DEPTH_OF_FIELD;
  std::vector<Config> configs;
  for (int samples : {1, 4, 9, 10, 100})
    for (int features : {0, ms, dof, ms | dof, ms | dof | RT_FEATURE_MOTION_BLUR})
      for (int course : {0, 1})
        for (float aperture : {0.0f, 1.5f})
          for (int lens : {RT_LENS_SQUARE, RT_LENS_DISK})
            configs.push_back({samples, features, course, aperture, lens});
  int batched = 0;
  for (const Config& c : configs) {
    SceneHeader h = Header(c);
    SceneData sd;
    std::memset(&sd, 0, sizeof sd);
    sd.header = &h;
    batched += CameraBatchRaysMade(&sd);
    for (int y : {0, 5, 11})
      for (int x : {0, 7, 15}) {
        CameraPixel cp = MakeCameraPixel(&sd, x, y);
        const int b = RT_PERMUTATION_BATCH;
        uint stratum[b] = {0u}, lens_stratum[b] = {0u};
        // Batches from sample 0 and from sample 3 (a pass that starts mid-batch).
        for (int begin : {0, 3})
          for (int first = begin; first < c.samples; first += b) {
            const int n = c.samples - first < b ? c.samples - first : b;
            if (RT_HAS(&sd, ms) && cp.key.strata > 1u)
              PermutationElements(first, n, cp.key.samples, cp.film_strata, stratum);
            if (RT_HAS(&sd, dof) && cp.key.strata > 1u)
              PermutationElements(first, n, cp.key.samples, cp.lens_strata, lens_stratum);
            uint prefix[b];
            real point[4 * b], ray[6 * b];
            CameraBatchPoints(&sd, cp.key, first, stratum, lens_stratum, prefix, point);
            const int batch_rays = CameraBatchRaysMade(&sd);
            if (batch_rays) CameraBatchRays(&sd, &cp, point, ray);
            for (int k = 0; k < n; ++k) {
              const uint s = static_cast<uint>(first + k);
              CameraSample batch = CameraSampleOf(&sd, &cp, PixelSampleKeyOf(cp.key, s, prefix[k]),
                                                  make_real2(point[k], point[b + k]),
                                                  make_real2(point[2 * b + k], point[3 * b + k]),
                                                  batch_rays ? ray : nullptr, k);
              ExpectSameSample(batch, GeneratePixelSample(&sd, &cp, s),
                               ("samples " + std::to_string(c.samples) + " features " +
                                std::to_string(c.features) + " course " + std::to_string(c.course) +
                                " aperture " + std::to_string(c.aperture) + " lens " +
                                std::to_string(c.lens) + " sample " + std::to_string(s))
                                   .c_str());
            }
          }
      }
  }
  // The batched rays were compared too, not only the per-sample fallback.
  EXPECT_GT(batched, 0);
}

}  // namespace
