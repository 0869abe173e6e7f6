// The OpenCL entry points: `render`, one work-item per pixel running a slice of that
// pixel's samples, and `rt_sizes`, the device's struct sizes for the host's layout check.
// All of the maths lives in the shared headers; the scene's arrays are the list of
// data_arrays.h, passed after the header in that order (src/device/cl/cl_scene_buffers.cpp binds them).
#include "data_arrays.h"
#include "integrator/pixel.h"

#define RT_KERNEL_PARAM(Type, name) __global const Type *name,
#define RT_KERNEL_FILL(Type, name) sd.name = name;
__kernel void render(__global const SceneHeader* header,
                     RT_DATA_ARRAYS(RT_KERNEL_PARAM) int row_begin, int sample_begin,
                     int sample_end, __global PixelAccum* accum, __global PrimaryInfo* primary) {
  int x = (int)get_global_id(0);
  int y = row_begin + (int)get_global_id(1);
  if (x >= header->camera.width || y >= header->camera.height) return;
  SceneData sd;
  sd.header = header;
  RT_DATA_ARRAYS(RT_KERNEL_FILL)
#if RT_GPU_FORMS
  int bvh_stack[RT_BVH_STACK];
  sd.bvh_stack = bvh_stack;
#endif
  int pixel = y * header->camera.width + x;
  AccumulatePixel(&sd, x, y, sample_begin, sample_end, &accum[pixel], &primary[pixel]);
}

// out[i] = sizeof of the i-th type of RT_LAYOUT_TYPES then RT_DATA_ARRAYS, the order of
// scene_layout() on the host.
#define RT_SIZE_OF_TYPE(Type) out[i++] = (int)sizeof(Type);
#define RT_SIZE_OF_ARRAY(Type, name) out[i++] = (int)sizeof(Type);
__kernel void rt_sizes(__global int* out) {
  int i = 0;
  RT_LAYOUT_TYPES(RT_SIZE_OF_TYPE)
  RT_DATA_ARRAYS(RT_SIZE_OF_ARRAY)
}
