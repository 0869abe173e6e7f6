// The ray tree of one camera sample as an explicit, bounded stack of weighted rays (no
// recursion in OpenCL C): the radiance of the sample is the sum over the tree of
// weight * the light each ray finds. Scattering pushes children; Li pops them.
#ifndef RT_INTEGRATOR_RAY_TREE_H
#define RT_INTEGRATOR_RAY_TREE_H

#include "../features.h"
#include "../geometry/ray.h"
#include "../scene_types.h"
#include "../util/hash.h"

// A ray tree of depth D never holds more than D + 2 pending rays (one sibling per level
// plus the pair just pushed), which bounds the stack. Only dielectrics branch: a kernel
// compiled without them needs room for one ray, and less private memory.
#if defined(__OPENCL_C_VERSION__) && !(RT_KERNEL_FEATURES & RT_FEATURE_DIELECTRIC)
#define RT_TASK_STACK 2
#else
#define RT_TASK_STACK (RT_MAX_DEPTH + 2)
#endif

// Children's keys: HashCombine(parent key, child). Every random number a ray draws is keyed
// by its own key, so the tree's samples never collide.
#define RT_CHILD_REFLECTED 1u
#define RT_CHILD_REFRACTED 2u

typedef struct RayTask {
  Ray ray;
  real3 weight;
  real3 medium;  // Absorption coefficient of the medium the ray travels in (0: air).
  uint key;      // Identifies the ray in the tree; keys its random dimensions.
  int depth;
  int inside;  // 1 while the ray travels inside a dielectric.
} RayTask;

typedef struct RayStack {
  RayTask tasks[RT_TASK_STACK];
  int size;
} RayStack;

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

RT_DEVICE void PushRay(RT_PRIVATE RayStack* stack, RayTask task) {
  RT_ASSERT(stack->size < RT_TASK_STACK);
  stack->tasks[stack->size++] = task;
}

RT_DEVICE RayTask PopRay(RT_PRIVATE RayStack* stack) { return stack->tasks[--stack->size]; }

// Pops the next pending ray into *task; 0 when the tree is done.
RT_DEVICE int NextRay(RT_PRIVATE RayStack* stack, RT_PRIVATE RayTask* task) {
  if (stack->size == 0) return 0;
  *task = PopRay(stack);
  return 1;
}

#endif  // RT_INTEGRATOR_RAY_TREE_H
