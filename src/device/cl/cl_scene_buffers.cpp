#include "cl_scene_buffers.h"

#include <stdexcept>
#include <type_traits>

#include "bvh/bvh_lanes.h"

#include "integrator/render.h"

namespace rt {
namespace {

// Elements of a FlatScene array that make one item of the kernel's: a node or a triangle
// block of bvh_width lanes spans wide_units of this build's (src/bvh/bvh_lanes.h).
template <typename T>
uint64_t elements_per_item(int bvh_width) {
  return std::is_same_v<T, BvhNode> || std::is_same_v<T, TriangleBlock> ? wide_units(bvh_width) : 1;
}

template <typename T>
cl::Buffer upload(const cl::Context& context, const T* data, size_t count, bool share) {
  return cl::Buffer(context,
                    CL_MEM_READ_ONLY | (share ? CL_MEM_USE_HOST_PTR : CL_MEM_COPY_HOST_PTR),
                    sizeof(T) * count, const_cast<T*>(data));
}

}  // namespace

ClSceneBuffers upload_scene(const cl::Context& context, const FlatScene& flat, bool share_host,
                            size_t base_align) {
  ClSceneBuffers b;
  b.arrays.push_back(upload(context, &flat.header, 1, false));
  auto aligned = [&](const void* p) {
    return share_host && base_align > 0 && reinterpret_cast<uintptr_t>(p) % base_align == 0;
  };
#define RT_UPLOAD_ARRAY(Type, name)                                                    \
  b.arrays.push_back(                                                                  \
      upload(context, flat.name.data(), flat.name.size(), aligned(flat.name.data()))); \
  b.shared_bytes += aligned(flat.name.data()) ? sizeof(Type) * flat.name.size() : 0;
  RT_DATA_ARRAYS(RT_UPLOAD_ARRAY)
#undef RT_UPLOAD_ARRAY
  return b;
}

int bind_scene(cl::Kernel& kernel, const ClSceneBuffers& buffers, int first_arg) {
  int arg = first_arg;
  for (const cl::Buffer& buffer : buffers.arrays) kernel.setArg(arg++, buffer);
  return arg;
}

std::vector<std::pair<const char*, uint64_t>> scene_array_bytes(const ArrayCounts& counts) {
  std::vector<std::pair<const char*, uint64_t>> out = {{"header", sizeof(SceneHeader)}};
#define RT_ARRAY_BYTES(Type, name) out.emplace_back(#name, sizeof(Type) * counts.name);
  RT_DATA_ARRAYS(RT_ARRAY_BYTES)
#undef RT_ARRAY_BYTES
  return out;
}

std::vector<std::pair<const char*, uint64_t>> scene_layout(int bvh_width) {
  std::vector<std::pair<const char*, uint64_t>> out;
#define RT_LAYOUT_OF_TYPE(Type) out.emplace_back(#Type, sizeof(Type));
#define RT_LAYOUT_OF_ARRAY(Type, name) \
  out.emplace_back(#Type, sizeof(Type) * elements_per_item<Type>(bvh_width));
  RT_LAYOUT_TYPES(RT_LAYOUT_OF_TYPE)
  RT_DATA_ARRAYS(RT_LAYOUT_OF_ARRAY)
#undef RT_LAYOUT_OF_TYPE
#undef RT_LAYOUT_OF_ARRAY
  return out;
}

void check_scene_layout(const cl::Context& context, cl::CommandQueue& queue,
                        const cl::Program& program, const std::string& device_name, int bvh_width) {
  const std::vector<std::pair<const char*, uint64_t>> host = scene_layout(bvh_width);
  cl::Kernel k(program, "rt_sizes");
  cl::Buffer out(context, CL_MEM_WRITE_ONLY, sizeof(cl_int) * host.size());
  k.setArg(0, out);
  queue.enqueueNDRangeKernel(k, cl::NullRange, cl::NDRange(1), cl::NullRange);
  std::vector<cl_int> device(host.size());
  queue.enqueueReadBuffer(out, CL_TRUE, 0, sizeof(cl_int) * device.size(), device.data());
  for (size_t i = 0; i < host.size(); ++i)
    if (static_cast<uint64_t>(device[i]) != host[i].second)
      throw std::runtime_error("OpenCL: struct " + std::string(host[i].first) + " is " +
                               std::to_string(device[i]) + " bytes on " + device_name + " but " +
                               std::to_string(host[i].second) +
                               " bytes on the host (layout mismatch)");
}

}  // namespace rt
