// The shared math in float, the default (the headers' `real` is float unless
// RT_REAL_DOUBLE is defined, as in every other translation unit that includes them),
// compiled for the baseline target of the build.
#include "cl/integrator/pixel.h"
#include "cl/bvh/intersect.h"
#include "device/cpu/cpu_kernel.h"

namespace rt {

void accumulate_pixel_float(const SceneData* sd, int x, int y, int sample_begin, int sample_end,
                            PixelAccum* acc, PrimaryInfo* primary) {
  AccumulatePixel(sd, x, y, sample_begin, sample_end, acc, primary);
}

int intersect_closest_float(const SceneData* sd, const Ray* ray, Hit* hit) {
  return IntersectClosest(sd, *ray, 0, hit);
}

}  // namespace rt
