// Command-line options of the raytracer executable.
#pragma once

#include <string>

#include "device/device.h"
#include "flat_scene.h"
#include "scene.h"

namespace rt {

struct CliOptions {
  std::string scene;
  std::string output_dir = ".";
  Device device = Device::kAuto;
  std::string cl_device;  // Index or name substring; empty: the first GPU, else the first device.
  bool generic_kernel = false;
  bool kernel_cache = true;
  bool list_devices = false;
  int threads = 0;
  int camera = -1;  // -1: every camera.
  bool quiet = false;
  bool stats = false;
  bool moments = false;           // Also write <image>.moments.exr beside each PNG.
  double resolution_scale = 1.0;  // Scales every camera's pixel count, same view.
  RenderOptions render;
  LoadOptions load;  // --strict
};

// Parses argv; on --help / --version prints and exits 0; on a bad option prints one line
// and the usage hint, and exits 2.
CliOptions parse_cli(int argc, char** argv);

// What parse_cli prints before it exits: the help or version (status 0, for stdout) or a
// usage error (status 2, for stderr).
struct CliExit {
  int status;
  std::string message;
};

// parse_cli without printing or exiting: throws CliExit instead (the fuzzer calls this).
CliOptions parse_arguments(int argc, char** argv);

}  // namespace rt
