// The OpenCL renderer: runs cl/kernel.cl, compiled for the scene's features, on one
// OpenCL device, over the same flattened arrays as the CPU reference.
#pragma once

#include <cstdio>
#include <memory>
#include <string>

#include "render.h"

namespace rt {

struct ClTimings {
  double compile_ms = 0;  // Building the program (or loading it from the cache).
  bool cache_hit = false;
  std::string options;  // The build options used (feature defines included).
};

class ClRenderer {
 public:
  virtual ~ClRenderer() = default;
  // Picks a device: `selector` is an index into the list --list-devices prints, or a
  // substring of a device name; empty picks the first GPU, else the first device.
  // Returns nullptr and sets *why (one line) when no usable device exists.
  static std::unique_ptr<ClRenderer> create(const std::string& selector, bool use_cache,
                                            std::string* why);
  virtual std::string device_name() const = 0;
  // Renders the camera set in `flat`. `generic` compiles the all-features kernel instead
  // of the one specialized to flat.header.features. Throws std::runtime_error (one
  // line) on a build or launch failure; the build log goes to stderr in full.
  // Sampling stops early, between slices of samples, when `stop` says so.
  virtual RenderResult render(const FlatScene& flat, bool generic, Progress& progress,
                              ClTimings* timings, const StopRule& stop = StopRule()) = 0;
};

// Prints every platform and device with its index; false when there is none.
bool list_cl_devices(std::FILE* out);

// The kernel source with every shared header inlined (generated at build time).
extern const char* const kKernelSource;

}  // namespace rt
