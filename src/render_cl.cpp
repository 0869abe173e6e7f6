// The OpenCL host: device discovery, program build (with an on-disk cache of compiled
// binaries), buffer upload and the sliced dispatch of the `render` kernel.
#define CL_HPP_ENABLE_EXCEPTIONS
#include "render_cl.h"

#include <unistd.h>
#include <CL/opencl.hpp>

#include <algorithm>
#include <atomic>
#include <cctype>
#include <chrono>
#include <cinttypes>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <map>
#include <stdexcept>
#include <system_error>
#include <vector>

#include "cl/features.h"
#include "cl_scene_buffers.h"

namespace rt {
namespace {

using Clock = std::chrono::steady_clock;

double ms_between(Clock::time_point a, Clock::time_point b) {
  return std::chrono::duration<double, std::milli>(b - a).count();
}

const char* cl_error_name(cl_int code) {
  switch (code) {
    case CL_SUCCESS:
      return "CL_SUCCESS";
    case CL_DEVICE_NOT_FOUND:
      return "CL_DEVICE_NOT_FOUND";
    case CL_DEVICE_NOT_AVAILABLE:
      return "CL_DEVICE_NOT_AVAILABLE";
    case CL_COMPILER_NOT_AVAILABLE:
      return "CL_COMPILER_NOT_AVAILABLE";
    case CL_MEM_OBJECT_ALLOCATION_FAILURE:
      return "CL_MEM_OBJECT_ALLOCATION_FAILURE";
    case CL_OUT_OF_RESOURCES:
      return "CL_OUT_OF_RESOURCES";
    case CL_OUT_OF_HOST_MEMORY:
      return "CL_OUT_OF_HOST_MEMORY";
    case CL_PROFILING_INFO_NOT_AVAILABLE:
      return "CL_PROFILING_INFO_NOT_AVAILABLE";
    case CL_MEM_COPY_OVERLAP:
      return "CL_MEM_COPY_OVERLAP";
    case CL_IMAGE_FORMAT_MISMATCH:
      return "CL_IMAGE_FORMAT_MISMATCH";
    case CL_IMAGE_FORMAT_NOT_SUPPORTED:
      return "CL_IMAGE_FORMAT_NOT_SUPPORTED";
    case CL_BUILD_PROGRAM_FAILURE:
      return "CL_BUILD_PROGRAM_FAILURE";
    case CL_MAP_FAILURE:
      return "CL_MAP_FAILURE";
    case CL_MISALIGNED_SUB_BUFFER_OFFSET:
      return "CL_MISALIGNED_SUB_BUFFER_OFFSET";
    case CL_EXEC_STATUS_ERROR_FOR_EVENTS_IN_WAIT_LIST:
      return "CL_EXEC_STATUS_ERROR_FOR_EVENTS_IN_WAIT_LIST";
    case CL_COMPILE_PROGRAM_FAILURE:
      return "CL_COMPILE_PROGRAM_FAILURE";
    case CL_LINKER_NOT_AVAILABLE:
      return "CL_LINKER_NOT_AVAILABLE";
    case CL_LINK_PROGRAM_FAILURE:
      return "CL_LINK_PROGRAM_FAILURE";
    case CL_DEVICE_PARTITION_FAILED:
      return "CL_DEVICE_PARTITION_FAILED";
    case CL_KERNEL_ARG_INFO_NOT_AVAILABLE:
      return "CL_KERNEL_ARG_INFO_NOT_AVAILABLE";
    case CL_INVALID_VALUE:
      return "CL_INVALID_VALUE";
    case CL_INVALID_DEVICE_TYPE:
      return "CL_INVALID_DEVICE_TYPE";
    case CL_INVALID_PLATFORM:
      return "CL_INVALID_PLATFORM";
    case CL_INVALID_DEVICE:
      return "CL_INVALID_DEVICE";
    case CL_INVALID_CONTEXT:
      return "CL_INVALID_CONTEXT";
    case CL_INVALID_QUEUE_PROPERTIES:
      return "CL_INVALID_QUEUE_PROPERTIES";
    case CL_INVALID_COMMAND_QUEUE:
      return "CL_INVALID_COMMAND_QUEUE";
    case CL_INVALID_HOST_PTR:
      return "CL_INVALID_HOST_PTR";
    case CL_INVALID_MEM_OBJECT:
      return "CL_INVALID_MEM_OBJECT";
    case CL_INVALID_IMAGE_FORMAT_DESCRIPTOR:
      return "CL_INVALID_IMAGE_FORMAT_DESCRIPTOR";
    case CL_INVALID_IMAGE_SIZE:
      return "CL_INVALID_IMAGE_SIZE";
    case CL_INVALID_SAMPLER:
      return "CL_INVALID_SAMPLER";
    case CL_INVALID_BINARY:
      return "CL_INVALID_BINARY";
    case CL_INVALID_BUILD_OPTIONS:
      return "CL_INVALID_BUILD_OPTIONS";
    case CL_INVALID_PROGRAM:
      return "CL_INVALID_PROGRAM";
    case CL_INVALID_PROGRAM_EXECUTABLE:
      return "CL_INVALID_PROGRAM_EXECUTABLE";
    case CL_INVALID_KERNEL_NAME:
      return "CL_INVALID_KERNEL_NAME";
    case CL_INVALID_KERNEL_DEFINITION:
      return "CL_INVALID_KERNEL_DEFINITION";
    case CL_INVALID_KERNEL:
      return "CL_INVALID_KERNEL";
    case CL_INVALID_ARG_INDEX:
      return "CL_INVALID_ARG_INDEX";
    case CL_INVALID_ARG_VALUE:
      return "CL_INVALID_ARG_VALUE";
    case CL_INVALID_ARG_SIZE:
      return "CL_INVALID_ARG_SIZE";
    case CL_INVALID_KERNEL_ARGS:
      return "CL_INVALID_KERNEL_ARGS";
    case CL_INVALID_WORK_DIMENSION:
      return "CL_INVALID_WORK_DIMENSION";
    case CL_INVALID_WORK_GROUP_SIZE:
      return "CL_INVALID_WORK_GROUP_SIZE";
    case CL_INVALID_WORK_ITEM_SIZE:
      return "CL_INVALID_WORK_ITEM_SIZE";
    case CL_INVALID_GLOBAL_OFFSET:
      return "CL_INVALID_GLOBAL_OFFSET";
    case CL_INVALID_EVENT_WAIT_LIST:
      return "CL_INVALID_EVENT_WAIT_LIST";
    case CL_INVALID_EVENT:
      return "CL_INVALID_EVENT";
    case CL_INVALID_OPERATION:
      return "CL_INVALID_OPERATION";
    case CL_INVALID_GL_OBJECT:
      return "CL_INVALID_GL_OBJECT";
    case CL_INVALID_BUFFER_SIZE:
      return "CL_INVALID_BUFFER_SIZE";
    case CL_INVALID_MIP_LEVEL:
      return "CL_INVALID_MIP_LEVEL";
    case CL_INVALID_GLOBAL_WORK_SIZE:
      return "CL_INVALID_GLOBAL_WORK_SIZE";
    case CL_INVALID_PROPERTY:
      return "CL_INVALID_PROPERTY";
    case CL_INVALID_IMAGE_DESCRIPTOR:
      return "CL_INVALID_IMAGE_DESCRIPTOR";
    case CL_INVALID_COMPILER_OPTIONS:
      return "CL_INVALID_COMPILER_OPTIONS";
    case CL_INVALID_LINKER_OPTIONS:
      return "CL_INVALID_LINKER_OPTIONS";
    case CL_INVALID_DEVICE_PARTITION_COUNT:
      return "CL_INVALID_DEVICE_PARTITION_COUNT";
    case -1001:
      return "CL_PLATFORM_NOT_FOUND_KHR";
    default:
      return nullptr;
  }
}

std::string describe_error(const cl::Error& e) {
  const char* name = cl_error_name(e.err());
  std::string code = name ? name : std::to_string(e.err());
  return std::string(e.what() ? e.what() : "OpenCL call") + " failed (" + code + ")";
}

// Device strings may carry trailing NULs or blanks.
std::string clean(std::string s) {
  while (!s.empty() && (s.back() == '\0' || std::isspace(static_cast<unsigned char>(s.back()))))
    s.pop_back();
  size_t b = 0;
  while (b < s.size() && std::isspace(static_cast<unsigned char>(s[b]))) ++b;
  return s.substr(b);
}

std::string lower(std::string s) {
  for (char& c : s) c = static_cast<char>(std::tolower(static_cast<unsigned char>(c)));
  return s;
}

std::string type_name(cl_device_type t) {
  if (t & CL_DEVICE_TYPE_GPU) return "GPU";
  if (t & CL_DEVICE_TYPE_CPU) return "CPU";
  if (t & CL_DEVICE_TYPE_ACCELERATOR) return "accelerator";
#ifdef CL_DEVICE_TYPE_CUSTOM
  if (t & CL_DEVICE_TYPE_CUSTOM) return "custom";
#endif
  return "other";
}

struct DeviceEntry {
  cl::Platform platform;
  cl::Device device;
};

// Every device of every platform, in the order --list-devices prints them. Throws
// cl::Error when the platform query itself fails; a platform without devices is skipped.
std::vector<DeviceEntry> enumerate_devices() {
  std::vector<cl::Platform> platforms;
  cl::Platform::get(&platforms);
  std::vector<DeviceEntry> out;
  for (const cl::Platform& p : platforms) {
    std::vector<cl::Device> devices;
    try {
      p.getDevices(CL_DEVICE_TYPE_ALL, &devices);
    } catch (const cl::Error&) {
      continue;  // CL_DEVICE_NOT_FOUND and friends: nothing usable on this platform.
    }
    for (const cl::Device& d : devices) out.push_back({p, d});
  }
  return out;
}

// FNV-1a, 64 bits; each part is prefixed with its length so concatenations differ.
class Fnv1a {
 public:
  void add(const void* data, size_t n) {
    const unsigned char* p = static_cast<const unsigned char*>(data);
    for (size_t i = 0; i < n; ++i) {
      h_ ^= p[i];
      h_ *= 0x100000001b3ull;
    }
  }
  void add(const std::string& s) {
    uint64_t n = s.size();
    add(&n, sizeof n);
    add(s.data(), s.size());
  }
  uint64_t value() const { return h_; }

 private:
  uint64_t h_ = 0xcbf29ce484222325ull;
};

std::filesystem::path cache_dir() {
  const char* xdg = std::getenv("XDG_CACHE_HOME");
  if (xdg && *xdg == '/') return std::filesystem::path(xdg) / "raytracer" / "kernels";
  const char* home = std::getenv("HOME");
  if (home && *home) return std::filesystem::path(home) / ".cache" / "raytracer" / "kernels";
  return {};
}

bool read_file(const std::filesystem::path& path, std::vector<unsigned char>* data) {
  std::ifstream in(path, std::ios::binary);
  if (!in) return false;
  data->assign(std::istreambuf_iterator<char>(in), std::istreambuf_iterator<char>());
  return !in.bad() && !data->empty();
}

// Writes through a temporary file and a rename, so a reader never sees half a binary.
// Any failure leaves no file behind and is otherwise ignored.
void write_file_atomic(const std::filesystem::path& path, const std::vector<unsigned char>& data) {
  std::error_code ec;
  std::filesystem::create_directories(path.parent_path(), ec);
  if (ec) return;
  static std::atomic<unsigned> counter{0};
  char suffix[48];
  std::snprintf(suffix, sizeof suffix, ".%ld.%u.tmp", static_cast<long>(::getpid()),
                counter.fetch_add(1));
  std::filesystem::path tmp = path;
  tmp += suffix;
  {
    std::ofstream out(tmp, std::ios::binary | std::ios::trunc);
    if (!out) return;
    out.write(reinterpret_cast<const char*>(data.data()),
              static_cast<std::streamsize>(data.size()));
    out.close();
    if (!out) {
      std::filesystem::remove(tmp, ec);
      return;
    }
  }
  std::filesystem::rename(tmp, path, ec);
  if (ec) std::filesystem::remove(tmp, ec);
}

double mib(uint64_t bytes) { return static_cast<double>(bytes) / (1024.0 * 1024.0); }

class ClRendererImpl final : public ClRenderer {
 public:
  ClRendererImpl(const DeviceEntry& e, bool use_cache)
      : platform_(e.platform), device_(e.device), use_cache_(use_cache) {
    platform_name_ = clean(platform_.getInfo<CL_PLATFORM_NAME>());
    name_ = clean(device_.getInfo<CL_DEVICE_NAME>());
    device_version_ = clean(device_.getInfo<CL_DEVICE_VERSION>());
    driver_version_ = clean(device_.getInfo<CL_DRIVER_VERSION>());
    cl_context_properties props[] = {CL_CONTEXT_PLATFORM,
                                     reinterpret_cast<cl_context_properties>(platform_()), 0};
    context_ = cl::Context(device_, props);
    queue_ = cl::CommandQueue(context_, device_);
    cl_device_fp_config fp = device_.getInfo<CL_DEVICE_SINGLE_FP_CONFIG>();
    correctly_rounded_ = (fp & CL_FP_CORRECTLY_ROUNDED_DIVIDE_SQRT) != 0;
    max_alloc_ = device_.getInfo<CL_DEVICE_MAX_MEM_ALLOC_SIZE>();
    global_mem_ = device_.getInfo<CL_DEVICE_GLOBAL_MEM_SIZE>();
  }

  std::string device_name() const override { return name_; }

  RenderResult render(const FlatScene& flat, bool generic, Progress& progress, ClTimings* timings,
                      const StopRule& stop) override;

 private:
  struct Built {
    cl::Program program;
    cl::Kernel kernel;
    size_t local_x = 8, local_y = 8;
    bool warmed = false;  // The first launch (and any lazy device compile) has happened.
  };

  std::string build_options(int features) const {
    std::string o = "-cl-std=CL1.2 -DRT_KERNEL_FEATURES=" + std::to_string(features);
    if (correctly_rounded_) o += " -cl-fp32-correctly-rounded-divide-sqrt";
    // A developer's knob for experiments (e.g. RT_CL_OPTIONS=-cl-fast-relaxed-math).
    if (const char* extra = std::getenv("RT_CL_OPTIONS")) o += std::string(" ") + extra;
    return o;
  }
  Built& program_for(const std::string& options, ClTimings* timings);
  cl::Program build_program(const std::string& source, const std::string& options, bool* hit);
  void check_layout(Built& b);
  [[noreturn]] void fail(const cl::Error& e) const {
    throw std::runtime_error("OpenCL: " + describe_error(e) + " on " + name_);
  }

  cl::Platform platform_;
  cl::Device device_;
  cl::Context context_;
  cl::CommandQueue queue_;
  std::string platform_name_, name_, device_version_, driver_version_;
  bool use_cache_;
  bool correctly_rounded_ = false;
  uint64_t max_alloc_ = 0, global_mem_ = 0;
  std::map<std::string, Built> programs_;
};

cl::Program ClRendererImpl::build_program(const std::string& source, const std::string& options,
                                          bool* hit) {
  *hit = false;
  std::vector<cl::Device> devices{device_};
  std::filesystem::path file;
  if (use_cache_) {
    std::filesystem::path dir = cache_dir();
    if (!dir.empty()) {
      Fnv1a h;
      h.add(source);
      h.add(options);
      h.add(platform_name_);
      h.add(name_);
      h.add(device_version_);
      h.add(driver_version_);
      char name[32];
      std::snprintf(name, sizeof name, "%016" PRIx64 ".bin", h.value());
      file = dir / name;
      std::vector<unsigned char> binary;
      if (read_file(file, &binary)) {
        try {
          cl::Program::Binaries binaries{binary};
          cl::Program p(context_, devices, binaries);
          p.build(devices, options.c_str());
          *hit = true;
          return p;
        } catch (const cl::Error&) {
          // A stale or foreign binary: compile from source below and overwrite it.
        }
      }
    }
  }
  cl::Program p(context_, source);
  try {
    p.build(devices, options.c_str());
  } catch (const cl::Error& e) {
    std::string log;
    try {
      log = p.getBuildInfo<CL_PROGRAM_BUILD_LOG>(device_);
    } catch (const cl::Error&) {
      log = "(no build log available)";
    }
    std::fprintf(stderr, "OpenCL build log for %s (options: %s):\n%s\n", name_.c_str(),
                 options.c_str(), clean(log).c_str());
    std::fprintf(stderr, "OpenCL build error: %s\n", describe_error(e).c_str());
    throw std::runtime_error("OpenCL: kernel build failed on " + name_ + " (see the log above)");
  }
  if (!file.empty()) {
    try {
      std::vector<std::vector<unsigned char>> bins = p.getInfo<CL_PROGRAM_BINARIES>();
      if (bins.size() == 1 && !bins[0].empty()) write_file_atomic(file, bins[0]);
    } catch (const cl::Error&) {
      // The cache is an optimisation only.
    }
  }
  return p;
}

void ClRendererImpl::check_layout(Built& b) {
  check_scene_layout(context_, queue_, b.program, name_);
}

ClRendererImpl::Built& ClRendererImpl::program_for(const std::string& options, ClTimings* timings) {
  auto it = programs_.find(options);
  if (it != programs_.end()) {
    timings->compile_ms = 0;
    timings->cache_hit = true;  // Reused from memory.
    return it->second;
  }
  auto t0 = Clock::now();
  bool hit = false;
  Built b;
  b.program = build_program(kKernelSource, options, &hit);
  try {
    b.kernel = cl::Kernel(b.program, "render");
    size_t max_wg = b.kernel.getWorkGroupInfo<CL_KERNEL_WORK_GROUP_SIZE>(device_);
    std::vector<size_t> max_items = device_.getInfo<CL_DEVICE_MAX_WORK_ITEM_SIZES>();
    // 8x8 where the kernel allows it, else the largest power-of-two square-ish shape.
    b.local_x = 8;
    b.local_y = 8;
    while (b.local_x * b.local_y > max_wg) {
      if (b.local_y >= b.local_x && b.local_y > 1)
        b.local_y /= 2;
      else
        b.local_x /= 2;
    }
    if (max_items.size() >= 2) {
      b.local_x = std::max<size_t>(1, std::min(b.local_x, max_items[0]));
      b.local_y = std::max<size_t>(1, std::min(b.local_y, max_items[1]));
    }
    check_layout(b);
  } catch (const cl::Error& e) {
    fail(e);
  }
  timings->compile_ms = ms_between(t0, Clock::now());
  timings->cache_hit = hit;
  return programs_.emplace(options, std::move(b)).first->second;
}

size_t round_up(size_t n, size_t m) { return (n + m - 1) / m * m; }

RenderResult ClRendererImpl::render(const FlatScene& flat, bool generic, Progress& progress,
                                    ClTimings* timings, const StopRule& stop) {
  ClTimings local_timings;
  if (!timings) timings = &local_timings;
  const Camera& cam = flat.header.camera;
  const int width = cam.width, height = cam.height, spp = cam.samples;
  RenderResult r;
  r.width = width;
  r.height = height;
  const size_t pixels = static_cast<size_t>(width) * height;

  // Memory check before allocating anything.
  std::vector<std::pair<const char*, uint64_t>> sizes = scene_array_bytes(flat);
  sizes.emplace_back("accum", sizeof(PixelAccum) * pixels);
  sizes.emplace_back("primary", sizeof(PrimaryInfo) * pixels);
  uint64_t total = 0, largest = 0;
  for (const auto& buffer : sizes) {
    const uint64_t s = buffer.second;
    total += s;
    largest = std::max(largest, s);
  }
  char msg[256];
  if (largest > max_alloc_) {
    std::snprintf(msg, sizeof msg,
                  "OpenCL: the scene needs a buffer of %.1f MiB but %s allows %.1f MiB per buffer",
                  mib(largest), name_.c_str(), mib(max_alloc_));
    throw std::runtime_error(msg);
  }
  if (total > global_mem_) {
    std::snprintf(msg, sizeof msg, "OpenCL: the scene needs %.1f MiB but %s allows %.1f MiB",
                  mib(total), name_.c_str(), mib(global_mem_));
    throw std::runtime_error(msg);
  }

  timings->options = build_options(generic ? RT_FEATURE_ALL : flat.header.features);
  if (flat.fast_math) timings->options += " -cl-fast-relaxed-math";
  auto compile_start = Clock::now();
  Built& b = program_for(timings->options, timings);

  try {
    ClSceneBuffers scene = upload_scene(context_, flat);
    const size_t cells = std::max<size_t>(pixels, 1);  // OpenCL has no empty buffers.
    cl::Buffer accum(context_, CL_MEM_READ_WRITE, sizeof(PixelAccum) * cells);
    cl::Buffer primary(context_, CL_MEM_READ_WRITE, sizeof(PrimaryInfo) * cells);
    queue_.enqueueFillBuffer(accum, cl_uint(0), 0, sizeof(PixelAccum) * cells);
    queue_.enqueueFillBuffer(primary, cl_uint(0), 0, sizeof(PrimaryInfo) * cells);

    cl::Kernel& k = b.kernel;
    // The kernel's arguments: the scene, then (row_begin, sample_begin, sample_end) per
    // launch, then the two per-pixel outputs.
    const int launch_arg = bind_scene(k, scene, 0);
    k.setArg(launch_arg + 3, accum);
    k.setArg(launch_arg + 4, primary);

    const size_t lx = b.local_x, ly = b.local_y;
    const size_t gx = round_up(static_cast<size_t>(width), lx);
    auto launch = [&](int row_begin, int rows, int s0, int s1) {
      k.setArg(launch_arg, row_begin);
      k.setArg(launch_arg + 1, s0);
      k.setArg(launch_arg + 2, s1);
      queue_.enqueueNDRangeKernel(k, cl::NullRange,
                                  cl::NDRange(gx, round_up(static_cast<size_t>(rows), ly)),
                                  cl::NDRange(lx, ly));
      queue_.finish();
    };

    // A first use of a program may compile device code lazily at its first launch (PoCL
    // builds its work-group functions then): an empty launch (no samples) over the whole
    // image triggers that outside the timed render and counts it as compile time.
    if (!b.warmed) {
      if (width > 0 && height > 0) launch(0, height, 0, 0);
      b.warmed = true;
      timings->compile_ms = ms_between(compile_start, Clock::now());
    }

    // Sample slicing: every launch runs samples [s0, s1) of a band of rows; the bands of
    // one slice cover the image once, slices run in sample order and the queue is in
    // order, so every pixel accumulates its samples 0, 1, 2, ... as on the CPU.
    // The first launch is one sample of the whole image; its time, and then each band's,
    // gives a per-row cost (seconds per sample) from which the next launches are sized to
    // take about kTargetS: several samples of the whole image when one sample is quick,
    // otherwise bands of rows when one sample of the image would take over kSplitS.
    constexpr double kTargetS = 0.15, kSplitS = 0.5;
    std::vector<double> row_cost(static_cast<size_t>(height), 0.0);
    bool measured = false;
    int samples_per_launch = 1;
    auto start = Clock::now();
    int s0 = 0;
    while (s0 < spp && pixels > 0) {
      double image_cost = 0;  // One sample of the whole image, estimated.
      for (double c : row_cost) image_cost += c;
      bool banded = measured && image_cost > kSplitS;
      if (!measured) {
        samples_per_launch = 1;
      } else if (!banded) {
        long want = std::lround(kTargetS / std::max(image_cost, 1e-9));
        samples_per_launch = static_cast<int>(
            std::clamp<long>(want, 1, std::min<long>(4L * samples_per_launch, 1L << 20)));
      } else {
        samples_per_launch = 1;
      }
      const int s1 = std::min(spp, s0 + samples_per_launch);
      const int ns = s1 - s0;
      for (int row = 0; row < height;) {
        int rows = height - row;
        if (banded) {
          // Rows until the estimate reaches the target, rounded to whole work-groups.
          double acc = 0;
          int n = 0;
          while (row + n < height && acc < kTargetS) acc += row_cost[row + n++] * ns;
          n = static_cast<int>((n + ly / 2) / ly * ly);
          rows = std::min(std::max(n, static_cast<int>(ly)), height - row);
        }
        auto t0 = Clock::now();
        launch(row, rows, s0, s1);
        double t = std::chrono::duration<double>(Clock::now() - t0).count();
        progress.add(static_cast<uint64_t>(rows) * width * ns, 0);
        double per_row = t / (static_cast<double>(rows) * ns);
        std::fill(row_cost.begin() + row, row_cost.begin() + row + rows, per_row);
        measured = true;
        row += rows;
      }
      s0 = s1;
      if (s0 >= spp) break;
      // Stop rules, checked between slices so every pixel has s0 samples.
      double t = std::chrono::duration<double>(Clock::now() - start).count();
      if (stop.time_limit_s > 0 && t + t / s0 * samples_per_launch > stop.time_limit_s) break;
      if (stop.noise_target > 0 && s0 >= 2) {
        std::vector<PixelAccum> now(pixels);
        queue_.enqueueReadBuffer(accum, CL_TRUE, 0, sizeof(PixelAccum) * pixels, now.data());
        if (relative_noise(now) < stop.noise_target) break;
      }
    }
    r.spp = s0;
    r.accum.resize(pixels);
    r.primary.resize(pixels);
    if (pixels > 0) {
      queue_.enqueueReadBuffer(accum, CL_TRUE, 0, sizeof(PixelAccum) * pixels, r.accum.data());
      queue_.enqueueReadBuffer(primary, CL_TRUE, 0, sizeof(PrimaryInfo) * pixels, r.primary.data());
    }
    r.seconds = std::chrono::duration<double>(Clock::now() - start).count();
  } catch (const cl::Error& e) {
    fail(e);
  }
  r.samples = static_cast<uint64_t>(pixels) * r.spp;
  for (const PixelAccum& a : r.accum) r.rays += a.rays;
  return r;
}

}  // namespace

std::unique_ptr<ClRenderer> ClRenderer::create(const std::string& selector, bool use_cache,
                                               std::string* why) {
  std::string dummy;
  if (!why) why = &dummy;
  try {
    std::vector<DeviceEntry> all;
    try {
      all = enumerate_devices();
    } catch (const cl::Error& e) {
      const char* name = cl_error_name(e.err());
      *why = "no OpenCL platform (" + std::string(e.what()) + ": " +
             (name ? std::string(name) + ", " : std::string()) + std::to_string(e.err()) + ")";
      return nullptr;
    }
    if (all.empty()) {
      *why = "no OpenCL device found";
      return nullptr;
    }
    auto usable = [](const cl::Device& d) {
      try {
        return d.getInfo<CL_DEVICE_AVAILABLE>() && d.getInfo<CL_DEVICE_COMPILER_AVAILABLE>();
      } catch (const cl::Error&) {
        return false;
      }
    };
    const DeviceEntry* pick = nullptr;
    if (selector.empty()) {
      for (const auto& e : all)
        if ((e.device.getInfo<CL_DEVICE_TYPE>() & CL_DEVICE_TYPE_GPU) && usable(e.device)) {
          pick = &e;
          break;
        }
      if (!pick)
        for (const auto& e : all)
          if (usable(e.device)) {
            pick = &e;
            break;
          }
      if (!pick) pick = &all[0];  // Reported as unavailable below.
    } else if (std::all_of(selector.begin(), selector.end(),
                           [](char c) { return std::isdigit(static_cast<unsigned char>(c)); })) {
      unsigned long index = std::strtoul(selector.c_str(), nullptr, 10);
      if (selector.size() > 9 || index >= all.size()) {
        *why = "no OpenCL device " + selector + " (there are " + std::to_string(all.size()) +
               "; see --list-devices)";
        return nullptr;
      }
      pick = &all[index];
    } else {
      std::string want = lower(selector);
      for (const auto& e : all)
        if (lower(clean(e.device.getInfo<CL_DEVICE_NAME>())).find(want) != std::string::npos) {
          pick = &e;
          break;
        }
      if (!pick) {
        *why = "no OpenCL device matches '" + selector + "' (see --list-devices)";
        return nullptr;
      }
    }
    std::string name = clean(pick->device.getInfo<CL_DEVICE_NAME>());
    if (!pick->device.getInfo<CL_DEVICE_AVAILABLE>()) {
      *why = "OpenCL device " + name + " is not available";
      return nullptr;
    }
    if (!pick->device.getInfo<CL_DEVICE_COMPILER_AVAILABLE>()) {
      *why = "OpenCL device " + name + " has no compiler";
      return nullptr;
    }
    return std::make_unique<ClRendererImpl>(*pick, use_cache);
  } catch (const cl::Error& e) {
    *why = describe_error(e);
  } catch (const std::exception& e) {
    *why = e.what();
  }
  return nullptr;
}

bool list_cl_devices(std::FILE* out) {
  std::vector<DeviceEntry> all;
  try {
    all = enumerate_devices();
  } catch (const cl::Error& e) {
    std::fprintf(out, "no OpenCL platform found (%s)\n", describe_error(e).c_str());
    return false;
  }
  if (all.empty()) {
    std::fprintf(out, "no OpenCL device found\n");
    return false;
  }
  for (size_t i = 0; i < all.size(); ++i) {
    try {
      const cl::Device& d = all[i].device;
      std::fprintf(out, "%zu: %s (platform %s, %s, %u compute units, %.0f MiB global memory, %s)\n",
                   i, clean(d.getInfo<CL_DEVICE_NAME>()).c_str(),
                   clean(all[i].platform.getInfo<CL_PLATFORM_NAME>()).c_str(),
                   type_name(d.getInfo<CL_DEVICE_TYPE>()).c_str(),
                   static_cast<unsigned>(d.getInfo<CL_DEVICE_MAX_COMPUTE_UNITS>()),
                   mib(d.getInfo<CL_DEVICE_GLOBAL_MEM_SIZE>()),
                   clean(d.getInfo<CL_DEVICE_OPENCL_C_VERSION>()).c_str());
    } catch (const cl::Error& e) {
      std::fprintf(out, "%zu: (cannot query the device: %s)\n", i, describe_error(e).c_str());
    }
  }
  return true;
}

}  // namespace rt
