// The shared math in double (`--precision double`). The storage headers (float layouts,
// the same types as everywhere else) are included first, at global scope; the computation
// headers then compile inside rt_double with RT_REAL_DOUBLE, so their inline functions and
// private structs cannot collide with the float build's. This file must include no other
// header that pulls in the computation headers.
#define RT_REAL_DOUBLE 1

#include "cl/compat.h"
#include "cl/film/film_types.h"
#include "cl/scene_types.h"
#include "device/cpu/cpu_kernel.h"

namespace rt_double {
#include "cl/integrator/pixel.h"
}  // namespace rt_double

namespace rt {

void accumulate_pixel_double(const SceneData* sd, int x, int y, int sample_begin, int sample_end,
                             PixelAccum* acc, PrimaryInfo* primary) {
  rt_double::AccumulatePixel(sd, x, y, sample_begin, sample_end, acc, primary);
}

}  // namespace rt
