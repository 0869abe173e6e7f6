// Camera rays: the course's pinhole camera with an optional thin lens.
#ifndef RT_CAMERA_H
#define RT_CAMERA_H

#include "../features.h"
#include "../geometry/ray.h"
#include "../sampling/sampler.h"
#include "../scene_types.h"

// Maps [0,1)^2 to the unit disk with Shirley and Chiu's concentric map, so strata stay
// compact (used only by the optional disk lens). Its sine and cosine are
// util/transcendental.h's, which both devices round alike (glibc's sinf and cosf and PoCL's
// differ in the last bit for some angles, which moves a camera ray).
RT_DEVICE real2 SampleConcentricDisk(real2 u) {
  real ox = 2.0f * u.x - 1.0f, oy = 2.0f * u.y - 1.0f;
  if (ox == 0.0f && oy == 0.0f) return make_real2(0.0f, 0.0f);
  real r, theta;
  if (fabs(ox) > fabs(oy)) {
    r = ox;
    theta = (RT_PI / 4.0f) * (oy / ox);
  } else {
    r = oy;
    theta = (RT_PI / 2.0f) - (RT_PI / 4.0f) * (ox / oy);
  }
  real sin_theta, cos_theta;
  SinCos(theta, &sin_theta, &cos_theta);
  return make_real2(r * cos_theta, r * sin_theta);
}

// The width and height of a pixel on the course camera's film: the same for every sample,
// so computed once per pixel (CameraPixel) rather than divided out again per sample.
RT_DEVICE real2 CourseFilmPixelSize(RT_GLOBAL const Camera* cam) {
  return make_real2((cam->right - cam->left) / (real)cam->width,
                    (cam->top - cam->bottom) / (real)cam->height);
}

// The direction of the course renderer's camera ray through film position (px, py): the
// film point s = q + su u - sv v and s - e are formed in world space, in float, so their
// rounding (up to 1e-3 pixel for a camera 30 units from the origin) is the course's. On
// steep gradients, the silhouettes of smooth meshes and shadow terminators, that decides
// the 8-bit value: hw1 windmill_smooth has several times fewer pixels off the course's
// image with these rays than with exact ones. Each operation and its order is the one that
// matched (su from the pixel width, s summed left to right, d divided by its length).
// `pixel_size` is CourseFilmPixelSize(cam).
// CourseFilmAxis is one axis of s - e, so the CPU reference's camera batch
// (cl/camera/camera_batch.h) forms it lane by lane with the same operations.
RT_DEVICE real CourseFilmAxis(real q, real u, real v, real eye, real su, real sv) {
  return (q + u * su - v * sv) - eye;
}

RT_DEVICE real3 CourseCameraDirection(RT_GLOBAL const Camera* cam, real2 pixel_size, real px,
                                      real py) {
  real su = pixel_size.x * px;
  real sv = pixel_size.y * py;
  real3 q = ToReal3(cam->course_q), u = ToReal3(cam->course_u), v = ToReal3(cam->course_v);
  real3 e = ToReal3(cam->course_eye);
  real3 d = make_real3(CourseFilmAxis(q.x, u.x, v.x, e.x, su, sv),
                       CourseFilmAxis(q.y, u.y, v.y, e.y, su, sv),
                       CourseFilmAxis(q.z, u.z, v.z, e.z, su, sv));
  real len = Length(d);
  return make_real3(d.x / len, d.y / len, d.z / len);
}

// The direction of the camera ray through film position (px, py), formed relative to the
// camera: subtracting its position from an absolute film point would cancel away the
// film's detail far from the origin.
RT_DEVICE real3 ExactCameraDirection(RT_GLOBAL const Camera* cam, real px, real py) {
  real su = (cam->right - cam->left) * (px / (real)cam->width);
  real sv = (cam->top - cam->bottom) * (py / (real)cam->height);
  real3 film = ToReal3(cam->u) * (cam->left + su) + ToReal3(cam->v) * (cam->top - sv) -
               ToReal3(cam->w) * cam->near_distance;
  return Normalize(film);
}

// One axis of the thin lens's offset from the camera's position for the lens point l
// (centred on the lens): (u l.x + v l.y) aperture; per axis, as for CourseFilmAxis.
RT_DEVICE real LensOffsetAxis(real u, real v, real2 l, real aperture) {
  return (u * l.x + v * l.y) * aperture;
}

// The ray through film position (px, py) in pixels (x right, y down) at shutter time
// `time`, through lens sample `lens` in [0,1)^2; `course_pixel_size` as for
// CourseCameraDirection.
RT_DEVICE Ray GenerateCameraRay(RT_PRIVATE const SceneData* sd, real2 course_pixel_size, real px,
                                real py, real2 lens, real time) {
  RT_GLOBAL const Camera* cam = &sd->header->camera;
  real3 dir = (sd->header->flags & RT_FLAG_COURSE_CAMERA) != 0
                  ? CourseCameraDirection(cam, course_pixel_size, px, py)
                  : ExactCameraDirection(cam, px, py);
  Ray ray = MakeRay(ToReal3(cam->position), dir, RT_INFINITY, time);
  if (RT_HAS(sd, RT_FEATURE_DEPTH_OF_FIELD) && cam->aperture > 0.0f) {
    // The focal plane lies focus_distance along the gaze; every lens point aims at where
    // the pinhole ray meets it.
    real tfocus = cam->focus_distance / Dot(dir, -ToReal3(cam->w));
    real2 l = make_real2(lens.x - 0.5f, lens.y - 0.5f);
    if (cam->lens == RT_LENS_DISK) {
      real2 disk = SampleConcentricDisk(lens);
      l = make_real2(0.5f * disk.x, 0.5f * disk.y);
    }
    real3 u = ToReal3(cam->u), v = ToReal3(cam->v);
    real3 lens_offset = make_real3(LensOffsetAxis(u.x, v.x, l, cam->aperture),
                                   LensOffsetAxis(u.y, v.y, l, cam->aperture),
                                   LensOffsetAxis(u.z, v.z, l, cam->aperture));
    ray.origin = ToReal3(cam->position) + lens_offset;
    ray.direction = Normalize(dir * tfocus - lens_offset);
  }
  return ray;
}

// What every camera sample of pixel (x, y) shares, computed once per pixel: the pixel's
// part of the sample keys and the stratum permutations of the camera's dimensions.
typedef struct CameraPixel {
  int x, y;
  // The pixel's place on the film, (x, y) / resolution: the background image is stretched
  // over the film, and with the bilinear lookup's convention (texture/image_texture.h) an
  // image of the film's size is reproduced texel for texel, as in the course's galactica images.
  // (0, 0) where the scene has no background image.
  real2 uv;
  PixelKey key;
  uint film_strata, lens_strata, time_strata;  // StratumKey* of RT_DIM_PIXEL, _LENS, _TIME.
  real2 course_pixel_size;                     // CourseFilmPixelSize.
} CameraPixel;

RT_DEVICE CameraPixel MakeCameraPixel(RT_PRIVATE const SceneData* sd, int x, int y) {
  RT_GLOBAL const SceneHeader* h = sd->header;
  RT_GLOBAL const Camera* cam = &h->camera;
  CameraPixel cp;
  cp.x = x;
  cp.y = y;
  cp.uv = make_real2(0.0f, 0.0f);  // Only a background image reads it (texturing.h, Background).
  if (RT_HAS(sd, RT_FEATURE_TEXTURES) && h->background_texture >= 0)
    cp.uv = make_real2((real)x / (real)cam->width, (real)y / (real)cam->height);
  cp.key = MakePixelKey((uint)(y * cam->width + x), (uint)cam->samples, (uint)cam->strata, h->seed);
  if ((h->flags & RT_FLAG_SOBOL_SAMPLER) != 0) UseSobolSampler(&cp.key);
  // The camera ray's light sample is made with the camera sample where the scene draws one
  // (CacheCameraRaySamples).
  if (RT_HAS(sd, RT_LIGHT_AREA | RT_FEATURE_OBJECT_LIGHTS | RT_LIGHT_ENVIRONMENT))
    CacheCameraRaySamples(&cp.key, RT_CACHE_LIGHT);
  cp.film_strata = cp.lens_strata = cp.time_strata = 0u;
  // One stratum (one sample per pixel) needs no permutation key (Stratified2DKeyed), nor does
  // the Sobol sampler.
  int permuted = cp.key.sobol == 0u;
  if (permuted && cam->strata > 1) {
    if (RT_HAS(sd, RT_FEATURE_MULTISAMPLE))
      cp.film_strata = StratumKey(cp.key.hash, cp.key.seed, RT_DIM_PIXEL, RT_STRATA_SALT_2D);
    if (RT_HAS(sd, RT_FEATURE_DEPTH_OF_FIELD))
      cp.lens_strata = StratumKey(cp.key.hash, cp.key.seed, RT_DIM_LENS, RT_STRATA_SALT_2D);
  }
  if (permuted && RT_HAS(sd, RT_FEATURE_MOTION_BLUR) && cam->samples > 1)
    cp.time_strata = StratumKey(cp.key.hash, cp.key.seed, RT_DIM_TIME, RT_STRATA_SALT_1D);
  cp.course_pixel_size = CourseFilmPixelSize(cam);
  return cp;
}

// Camera sample `sample` of a pixel: its key (every later random number of the sample
// derives from it), its film position within the pixel (for the reconstruction filter)
// and its ray. The renderer and bench/embree_bench.cpp take their camera rays from here.
typedef struct CameraSample {
  SampleKey key;
  real2 film;
  Ray ray;
} CameraSample;

// Whether the camera samples' film and lens positions are drawn (else the pixel's and the
// lens's centre).
RT_DEVICE int CameraFilmDrawn(RT_PRIVATE const SceneData* sd) {
  return RT_HAS(sd, RT_FEATURE_MULTISAMPLE) && sd->header->camera.samples > 1;
}
#define RT_CAMERA_LENS_DRAWN(sd) RT_HAS(sd, RT_FEATURE_DEPTH_OF_FIELD)

// The camera sample of key `key` (PixelSampleKeyOf) of a pixel, given its film and lens
// positions in [0, 1)^2 (GeneratePixelSample; cl/integrator/pixel.h makes a batch's at once,
// CameraBatchPoints). `ray`: null, or sample `k` of a batch's rays (CameraBatchRays).
RT_DEVICE_INLINE CameraSample CameraSampleOf(RT_PRIVATE const SceneData* sd,
                                             RT_PRIVATE const CameraPixel* cp, SampleKey key,
                                             real2 film, real2 lens, RT_PRIVATE const real* ray,
                                             int k) {
  CameraSample cs;
  cs.key = key;
  cs.film = film;
  real time = 0.0f;
  if (RT_HAS(sd, RT_FEATURE_MOTION_BLUR))
    time = Stratified1DKeyed(cs.key, RT_DIM_TIME, cp->time_strata);
  if (ray) {
    const int b = RT_PERMUTATION_BATCH;
    cs.ray = MakeRay(make_real3(ray[k], ray[b + k], ray[2 * b + k]),
                     make_real3(ray[3 * b + k], ray[4 * b + k], ray[5 * b + k]), RT_INFINITY, time);
  } else {
    cs.ray = GenerateCameraRay(sd, cp->course_pixel_size, (real)cp->x + film.x,
                               (real)cp->y + film.y, lens, time);
  }
  return cs;
}

// The kernel's camera sample, one at a time: the strata first, off the key's chain, as
// before the CPU reference made its samples a batch at a time.
RT_DEVICE_INLINE CameraSample GeneratePixelSample(RT_PRIVATE const SceneData* sd,
                                                  RT_PRIVATE const CameraPixel* cp, uint sample) {
  uint film_stratum = 0u, lens_stratum = 0u;
  int permuted = cp->key.strata > 1u && cp->key.sobol == 0u;  // StratumPointOf ignores it else.
  if (RT_HAS(sd, RT_FEATURE_MULTISAMPLE) && permuted)
    film_stratum = PermutationElement(sample, cp->key.samples, cp->film_strata);
  if (RT_HAS(sd, RT_FEATURE_DEPTH_OF_FIELD) && permuted)
    lens_stratum = PermutationElement(sample, cp->key.samples, cp->lens_strata);
  SampleKey k = PixelSampleKey(cp->key, sample);
  real2 film = make_real2(0.5f, 0.5f), lens = make_real2(0.5f, 0.5f);
  if (CameraFilmDrawn(sd)) film = StratumPoint2D(k, RT_DIM_PIXEL, film_stratum);
  if (RT_CAMERA_LENS_DRAWN(sd)) lens = StratumPoint2D(k, RT_DIM_LENS, lens_stratum);
  return CameraSampleOf(sd, cp, k, film, lens, 0, 0);
}

RT_DEVICE CameraSample GenerateCameraSample(RT_PRIVATE const SceneData* sd, int x, int y,
                                            uint sample) {
  CameraPixel cp = MakeCameraPixel(sd, x, y);
  return GeneratePixelSample(sd, &cp, sample);
}

#endif  // RT_CAMERA_H
