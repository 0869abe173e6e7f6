// Turns a hit record into the surface point the shading code needs.
#ifndef RT_SURFACE_H
#define RT_SURFACE_H

#include "../bvh/bvh.h"
#include "../features.h"
#include "../scene_types.h"
#include "ray.h"
#include "transform.h"

// The shading context of a hit (pbrt-v4's SurfaceInteraction): what lights, materials and
// scattering read about the point. Texture coordinates and tangents belong here too.
typedef struct SurfacePoint {
  real3 p;     // World-space position.
  real3 n;     // Unit shading normal (interpolated on smooth meshes).
  real3 ng;    // Unit geometric normal.
  real3 wo;    // Unit direction back along the incoming ray.
  real scale;  // Largest coordinate magnitude p was computed from (see OffsetRayOrigin); 0
               // where no offset reads it (SurfaceScaleRead).
  real time;   // The ray's shutter time; rays spawned here keep it.
  int material;
  int front;  // 1 when wo is on the side ng points to.
  Hit hit;    // The hit it was built from: textures rebuild their frame from it.
} SurfacePoint;

// The parts of a surface point ComputeSurfaceParts builds; the hit, the material and the
// time are always there, and a part left out stays zero. Shading that reads less than the
// whole point (a last hit lit by the ambient term alone, see Li) asks for less.
#define RT_SURFACE_NORMALS 1  // n, ng, wo and front.
#define RT_SURFACE_POINT 2    // p and scale.
#define RT_SURFACE_ALL (RT_SURFACE_NORMALS | RT_SURFACE_POINT)

// Whether a spawned ray's offset reads SurfacePoint.scale (OffsetRayOrigin): only the robust
// offset and a scene without ShadowRayEpsilon do. Elsewhere (the course's offset, every hw3
// scene) the bound is left at zero: its absolute values and maxima cost a tenth of the
// surface point and never reached a pixel.
RT_DEVICE int SurfaceScaleRead(RT_PRIVATE const SceneData* sd) {
  return RT_ROBUST_OFFSET(sd) || !(sd->header->shadow_epsilon > 0.0f);
}

// The position is origin + t * direction by default (--hit-point ray), as the course's
// renderer forms its points, whose rounding decides some of its images' pixels
// (docs/course_pixel_residue.md); --hit-point surface rebuilds it from the primitive
// (barycentrics on a triangle, a projection onto the unit sphere), so its error does not
// grow with the distance travelled. Each part is computed as in the whole point, so a part
// is the same to the bit whatever else is asked.
// The ray and hit come by pointer: passed by value, both are copied at every call.
RT_DEVICE SurfacePoint ComputeSurfaceParts(RT_PRIVATE const SceneData* sd,
                                           RT_PRIVATE const Ray* ray_in,
                                           RT_PRIVATE const Hit* hit_in, int parts) {
  Ray ray = *ray_in;
  Hit hit = *hit_in;
  RT_GLOBAL const Instance* inst = &sd->instances[hit.instance];
  int transformed =
      RT_HAS(sd, RT_FEATURE_TRANSFORMS) && (inst->flags & RT_INSTANCE_TRANSFORMED) != 0;
  int want_point = (parts & RT_SURFACE_POINT) != 0,
      want_normals = (parts & RT_SURFACE_NORMALS) != 0;
  int want_scale = want_point && SurfaceScaleRead(sd);
  // The primitive's own point is built only where it is the surface point.
  int ray_point = (sd->header->flags & RT_FLAG_RAY_HIT_POINT) != 0;
  SurfacePoint sp;
  sp.material = inst->material;
  sp.time = ray.time;
  sp.hit = hit;
  real3 p_obj = Vec3(0.0f), ng_obj = Vec3(0.0f), n_obj = Vec3(0.0f);
  // Only smooth meshes interpolate a shading normal; elsewhere n is ng.
  int interpolated = 0;
  real mag = 1.0f;  // Object-space magnitude: the unit sphere, or the triangle's vertices.
  if (hit.primitive < 0) {
    real3 o = RT_HAS(sd, RT_FEATURE_MOTION_BLUR) ? InstanceRayOrigin(inst, ray) : ray.origin;
    real3 d = ray.direction;
    if (transformed) {
      o = TransformPoint(inst->world_to_object, o);
      d = TransformVector(inst->world_to_object, d);
    }
    p_obj = Normalize(o + d * hit.t);
    ng_obj = p_obj;
  } else {
    RT_GLOBAL const Triangle* tri = &sd->triangles[hit.primitive];
    real b0 = 1.0f - hit.b1 - hit.b2;
    real3 v0 = ToReal3(tri->v0), v1 = ToReal3(tri->v1), v2 = ToReal3(tri->v2);
    if (want_point) {
      if (!ray_point) p_obj = v0 * b0 + v1 * hit.b1 + v2 * hit.b2;
      if (want_scale)
        mag = MaxF(MaxComponent(Abs3(v0)), MaxF(MaxComponent(Abs3(v1)), MaxComponent(Abs3(v2))));
    }
    if (want_normals) {
      ng_obj = Cross(v1 - v0, v2 - v0);
      interpolated = RT_HAS(sd, RT_FEATURE_SMOOTH) && (inst->flags & RT_INSTANCE_SMOOTH) != 0;
      if (interpolated) {
        RT_GLOBAL const TriangleNormals* tn = &sd->normals[hit.primitive];
        n_obj = ToReal3(tn->n0) * b0 + ToReal3(tn->n1) * hit.b1 + ToReal3(tn->n2) * hit.b2;
      }
    }
  }
  sp.p = Vec3(0.0f);
  sp.scale = 0.0f;
  if (want_point && ray_point) {
    sp.p = RayAt(ray, hit.t);
  } else if (want_point) {
    sp.p = p_obj;
    if (transformed) sp.p = TransformPoint(inst->object_to_world, p_obj);
    if (RT_HAS(sd, RT_FEATURE_MOTION_BLUR) && (inst->flags & RT_INSTANCE_MOVING) != 0)
      sp.p = sp.p + ToReal3(inst->motion) * ray.time;
  }
  if (want_scale) {
    sp.scale = mag;
    if (transformed) {
      // A bound on the world-space coordinates of points of magnitude `mag`.
      RT_GLOBAL const float4* o2w = inst->object_to_world;
      real lin = 0.0f, shift = 0.0f;
      for (int r = 0; r < 3; ++r) {
        lin = MaxF(lin, fabs(o2w[r].x) + fabs(o2w[r].y) + fabs(o2w[r].z));
        shift = MaxF(shift, fabs(o2w[r].w));
      }
      sp.scale = lin * mag + shift;
    }
    if (RT_HAS(sd, RT_FEATURE_MOTION_BLUR) && (inst->flags & RT_INSTANCE_MOVING) != 0)
      sp.scale = sp.scale + MaxComponent(Abs3(ToReal3(inst->motion))) * ray.time;
  }
  // The normals are formed in locals and stored once: copying sp.ng to sp.n through the
  // returned record loaded 16 bytes just stored as three floats, a load that waits for the
  // stores to retire (failed store-to-load forwarding).
  real3 ng = Vec3(0.0f), n = Vec3(0.0f), wo = Vec3(0.0f);
  int front = 0;
  if (want_normals) {
    if (transformed) {
      ng = Normalize(TransformNormalByInverse(inst->world_to_object, ng_obj));
      n = interpolated ? Normalize(TransformNormalByInverse(inst->world_to_object, n_obj)) : ng;
    } else {
      ng = Normalize(ng_obj);
      n = interpolated ? Normalize(n_obj) : ng;
    }
    wo = Normalize(-ray.direction);
    front = Dot(wo, ng) > 0.0f;
  }
  sp.ng = ng;
  sp.n = n;
  sp.wo = wo;
  sp.front = front;
  return sp;
}

RT_DEVICE SurfacePoint ComputeSurface(RT_PRIVATE const SceneData* sd, Ray ray, Hit hit) {
  return ComputeSurfaceParts(sd, &ray, &hit, RT_SURFACE_ALL);
}

// Turns the normals to the side wo is on: scattering (unlike direct light, see Li) treats
// the surface as seen from where the ray came.
RT_DEVICE void FaceForward(RT_PRIVATE SurfacePoint* s) {
  if (!s->front) {
    s->n = -s->n;
    s->ng = -s->ng;
  }
}

// A ray leaving s along dir, from just above the surface (or below it, for refraction),
// at the same shutter time.
RT_DEVICE Ray SpawnRay(RT_PRIVATE const SceneData* sd, RT_PRIVATE const SurfacePoint* s, real3 dir,
                       int below) {
  real3 origin = OffsetRayOrigin(s->p, below ? -s->ng : s->ng, sd->header->shadow_epsilon, s->scale,
                                 RT_ROBUST_OFFSET(sd));
  return MakeRay(origin, dir, RT_INFINITY, s->time);
}

#endif  // RT_SURFACE_H
