// The shared math in float once more, compiled for x86-64 CPUs with AVX2 and chosen at run
// time (cpu_kernel_select.cpp), so one binary runs on any x86-64 and uses the wider
// instructions where they exist (with BMI1/2, which every AVX2 CPU has: a variable shift
// of the hashes is one instruction instead of two). Only the instruction encoding changes:
// FP contraction stays off (no FMA is enabled, and -ffp-contract=off holds for every file),
// so each operation rounds as in the baseline build and the image is bit-identical.
//
// As in cpu_kernel_double.cpp, the storage headers come first at global scope, compiled for
// the baseline target; the computation headers then compile inside rt_avx2 under the AVX2
// target, so none of their inline functions can replace the baseline build's copies (the
// linker keeps one copy of an inline function, and that one must run on every CPU).
#include <cstring>

#include "cl/compat.h"
#include "cl/film/film_types.h"
#include "cl/scene_types.h"
#include "device/cpu/cpu_kernel.h"

#if defined(__x86_64__) && defined(__GNUC__) && !defined(__clang__)

#pragma GCC push_options
#pragma GCC target("avx2,bmi,bmi2")
namespace rt_avx2 {
#include "cl/integrator/pixel.h"
#include "cl/bvh/intersect.h"
}  // namespace rt_avx2

namespace rt {

void accumulate_pixel_float_avx2(const SceneData* sd, int x, int y, int sample_begin,
                                 int sample_end, PixelAccum* acc, PrimaryInfo* primary) {
  rt_avx2::AccumulatePixel(sd, x, y, sample_begin, sample_end, acc, primary);
}

// The caller's records are the float build's (cl/geometry/ray.h); this namespace's have the same
// layout, so they are copied across bytewise.
int intersect_closest_float_avx2(const SceneData* sd, const Ray* ray, Hit* hit) {
  rt_avx2::Ray r;
  rt_avx2::Hit h;
  std::memcpy(&r, ray, sizeof r);
  const int found = rt_avx2::IntersectClosest(sd, r, 0, &h);
  std::memcpy(hit, &h, sizeof h);
  return found;
}

}  // namespace rt
#pragma GCC pop_options

#endif
