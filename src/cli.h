// Command-line options of the raytracer executable.
#pragma once

#include <string>
#include <vector>

#include "device/device.h"
#include "flat_scene.h"

namespace rt {

struct CliOptions {
  std::vector<std::string> scenes;  // Every camera of each is rendered (an animation: frames).
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
  bool skip_existing = false;     // Render only the images whose file does not exist yet.
  int tile_rows = 0;              // MPI: rows of a tile when images are split (0: automatic).
  RenderOptions render;
};

// Parses argv; on --help / --version prints and exits 0; on a bad option prints one line
// and the usage hint, and exits 2.
CliOptions parse_cli(int argc, char** argv);

}  // namespace rt
