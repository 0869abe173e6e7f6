// The renderer interface every device implements, and the one place a device is chosen.
//
// A device holds one scene and one film (per-pixel accumulators) at a time and does one
// thing: add samples [s0, s1) of rows [r0, r1) to the film. Everything else (how passes are
// sized, when to stop, progress, cancellation) belongs to the scheduler
// (integrator/render_scheduler.h), so it is written once for every device, and a driver
// that spreads rows or samples over several devices (or ranks) works through this interface.
#pragma once

#include <cstdint>
#include <map>
#include <memory>
#include <string>
#include <vector>

#include "cl/film/film_types.h"
#include "device/kernel_config.h"
#include "prepare/flat_scene.h"

namespace rt {

enum class Device { kAuto, kCpu, kOpenCl };

struct DeviceOptions {
  Device kind = Device::kAuto;
  std::string cl_selector;      // Index or name substring; empty: first GPU, else first device.
  bool kernel_cache = true;     // OpenCL: read and write the compiled-kernel cache.
  bool generic_kernel = false;  // OpenCL: the all-features kernel, not one for the scene.
  int threads = 0;              // CPU: threads (0: all cores); the image does not depend on it.
  int gpu_rank = 0;  // OpenCL, empty selector: the GPU to take among several (a node-local rank).
};

// A block of work: samples [sample_begin, sample_end) of every pixel of rows
// [row_begin, row_end).
struct RenderWork {
  int row_begin = 0, row_end = 0;
  int sample_begin = 0, sample_end = 0;
  int rows() const { return row_end - row_begin; }
  int samples() const { return sample_end - sample_begin; }
};

// What rendering one camera needs, for the memory check: the scene's arrays, the film's
// resolution, and the caller's own host bytes (its copies and outputs).
struct MemoryNeed {
  ArrayCounts arrays;
  int width = 0, height = 0;
  uint64_t host_bytes = 0;
};

// What loading a scene cost, for --stats.
struct DeviceLoadInfo {
  double compile_ms = 0;      // Building the program (or loading it from a cache); 0 on the CPU.
  double upload_ms = 0;       // Making the scene's buffers and the film's; 0 on the CPU.
  uint64_t shared_bytes = 0;  // Scene bytes a CPU OpenCL device reads in place (not copied).
  bool cache_hit = false;
  std::string build_options;  // OpenCL build options (feature defines included).
};

class RenderDevice {
 public:
  virtual ~RenderDevice() = default;
  // "cpu-reference", or the OpenCL device's name.
  virtual std::string name() const = 0;
  // Whether the shared math can run in double here (--precision double; auto picks it).
  virtual bool has_double() const { return false; }
  // The BVH width (BvhOptions::width) this device renders fastest, for scenes flattened for
  // it, and whether it can render `width` at all. By default this build's RT_BVH_WIDTH
  // only, which the CPU reference is compiled for.
  virtual int bvh_width() const { return RT_BVH_WIDTH; }
  virtual bool supports_bvh_width(int width) const { return width == RT_BVH_WIDTH; }
  // Checks, before anything is allocated, that `need` fits: the device's buffers (scene
  // arrays and film) in its memory, and need.host_bytes more in the host's. Throws
  // std::runtime_error, one line naming the resolution, the bytes needed and the limit.
  virtual void check_memory(const MemoryNeed& need) const = 0;
  // Makes `flat` (with its camera) the scene of the following render() calls, with the kernel
  // `kernel` configures, and clears the film. `flat` must outlive them. Throws
  // std::runtime_error (one line) on failure.
  virtual DeviceLoadInfo load(const FlatScene& flat, const KernelConfig& kernel) = 0;
  // Adds samples [s0, s1) of rows [r0, r1) to the film; blocks until done. Each pixel's
  // samples must be added in order (s0 == the samples it holds), which keeps every device
  // bit-identical to the others. Returns the rays cast, or 0 when the device does not count
  // them as it goes (they are in the film either way).
  virtual uint64_t render(const RenderWork& work) = 0;
  // Bands of rows must start at, and hold, a multiple of this many rows unless they end at
  // the image's last row (the OpenCL kernel runs whole work-groups; valid after load()).
  virtual int row_alignment() const { return 1; }
  // Copies the film out: accumulators (every pass may need them) and first-hit facts.
  virtual void read_accum(std::vector<PixelAccum>* accum) = 0;
  virtual void read_primary(std::vector<PrimaryInfo>* primary) = 0;
  // Replaces the loaded camera's film by a saved one (a checkpoint's, read_accum's and
  // read_primary's copies, one record a pixel), so render() continues from the samples it
  // holds. Throws std::runtime_error when the sizes do not match the camera or the device
  // cannot (the default).
  virtual void write_film(const std::vector<PixelAccum>& accum,
                          const std::vector<PrimaryInfo>& primary);
};

// The BVH width to flatten a scene with for `device`: its own (RenderDevice::bvh_width)
// for 0, else `asked` when it can render that, else std::runtime_error naming both.
int resolve_bvh_width(int asked, const RenderDevice& device);

// A scene prepared for one device: the options resolved against it once, the kernel
// configuration they give, and the flat scene both steps of the preparation
// (prepare/flat_scene.h) build with them.
struct PreparedScene {
  RenderOptions options;  // Precision and BVH width resolved for the device.
  KernelConfig kernel;
  FlatScene flat;
};

// Every driver's preparation: resolves --precision (*notice: resolve_precision's) and the
// BVH width (resolve_bvh_width) for `device`, then runs prepare_scene.
PreparedScene prepare_for_device(const SceneDesc& scene, const RenderOptions& options,
                                 const RenderDevice& device, std::string* notice);
// prepare_camera with the options prepare_for_device resolved.
void prepare_camera(PreparedScene& prepared, const SceneDesc& scene, int camera);
// The kernel configuration of resolved `options`; throws std::logic_error for an unresolved
// --precision auto.
KernelConfig kernel_config(const RenderOptions& options);
// The memory check of camera `camera` of `scene`, before it is placed: the arrays as any
// camera makes them at most (camera_array_counts), and its resolution.
MemoryNeed camera_memory_need(const PreparedScene& prepared, const SceneDesc& scene, int camera,
                              uint64_t host_bytes);

// Bytes of one pixel's film (accumulator and first-hit facts), on any device.
constexpr uint64_t kFilmBytesPerPixel = sizeof(PixelAccum) + sizeof(PrimaryInfo);

// Throws the memory error of check_memory when `bytes` exceed `limit`: "<W>x<H> pixels need
// <bytes> of <what>, more than <limit_text>".
void check_memory_limit(const MemoryNeed& need, uint64_t bytes, uint64_t limit,
                        const std::string& what, const std::string& limit_text);

// The host memory a render may use: the kernel's estimate of available memory
// (MemAvailable), bounded by the address-space and data-size limits (ulimit -v, -d).
uint64_t available_host_memory();

// "1.5 GiB (1610612736 bytes)".
std::string format_bytes(uint64_t bytes);

// Picks the device `options.kind` asks for: kCpu the reference, kOpenCl an OpenCL device or
// a std::runtime_error naming why none is usable, kAuto OpenCL when usable, else the CPU
// reference with *notice set to one line saying why (empty otherwise).
std::unique_ptr<RenderDevice> create_device(const DeviceOptions& options, std::string* notice);

// Devices kept open by their options, for programs that render on several (the tests, the
// sweep): opening a device and building its programs is the slow part.
class DevicePool {
 public:
  // The device for `options`, opened on first use; nullptr with *why (one line) when it
  // cannot be. kAuto may fall back to the CPU reference, without the notice.
  RenderDevice* get(const DeviceOptions& options, std::string* why);

 private:
  struct Entry {
    std::unique_ptr<RenderDevice> device;
    std::string why;
  };
  std::map<std::string, Entry> devices_;
};

}  // namespace rt
