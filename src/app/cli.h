// Command-line options of the raytracer executable, declared once in its option table
// (src/app/cli.cpp; the table engine is src/util/args.h). The render options that reach the
// device, the scene header and the kernel build, are a table of their own that every
// executable that renders mounts; the rest stay on the host.
#pragma once

#include <string>
#include <utility>
#include <vector>

#include "device/device.h"
#include "io/png_io.h"
#include "prepare/flat_scene.h"
#include "util/args.h"

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
  bool moments = false;                     // Also write <image>.moments.exr beside each PNG.
  double resolution_scale = 1.0;            // Scales every camera's pixel count, same view.
  Quantize quantize = Quantize::kTruncate;  // Radiance to 8 bits, as the course's renderer.
  bool skip_existing = false;  // Render only the cameras whose outputs are not all complete.
  double checkpoint_s = 0;     // Seconds between checkpoints (0: only on an interrupt).
  bool resume = false;         // Continue every camera that has a matching checkpoint.
  int tile_rows = 0;           // MPI: rows of a tile when images are cut (0: automatic).
  RenderOptions render;
  LoadOptions load;  // --strict
};

// The options that reach the device: what ends up in the scene header or the OpenCL
// program build. Shared by the raytracer and the reference-image check.
const OptionTable<RenderOptions>& device_option_table();

// The names of --quantize, for every executable that writes 8-bit images.
std::vector<std::pair<std::string, Quantize>> quantize_choices();

// The raytracer's whole table: host options, the device table, the environment.
const OptionTable<CliOptions>& raytracer_option_table();

// Parses argv; on --help / --version prints and exits 0; on a bad option prints one line
// and exits 2.
CliOptions parse_cli(int argc, char** argv);

// parse_cli without printing or exiting: throws UsageError for a bad command line and sets
// *exit_text to what --help or --version print (the command-line fuzzer calls this).
CliOptions parse_arguments(int argc, char** argv, std::string* exit_text);

}  // namespace rt
