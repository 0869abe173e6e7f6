// The CPU reference's per-pixel entry point, once per precision of the shared math
// (cl/util/real.h), and the float one once more for CPUs with AVX2. Each is the kernel's
// AccumulatePixel compiled from the same cl/ headers, in its own translation unit and
// namespace; select_cpu_kernel picks one at run time.
#pragma once

#include "cl/film/film_types.h"
#include "cl/scene_types.h"

// The float build's ray and hit records (cl/geometry/ray.h); every variant shares their layout.
struct Ray;
struct Hit;

namespace rt {

using CpuPixelFunction = void (*)(const SceneData* sd, int x, int y, int sample_begin,
                                  int sample_end, PixelAccum* acc, PrimaryInfo* primary);
// The closest hit of a float ray (IntersectClosest, no culling): the traversal alone.
using CpuTraceFunction = int (*)(const SceneData* sd, const Ray* ray, Hit* hit);

void accumulate_pixel_float(const SceneData* sd, int x, int y, int sample_begin, int sample_end,
                            PixelAccum* acc, PrimaryInfo* primary);
void accumulate_pixel_double(const SceneData* sd, int x, int y, int sample_begin, int sample_end,
                             PixelAccum* acc, PrimaryInfo* primary);
int intersect_closest_float(const SceneData* sd, const Ray* ray, Hit* hit);
// GCC only (#pragma GCC target); a Clang build, such as the sanitized tree, keeps the
// baseline kernel.
#if defined(__x86_64__) && defined(__GNUC__) && !defined(__clang__)
#define RT_CPU_KERNEL_AVX2 1
void accumulate_pixel_float_avx2(const SceneData* sd, int x, int y, int sample_begin,
                                 int sample_end, PixelAccum* acc, PrimaryInfo* primary);
int intersect_closest_float_avx2(const SceneData* sd, const Ray* ray, Hit* hit);
#endif

struct CpuKernel {
  CpuPixelFunction accumulate;
  CpuTraceFunction intersect_closest;  // Float only; null for double.
  const char* isa;                     // "avx2" or "baseline".
};

// The AVX2 float kernel where the CPU has AVX2 and RT_CPU_ISA is not "baseline", else
// the baseline one (double: always the baseline). Every choice gives the same image.
CpuKernel select_cpu_kernel(bool double_precision);

}  // namespace rt
