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

#include "flat_scene.h"

namespace rt {

// The header's buffer, then one per array of RT_DATA_ARRAYS, in that order.
struct ClSceneBuffers {
  std::vector<cl::Buffer> arrays;
};

// Copies the header and every array of `flat` to read-only device buffers.
ClSceneBuffers upload_scene(const cl::Context& context, const FlatScene& flat);

// Sets the buffers as the kernel's arguments first_arg, first_arg + 1, ...; returns the
// next free argument index.
int bind_scene(cl::Kernel& kernel, const ClSceneBuffers& buffers, int first_arg);

// The bytes of every buffer upload_scene makes, named, for the memory check.
std::vector<std::pair<const char*, uint64_t>> scene_array_bytes(const FlatScene& flat);

// Host sizes of the shared structs, in the order the kernel `rt_sizes` (cl/kernel.cl)
// writes the device's.
std::vector<std::pair<const char*, uint64_t>> scene_layout();

// Runs `rt_sizes` of `program` and throws std::runtime_error (one line naming the struct
// and both sizes) when a struct differs between the host and `device_name`.
void check_scene_layout(const cl::Context& context, cl::CommandQueue& queue,
                        const cl::Program& program, const std::string& device_name);

}  // namespace rt
