// Run-time choice of the CPU reference's kernel (cpu_kernel.h).
#include <cstdlib>
#include <cstring>

#include "device/cpu/cpu_kernel.h"

namespace rt {

CpuKernel select_cpu_kernel(bool double_precision) {
  if (double_precision) return {accumulate_pixel_double, nullptr, "baseline"};
#ifdef RT_CPU_KERNEL_AVX2
  const char* forced = std::getenv("RT_CPU_ISA");
  const bool baseline = forced != nullptr && std::strcmp(forced, "baseline") == 0;
  if (!baseline && __builtin_cpu_supports("avx2") && __builtin_cpu_supports("bmi2"))
    return {accumulate_pixel_float_avx2, intersect_closest_float_avx2, "avx2"};
#endif
  return {accumulate_pixel_float, intersect_closest_float, "baseline"};
}

}  // namespace rt
