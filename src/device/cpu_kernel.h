// The CPU reference's per-pixel entry point, once per precision of the shared math
// (cl/util/real.h). Each is the kernel's AccumulatePixel compiled from the same cl/
// headers, in its own translation unit and namespace.
#pragma once

#include "cl/film_types.h"
#include "cl/scene_types.h"

namespace rt {

using CpuPixelFunction = void (*)(const SceneData* sd, int x, int y, int sample_begin,
                                  int sample_end, PixelAccum* acc, PrimaryInfo* primary);

void accumulate_pixel_float(const SceneData* sd, int x, int y, int sample_begin, int sample_end,
                            PixelAccum* acc, PrimaryInfo* primary);
void accumulate_pixel_double(const SceneData* sd, int x, int y, int sample_begin, int sample_end,
                             PixelAccum* acc, PrimaryInfo* primary);

}  // namespace rt
