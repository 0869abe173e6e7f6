// The per-sample integrator: Whitted-style recursion (mirrors, conductors, dielectrics
// with Fresnel and Beer's law) extended with the distribution effects of the course's
// third assignment. Recursion is replaced by an explicit, bounded stack of weighted rays:
// the radiance of a pixel sample is the sum over the ray tree of weight * local light.
#ifndef RT_INTEGRATOR_H
#define RT_INTEGRATOR_H

#include "camera.h"
#include "lights.h"
#include "surface.h"
#include "texture/texturing.h"

// A ray tree of depth D never holds more than D + 2 pending rays (one sibling per level
// plus the pair just pushed), which bounds the explicit stack. Only dielectrics branch:
// a kernel compiled without them needs room for one ray, and less private memory.
#if defined(__OPENCL_C_VERSION__) && !(RT_KERNEL_FEATURES & RT_FEATURE_DIELECTRIC)
#define RT_TASK_STACK 2
#else
#define RT_TASK_STACK (RT_MAX_DEPTH + 2)
#endif

typedef struct RayTask {
  Ray ray;
  float3 weight;
  float3 medium;  // Absorption coefficient of the medium the ray travels in (0: air).
  uint key;       // Identifies the ray in the tree; keys its random dimensions.
  int depth;
  int inside;  // 1 while the ray travels inside a dielectric.
} RayTask;

// Deterministic facts about a pixel's first camera ray, for exact comparisons.
typedef struct PrimaryInfo {
  float t;
  int instance;
  int primitive;
  float3 normal;
} PrimaryInfo;

RT_DEVICE RayTask MakeTask(Ray ray, float3 weight, float3 medium, uint key, int depth, int inside) {
  RayTask task;
  task.ray = ray;
  task.weight = weight;
  task.medium = medium;
  task.key = key;
  task.depth = depth;
  task.inside = inside;
  return task;
}

// The course's glossy reflection: the ideal direction r is moved within a square of
// edge `roughness` spanned by an orthonormal basis around r.
RT_DEVICE float3 PerturbDirection(float3 r, float roughness, float2 xi) {
  float3 u, v;
  CoordinateSystem(r, &u, &v);
  return Normalize(r + (u * (xi.x - 0.5f) + v * (xi.y - 0.5f)) * roughness);
}

RT_DEVICE float3 GlossyDirection(RT_PRIVATE const SceneData* sd, RT_PRIVATE const Material* m,
                                 float3 r, SampleKey sk, uint key, int primary) {
  if (!RT_HAS(sd, RT_FEATURE_ROUGHNESS) || m->roughness <= 0.0f) return r;
  uint dim = HashCombine(key, 0x2000u);
  float2 xi = primary ? Stratified2D(sk, dim) : Random2D(sk, dim);
  return PerturbDirection(r, m->roughness, xi);
}

// Radiance along a camera ray through the pixel at `pixel_uv` (where a background
// texture is looked up); *rays counts every ray cast (camera, secondary, shadow).
RT_DEVICE float3 Li(RT_PRIVATE const SceneData* sd, SampleKey sk, Ray camera_ray, float2 pixel_uv,
                    RT_PRIVATE PrimaryInfo* info, RT_PRIVATE uint* rays) {
  RT_GLOBAL const SceneHeader* h = sd->header;
  int max_depth = h->max_depth < RT_MAX_DEPTH ? h->max_depth : RT_MAX_DEPTH;
  float eps = h->shadow_epsilon;
  RayTask stack[RT_TASK_STACK];
  int sp = 0;
  stack[sp++] = MakeTask(camera_ray, Vec3(1.0f), Vec3(0.0f), RT_DIM_FIRST_FREE, 0, 0);
  float3 radiance = Vec3(0.0f);
  info->instance = -1;
  info->primitive = -1;
  info->t = RT_INFINITY;
  info->normal = Vec3(0.0f);
  while (sp > 0) {
    RayTask task = stack[--sp];
    Ray ray = task.ray;
    Hit hit;
    *rays += 1u;
    int cull = (h->flags & RT_FLAG_CULL_BACK_FACES) != 0 && task.depth == 0;
    if (!IntersectScene(sd, ray, 0, cull, &hit)) {
      if (task.depth == 0 || (h->flags & RT_FLAG_BACKGROUND_ON_SECONDARY_MISS) != 0)
        radiance += task.weight * Background(sd, pixel_uv);
      continue;
    }
    SurfacePoint s = ComputeSurface(sd, ray, hit);
    if (task.depth == 0) {
      info->t = hit.t;
      info->instance = hit.instance;
      info->primitive = hit.primitive;
      info->normal = s.n;
    }
    float3 weight = task.weight;
    if (RT_HAS(sd, RT_FEATURE_DIELECTRIC) && task.inside)
      weight = weight * BeerLambert(task.medium, hit.t * Length(ray.direction));
    float3 wo = Normalize(-ray.direction);
    int front = Dot(wo, s.ng) > 0.0f;
    // The material's parameters at this hit: textures replace some of them and may
    // perturb the shading normal, or paste their colour in place of any shading.
    Material mat = sd->materials[s.material];
    RT_PRIVATE const Material* m = &mat;
    if (RT_HAS(sd, RT_FEATURE_TEXTURES)) {
      float3 paste = Vec3(0.0f);
      if (ApplyTextures(sd, ray, hit, s.p, &mat, &s.n, &paste)) {
        radiance += weight * paste;
        continue;
      }
    }
    int primary = task.depth == 0;
    int dielectric = RT_HAS(sd, RT_FEATURE_DIELECTRIC) && m->type == RT_MATERIAL_DIELECTRIC;
    // Opaque surfaces are shaded with the normal as modelled, also when seen from behind,
    // as the course's renderer does: thin sheets such as grass blades are lit from either
    // side. No light reaches the inner side of a dielectric directly.
    if (!dielectric || front)
      radiance += weight * DirectLighting(sd, m, s.p, s.scale, s.n, s.ng, wo, ray.time, sk,
                                          task.key, primary, rays);
    if (!front) {
      s.n = -s.n;
      s.ng = -s.ng;
    }
    if (task.depth >= max_depth) continue;
    uint reflect_key = HashCombine(task.key, 1u);
    float3 above = OffsetRayOrigin(s.p, s.ng, eps, s.scale);
    float cos_o = Dot(s.n, wo);
    if (RT_HAS(sd, RT_FEATURE_MIRROR) && m->type == RT_MATERIAL_MIRROR) {
      float3 r = GlossyDirection(sd, m, Reflect(wo, s.n), sk, task.key, primary);
      stack[sp++] = MakeTask(MakeRay(above, r, RT_INFINITY, ray.time), weight * m->mirror,
                             task.medium, reflect_key, task.depth + 1, 0);
    } else if (RT_HAS(sd, RT_FEATURE_CONDUCTOR) && m->type == RT_MATERIAL_CONDUCTOR) {
      float fr = FrConductor(fmax(cos_o, 0.0f), m->refraction_index, m->absorption_index);
      float3 r = GlossyDirection(sd, m, Reflect(wo, s.n), sk, task.key, primary);
      stack[sp++] = MakeTask(MakeRay(above, r, RT_INFINITY, ray.time), weight * m->mirror * fr,
                             task.medium, reflect_key, task.depth + 1, 0);
    } else if (RT_HAS(sd, RT_FEATURE_DIELECTRIC) && m->type == RT_MATERIAL_DIELECTRIC) {
      float eta_i = front ? 1.0f : m->refraction_index;
      float eta_t = front ? m->refraction_index : 1.0f;
      float cos_t;
      float fr = FrDielectric(fmax(cos_o, 0.0f), eta_i, eta_t, &cos_t);
      // Either both rays are followed, weighted by Fresnel (the course's splitting), or
      // one is chosen with probability Fresnel (unbiased, one ray per bounce).
      int choose = (h->flags & RT_FLAG_FRESNEL_CHOICE) != 0;
      float pick = choose ? Random1D(sk, HashCombine(task.key, 4u)) : 0.0f;
      int do_reflect = !choose || pick < fr;
      int do_refract = fr < 1.0f && (!choose || pick >= fr);
      if (do_reflect) {
        float3 r = GlossyDirection(sd, m, Reflect(wo, s.n), sk, task.key, primary);
        stack[sp++] =
            MakeTask(MakeRay(above, r, RT_INFINITY, ray.time), choose ? weight : weight * fr,
                     front ? Vec3(0.0f) : task.medium, reflect_key, task.depth + 1, !front);
      }
      if (do_refract) {
        // Roughness frosts the glass too: the course's images blur what is seen through it.
        float3 t = GlossyDirection(sd, m, Refract(-wo, s.n, eta_i / eta_t, cos_o, cos_t), sk,
                                   HashCombine(task.key, 3u), primary);
        float3 below = OffsetRayOrigin(s.p, -s.ng, eps, s.scale);
        stack[sp++] = MakeTask(
            MakeRay(below, t, RT_INFINITY, ray.time), choose ? weight : weight * (1.0f - fr),
            front ? m->absorption : Vec3(0.0f), HashCombine(task.key, 2u), task.depth + 1, front);
      }
    }
  }
  return radiance;
}

// Camera sample `sample` of pixel (x, y): its radiance, and its reconstruction-filter
// weight in *weight.
RT_DEVICE float3 RenderSample(RT_PRIVATE const SceneData* sd, int x, int y, uint sample,
                              RT_PRIVATE float* weight, RT_PRIVATE PrimaryInfo* info,
                              RT_PRIVATE uint* rays) {
  RT_GLOBAL const SceneHeader* h = sd->header;
  RT_GLOBAL const Camera* cam = &h->camera;
  SampleKey sk = MakeSampleKey((uint)(y * cam->width + x), sample, (uint)cam->samples,
                               (uint)cam->strata, h->seed);
  float2 film = make_float2(0.5f, 0.5f);
  if (RT_HAS(sd, RT_FEATURE_MULTISAMPLE) && cam->samples > 1) film = Stratified2D(sk, RT_DIM_PIXEL);
  float2 lens = make_float2(0.5f, 0.5f);
  if (RT_HAS(sd, RT_FEATURE_DEPTH_OF_FIELD)) lens = Stratified2D(sk, RT_DIM_LENS);
  float time = 0.0f;
  if (RT_HAS(sd, RT_FEATURE_MOTION_BLUR)) time = Stratified1D(sk, RT_DIM_TIME);
  *weight = 1.0f;
  if (h->filter == RT_FILTER_GAUSSIAN) {
    float dx = film.x - 0.5f, dy = film.y - 0.5f;
    *weight = exp(-(dx * dx + dy * dy) / (2.0f * h->filter_sigma * h->filter_sigma));
  }
  Ray ray = GenerateCameraRay(sd, (float)x + film.x, (float)y + film.y, lens, time);
  // The background image is stretched over the film, pixel (x, y) at (x, y) / resolution:
  // with the bilinear lookup's convention (image_texture.h) an image of the film's size
  // is reproduced texel for texel, as in the course's galactica images.
  float2 pixel_uv = make_float2((float)x / (float)cam->width, (float)y / (float)cam->height);
  return Li(sd, sk, ray, pixel_uv, info, rays);
}

#endif  // RT_INTEGRATOR_H
