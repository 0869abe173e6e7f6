// The ray tree of one camera sample as an explicit, bounded stack of weighted rays (no
// recursion in OpenCL C): the radiance of the sample is the sum over the tree of
// weight * the light each ray finds. Scatter pushes a ray's children, one per delta lobe
// of the material it hits; Li pops them.
#ifndef RT_INTEGRATOR_RAY_TREE_H
#define RT_INTEGRATOR_RAY_TREE_H

#include "../features.h"
#include "../geometry/ray.h"
#include "../geometry/surface.h"
#include "../material/material.h"
#include "../sampling/dimensions.h"
#include "../scene_types.h"
#include "../util/hash.h"

// The deepest ray tree the integrator follows: the host builds the kernel for its scene's
// MaxRecursionDepth (-DRT_RAY_TREE_DEPTH, src/device/kernel_config.cpp); the CPU reference
// and a kernel built without it take the deepest the scene files may ask for.
#ifdef RT_RAY_TREE_DEPTH
#define RT_TREE_DEPTH RT_RAY_TREE_DEPTH
#else
#define RT_TREE_DEPTH RT_MAX_DEPTH
#endif

// A ray tree of depth D never holds more than D + 2 pending rays (one sibling per level
// plus the pair just pushed), which bounds the stack. Only dielectrics branch: a kernel
// compiled without them needs room for one ray, and less private memory.
#if defined(__OPENCL_C_VERSION__) && !(RT_KERNEL_FEATURES & RT_FEATURE_DIELECTRIC)
#define RT_TASK_STACK 2
#else
#define RT_TASK_STACK (RT_TREE_DEPTH + 2)
#endif

typedef struct RayTask {
  Ray ray;
  real3 weight;
  real3 medium;  // Absorption coefficient of the medium the ray travels in (0: air).
  uint key;      // Identifies the ray in the tree; keys its random dimensions.
  int depth;
  int inside;  // 1 while the ray travels inside a dielectric.
} RayTask;

#if RT_GPU_FORMS
// On a GPU the pending rays lie in scratch memory, a work-item's own: a task is kept there
// without the padding of its three-component vectors (68 bytes in float, not 96).
typedef struct PackedRayTask {
  real v[14];  // Origin, direction, tmax, time, weight, medium.
  uint key;
  int depth, inside;
} PackedRayTask;

typedef struct RayStack {
  PackedRayTask tasks[RT_TASK_STACK];
  int size;
} RayStack;
#else
typedef struct RayStack {
  RayTask tasks[RT_TASK_STACK];
  int size;
} RayStack;
#endif

RT_DEVICE RayTask MakeTask(Ray ray, real3 weight, real3 medium, uint key, int depth, int inside) {
  RayTask task;
  task.ray = ray;
  task.weight = weight;
  task.medium = medium;
  task.key = key;
  task.depth = depth;
  task.inside = inside;
  return task;
}

// Child `child` (RT_CHILD_*) of `parent`, one level deeper.
RT_DEVICE RayTask ChildTask(RT_PRIVATE const RayTask* parent, Ray ray, real3 weight, real3 medium,
                            uint child, int inside) {
  return MakeTask(ray, weight, medium, HashCombine(parent->key, child), parent->depth + 1, inside);
}

#if RT_GPU_FORMS
RT_DEVICE void PushRay(RT_PRIVATE RayStack* stack, RayTask task) {
  RT_PRIVATE PackedRayTask* p = &stack->tasks[stack->size++];
  p->v[0] = task.ray.origin.x;
  p->v[1] = task.ray.origin.y;
  p->v[2] = task.ray.origin.z;
  p->v[3] = task.ray.direction.x;
  p->v[4] = task.ray.direction.y;
  p->v[5] = task.ray.direction.z;
  p->v[6] = task.ray.tmax;
  p->v[7] = task.ray.time;
  p->v[8] = task.weight.x;
  p->v[9] = task.weight.y;
  p->v[10] = task.weight.z;
  p->v[11] = task.medium.x;
  p->v[12] = task.medium.y;
  p->v[13] = task.medium.z;
  p->key = task.key;
  p->depth = task.depth;
  p->inside = task.inside;
}

RT_DEVICE RayTask PopRay(RT_PRIVATE RayStack* stack) {
  RT_PRIVATE const PackedRayTask* p = &stack->tasks[--stack->size];
  RayTask task;
  task.ray.origin = make_real3(p->v[0], p->v[1], p->v[2]);
  task.ray.direction = make_real3(p->v[3], p->v[4], p->v[5]);
  task.ray.tmax = p->v[6];
  task.ray.time = p->v[7];
  task.weight = make_real3(p->v[8], p->v[9], p->v[10]);
  task.medium = make_real3(p->v[11], p->v[12], p->v[13]);
  task.key = p->key;
  task.depth = p->depth;
  task.inside = p->inside;
  return task;
}
#else
RT_DEVICE void PushRay(RT_PRIVATE RayStack* stack, RayTask task) {
  RT_ASSERT(stack->size < RT_TASK_STACK);
  stack->tasks[stack->size++] = task;
}

RT_DEVICE RayTask PopRay(RT_PRIVATE RayStack* stack) { return stack->tasks[--stack->size]; }
#endif

// Pops the next pending ray into *task; 0 when the tree is done.
RT_DEVICE int NextRay(RT_PRIVATE RayStack* stack, RT_PRIVATE RayTask* task) {
  if (stack->size == 0) return 0;
  *task = PopRay(stack);
  return 1;
}

// Whether the reflected ray of an opaque surface at s (normals facing the incoming ray)
// leaves from below the surface. The course's renderer offsets it along the normal as
// modelled, also on a surface seen from behind: there the ray starts behind the sheet and
// meets it again from the front, and that hit's reflection continues the incoming ray
// beyond the sheet. hw2 grass_desert's blades are mirrors seen from both sides, and its
// reference image shows them so. --reflection-offset facing keeps the ray on the viewer's
// side.
RT_DEVICE int ReflectionLeavesBelow(RT_PRIVATE const SceneData* sd,
                                    RT_PRIVATE const SurfacePoint* s) {
  return !s->front && (sd->header->flags & RT_FLAG_FACING_REFLECTION) == 0;
}

// Pushes a child of `task` for every delta lobe of the material at s (facing the incoming
// ray), reflection before refraction, so the refracted ray is followed first. A refracted
// ray enters (or leaves) the dielectric's medium; a dielectric's reflected ray stays on
// the side it came from, an opaque surface's leaves the medium's bookkeeping as it was.
RT_DEVICE void Scatter(RT_PRIVATE const SceneData* sd, RT_PRIVATE const Material* m,
                       RT_PRIVATE const SurfacePoint* s, RT_PRIVATE const RayTask* task,
                       RaySampler rs, RT_PRIVATE RayStack* stack) {
  BsdfSample lobes[RT_DELTA_LOBES];
  int choose = (sd->header->flags & RT_FLAG_FRESNEL_CHOICE) != 0;
  int n = SampleDeltaLobes(sd, m, s, rs, choose, lobes);
  int transmissive = IsTransmissive(sd, m);
  for (int l = 0; l < n; ++l) {
    RT_PRIVATE const BsdfSample* bs = &lobes[l];
    int below = 1, inside = s->front;
    uint child = RT_CHILD_REFRACTED;
    real3 medium = s->front ? ToReal3(m->absorption) : Vec3(0.0f);
    if (!bs->transmit) {
      child = RT_CHILD_REFLECTED;
      below = transmissive ? 0 : ReflectionLeavesBelow(sd, s);
      inside = transmissive ? !s->front : 0;
      medium = transmissive && s->front ? Vec3(0.0f) : task->medium;
    }
    PushRay(stack, ChildTask(task, SpawnRay(sd, s, bs->wi, below),
                             task->weight * bs->tint * bs->fresnel, medium, child, inside));
  }
}

#endif  // RT_INTEGRATOR_RAY_TREE_H
