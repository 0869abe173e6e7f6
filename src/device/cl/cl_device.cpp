#include "device/cl/cl_device.h"

#include <algorithm>
#include <chrono>
#include <stdexcept>

#include "bvh/bvh_lanes.h"
#include "cl/features.h"
#include "device/cl/cl_platform.h"
#include "device/cl/cl_program.h"
#include "device/cl/cl_scene_buffers.h"

namespace rt {
namespace {

size_t round_up(size_t n, size_t m) { return (n + m - 1) / m * m; }

class ClDevice final : public RenderDevice {
 public:
  ClDevice(const ClDeviceEntry& e, const DeviceOptions& options)
      : device_(e.device), generic_(options.generic_kernel) {
    name_ = clean_cl_string(device_.getInfo<CL_DEVICE_NAME>());
    cl_context_properties props[] = {CL_CONTEXT_PLATFORM,
                                     reinterpret_cast<cl_context_properties>(e.platform()), 0};
    context_ = cl::Context(device_, props);
    queue_ = cl::CommandQueue(context_, device_);
    programs_ = std::make_unique<ClProgramCache>(context_, device_, options.kernel_cache);
    max_alloc_ = device_.getInfo<CL_DEVICE_MAX_MEM_ALLOC_SIZE>();
    // A device on the host's own CPU reads the host's scene arrays in place.
    share_host_ = (device_.getInfo<CL_DEVICE_TYPE>() & CL_DEVICE_TYPE_CPU) != 0;
    base_align_ = device_.getInfo<CL_DEVICE_MEM_BASE_ADDR_ALIGN>() / 8;
    global_mem_ = device_.getInfo<CL_DEVICE_GLOBAL_MEM_SIZE>();
  }

  std::string name() const override { return name_; }
  bool has_double() const override { return programs_->has_double(); }
  // PoCL on an x86 CPU traverses 8-wide nodes faster than 4-wide ones, where the CPU
  // reference (GCC) is faster with 4. No GPU has been compared: it keeps the 4-wide nodes
  // every device used before.
  int bvh_width() const override { return programs_->is_cpu() ? 8 : std::max(4, RT_BVH_WIDTH); }
  bool supports_bvh_width(int width) const override { return valid_bvh_width(width); }
  void check_memory(const MemoryNeed& need) const override;
  int row_alignment() const override { return program_ ? static_cast<int>(program_->local_y) : 1; }
  DeviceLoadInfo load(const FlatScene& flat, const KernelConfig& kernel) override;
  uint64_t render(const RenderWork& work) override;
  void read_accum(std::vector<PixelAccum>* accum) override { read(accum_, accum); }
  void read_primary(std::vector<PrimaryInfo>* primary) override { read(primary_, primary); }
  void write_film(const std::vector<PixelAccum>& accum,
                  const std::vector<PrimaryInfo>& primary) override {
    if (accum.size() != pixels_ || primary.size() != pixels_)
      throw std::runtime_error("the saved film has " + std::to_string(accum.size()) +
                               " pixels, the camera " + std::to_string(pixels_));
    if (pixels_ == 0) return;
    try {
      queue_.enqueueWriteBuffer(accum_, CL_TRUE, 0, sizeof(PixelAccum) * pixels_, accum.data());
      queue_.enqueueWriteBuffer(primary_, CL_TRUE, 0, sizeof(PrimaryInfo) * pixels_,
                                primary.data());
    } catch (const cl::Error& e) {
      fail(e);
    }
  }

 private:
  void launch(const RenderWork& work);
  template <typename T>
  void read(const cl::Buffer& buffer, std::vector<T>* out) {
    out->resize(pixels_);
    if (pixels_ == 0) return;
    try {
      queue_.enqueueReadBuffer(buffer, CL_TRUE, 0, sizeof(T) * pixels_, out->data());
    } catch (const cl::Error& e) {
      fail(e);
    }
  }
  [[noreturn]] void fail(const cl::Error& e) const {
    throw std::runtime_error("OpenCL: " + describe_cl_error(e) + " on " + name_);
  }

  cl::Device device_;
  cl::Context context_;
  cl::CommandQueue queue_;
  std::unique_ptr<ClProgramCache> programs_;
  std::string name_;
  bool generic_;
  uint64_t max_alloc_ = 0, global_mem_ = 0;
  bool share_host_ = false;
  size_t base_align_ = 0;
  // The loaded scene.
  ClProgram* program_ = nullptr;
  int width_ = 0, height_ = 0;
  size_t pixels_ = 0;
  ClSceneBuffers scene_;
  cl::Buffer accum_, primary_;
  int launch_arg_ = 0;  // The first per-launch argument, after the scene's.
};

// Refuses, before anything is allocated, a scene the device cannot hold: each buffer within
// the device's largest allocation, all of them within its memory, and the host's copies
// within the host's.
void ClDevice::check_memory(const MemoryNeed& need) const {
  const uint64_t pixels = static_cast<uint64_t>(need.width) * need.height;
  std::vector<std::pair<const char*, uint64_t>> sizes = scene_array_bytes(need.arrays);
  sizes.emplace_back("accum", sizeof(PixelAccum) * pixels);
  sizes.emplace_back("primary", sizeof(PrimaryInfo) * pixels);
  uint64_t total = 0, largest = 0;
  for (const auto& buffer : sizes) {
    total += buffer.second;
    largest = std::max(largest, buffer.second);
  }
  check_memory_limit(need, largest, max_alloc_, "OpenCL memory in one buffer",
                     "the " + format_bytes(max_alloc_) + " per buffer of " + name_);
  check_memory_limit(need, total, global_mem_, "OpenCL memory",
                     "the " + format_bytes(global_mem_) + " of " + name_);
  const uint64_t limit = available_host_memory();
  check_memory_limit(need, need.host_bytes, limit, "host memory",
                     "the " + format_bytes(limit) + " available");
}

DeviceLoadInfo ClDevice::load(const FlatScene& flat, const KernelConfig& kernel) {
  width_ = flat.header.camera.width;
  height_ = flat.header.camera.height;
  pixels_ = static_cast<size_t>(width_) * height_;
  program_ = nullptr;
  check_memory({array_counts(flat), width_, height_, 0});
  DeviceLoadInfo info;
  // The private arrays sized for this scene (and its depths checked) as the options say.
  info.build_options = programs_->options_for(generic_ ? RT_FEATURE_ALL : flat.header.features,
                                              sized_for_scene(kernel, flat));
  ClProgram& p =
      programs_->get(info.build_options, kernel.bvh_width, &info.compile_ms, &info.cache_hit);
  auto since = [](std::chrono::steady_clock::time_point t) {
    return std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - t).count();
  };
  try {
    auto upload_start = std::chrono::steady_clock::now();
    scene_ = upload_scene(context_, flat, share_host_, base_align_);
    const size_t cells = std::max<size_t>(pixels_, 1);  // OpenCL has no empty buffers.
    accum_ = cl::Buffer(context_, CL_MEM_READ_WRITE, sizeof(PixelAccum) * cells);
    primary_ = cl::Buffer(context_, CL_MEM_READ_WRITE, sizeof(PrimaryInfo) * cells);
    queue_.enqueueFillBuffer(accum_, cl_uint(0), 0, sizeof(PixelAccum) * cells);
    queue_.enqueueFillBuffer(primary_, cl_uint(0), 0, sizeof(PrimaryInfo) * cells);
    queue_.finish();
    info.upload_ms = since(upload_start);
    info.shared_bytes = scene_.shared_bytes;
    cl::Kernel& k = p.kernel;
    // The kernel's arguments: the scene, then (row_begin, sample_begin, sample_end) per
    // launch, then the two per-pixel outputs.
    launch_arg_ = bind_scene(k, scene_, 0);
    k.setArg(launch_arg_ + 3, accum_);
    k.setArg(launch_arg_ + 4, primary_);
    program_ = &p;
    // A first use of a program may compile device code lazily at its first launch (PoCL
    // builds its work-group functions then): an empty launch (no samples) over the whole
    // image triggers that here, outside the timed render, and counts as compile time.
    if (!p.warmed) {
      auto warm_start = std::chrono::steady_clock::now();
      if (pixels_ > 0) launch({0, height_, 0, 0});
      p.warmed = true;
      info.compile_ms += since(warm_start);
    }
  } catch (const cl::Error& e) {
    fail(e);
  }
  return info;
}

void ClDevice::launch(const RenderWork& work) {
  cl::Kernel& k = program_->kernel;
  k.setArg(launch_arg_, work.row_begin);
  k.setArg(launch_arg_ + 1, work.sample_begin);
  k.setArg(launch_arg_ + 2, work.sample_end);
  const size_t lx = program_->local_x, ly = program_->local_y;
  queue_.enqueueNDRangeKernel(k, cl::NullRange,
                              cl::NDRange(round_up(static_cast<size_t>(width_), lx),
                                          round_up(static_cast<size_t>(work.rows()), ly)),
                              cl::NDRange(lx, ly));
  queue_.finish();
}

uint64_t ClDevice::render(const RenderWork& work) {
  if (work.rows() <= 0 || width_ <= 0) return 0;
  try {
    launch(work);
  } catch (const cl::Error& e) {
    fail(e);
  }
  return 0;  // The kernel counts rays in the film only.
}

}  // namespace

std::unique_ptr<RenderDevice> create_cl_device(const DeviceOptions& options, std::string* why) {
  ClDeviceEntry entry;
  if (!pick_cl_device(options.cl_selector, &entry, why, options.gpu_rank)) return nullptr;
  try {
    return std::make_unique<ClDevice>(entry, options);
  } catch (const cl::Error& e) {
    *why = describe_cl_error(e);
  } catch (const std::exception& e) {
    *why = e.what();
  }
  return nullptr;
}

}  // namespace rt
