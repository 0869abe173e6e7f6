// The scene's OpenCL buffers, generated from the one list of device arrays
// (cl/data_arrays.h): upload, kernel arguments in the kernel's order, the memory figures
// and the check that host and device agree on every struct's size.
#pragma once

#ifndef CL_HPP_ENABLE_EXCEPTIONS
#define CL_HPP_ENABLE_EXCEPTIONS
#endif
#include <CL/opencl.hpp>

#include <cstdint>
#include <string>
#include <utility>
#include <vector>

#include "prepare/flat_scene.h"

namespace rt {

// The header's buffer, then one per array of RT_DATA_ARRAYS, in that order.
struct ClSceneBuffers {
  std::vector<cl::Buffer> arrays;
  uint64_t shared_bytes = 0;  // Of them, the bytes the device reads from the host's arrays.
};

// Read-only device buffers of the header and every array of `flat`. With `share_host`
// (a device on the host's CPU, src/device/cl/cl_device.cpp), arrays whose storage is
// aligned to `base_align` bytes become buffers over the host's memory itself
// (CL_MEM_USE_HOST_PTR), so the scene is held once; `flat` must then outlive the buffers'
// use. Otherwise, and always for the small header (rewritten per camera), they are copied.
ClSceneBuffers upload_scene(const cl::Context& context, const FlatScene& flat, bool share_host,
                            size_t base_align);

// Sets the buffers as the kernel's arguments first_arg, first_arg + 1, ...; returns the
// next free argument index.
int bind_scene(cl::Kernel& kernel, const ClSceneBuffers& buffers, int first_arg);

// The bytes of every buffer upload_scene makes for arrays of `counts` elements, named, for
// the memory check.
std::vector<std::pair<const char*, uint64_t>> scene_array_bytes(const ArrayCounts& counts);

// Host sizes of the shared structs, in the order the kernel `rt_sizes` (cl/kernel.cl)
// writes the device's, for a kernel built for nodes of `bvh_width` children.
std::vector<std::pair<const char*, uint64_t>> scene_layout(int bvh_width = RT_BVH_WIDTH);

// Runs `rt_sizes` of `program` (built for `bvh_width`) and throws std::runtime_error (one
// line naming the struct and both sizes) when a struct differs between the host and
// `device_name`.
void check_scene_layout(const cl::Context& context, cl::CommandQueue& queue,
                        const cl::Program& program, const std::string& device_name, int bvh_width);

}  // namespace rt
