#include "cli.h"

#include <cstdio>
#include <cstdlib>
#include <cstring>

#include "version.h"

namespace rt {
namespace {

const char* kUsage = R"(usage: raytracer SCENE.xml [options]

Renders every camera of a METU CENG795 scene file to PNG (one file per camera,
named by its ImageName).

Device:
  --device auto|cl|cpu   auto (default): OpenCL when a usable device exists, else the
                         CPU reference (with a notice); cl: OpenCL only; cpu: the C++
                         reference renderer
  --cl-device SEL        OpenCL device by index (see --list-devices) or name substring
  --list-devices         list OpenCL platforms and devices, then exit
  --kernel generic       compile the all-features kernel instead of one specialized
                         to the scene's features
  --no-kernel-cache      always compile the kernel; do not read or write the cache
  --threads N            CPU reference threads (default: all cores)

Output:
  --output-dir DIR       where PNGs are written (default: current directory)
  --camera N             render only camera N (0-based, in file order)
  --quiet                no progress and no notices
  --stats                print timings, BVH figures, samples/s and rays/s, features
  --moments              also write <ImageName minus .png>.moments.exr beside each PNG:
                         per-pixel sample count, mean and variance of the unclamped
                         radiance, and the first sample's hit (OpenEXR; see
                         compare --help and src/io/moments.h for the channels)
  --strict               treat every warning about the scene as an error (unknown
                         elements, repeated ids, skipped degenerate triangles)
  --resolution-scale F   render width*F x height*F pixels (rounded, at least 1) of the
                         same view, e.g. for quick tests (default 1)

Sampling:
  --spp N                samples per pixel, overriding the scene's NumSamples
  --seed N               random stream (default 0); equal seeds give equal images
  --filter box|gaussian  reconstruction filter (default box)
  --filter-sigma S       Gaussian standard deviation in pixels (default 0.5)
  --lens square|disk     lens shape for depth of field (default square, as the course)
  --time-limit S         stop sampling when the next pass would end after S seconds
                         (every pixel keeps the same sample count; at least one pass)
  --noise-target E       stop sampling once the estimated relative error of the image
                         (root mean of var(pixel mean) / (mean^2 + 1), 0-255 scale)
                         is below E; E^2 estimates the relative MSE of bench/sweep
  --dielectric split|choose
                         split (default, as the course): follow both the reflected and
                         the refracted ray; choose: follow one, picked by Fresnel
  --fast-math            OpenCL: build with -cl-fast-relaxed-math (faster, less exact;
                         the CPU reference is always precise)

Geometry:
  --cull-back-faces      primary and reflected rays ignore triangles facing away (the
                         course's hw1 reference images were made this way)
  --background-on-secondary-miss
                         reflected/refracted rays that escape see BackgroundColor
                         (default: only camera rays do)
  --no-scene-epsilon     ignore ShadowRayEpsilon; rely on the scale-aware offset alone
  --bvh-bins N           SAH bins per axis (default 16)
  --bvh-leaf N           largest leaf the SAH may choose (default 4)

  --help, --version
)";

[[noreturn]] void usage_error(const std::string& what) {
  throw CliExit{2, "raytracer: " + what + "\n(see raytracer --help)\n"};
}

long parse_long(const char* opt, const char* value, long lo, long hi) {
  char* end = nullptr;
  long v = std::strtol(value, &end, 10);
  if (!*value || *end || v < lo || v > hi)
    usage_error(std::string(opt) + ": '" + value + "' is not a whole number in [" +
                std::to_string(lo) + ", " + std::to_string(hi) + "]");
  return v;
}

double parse_positive(const char* opt, const char* value) {
  char* end = nullptr;
  double v = std::strtod(value, &end);
  if (!*value || *end || !(v > 0) || !(v < 1e12))
    usage_error(std::string(opt) + ": '" + value + "' is not a positive number");
  return v;
}

}  // namespace

CliOptions parse_cli(int argc, char** argv) {
  try {
    return parse_arguments(argc, argv);
  } catch (const CliExit& e) {
    std::fputs(e.message.c_str(), e.status == 0 ? stdout : stderr);
    std::exit(e.status);
  }
}

CliOptions parse_arguments(int argc, char** argv) {
  CliOptions o;
  for (int i = 1; i < argc; ++i) {
    std::string a = argv[i];
    auto value = [&]() -> const char* {
      if (i + 1 >= argc) usage_error(a + " needs a value");
      return argv[++i];
    };
    if (a == "--help" || a == "-h") {
      throw CliExit{0, kUsage};
    } else if (a == "--version") {
      throw CliExit{0, std::string("raytracer ") + RT_VERSION + "\n"};
    } else if (a == "--device") {
      std::string v = value();
      if (v == "auto") o.device = Device::kAuto;
      else if (v == "cpu") o.device = Device::kCpu;
      else if (v == "cl") o.device = Device::kOpenCl;
      else usage_error("--device: '" + v + "' is not one of auto, cl, cpu");
    } else if (a == "--cl-device") {
      o.cl_device = value();
    } else if (a == "--list-devices") {
      o.list_devices = true;
    } else if (a == "--kernel") {
      std::string v = value();
      if (v == "generic") o.generic_kernel = true;
      else if (v == "specialized") o.generic_kernel = false;
      else usage_error("--kernel: '" + v + "' is not one of generic, specialized");
    } else if (a == "--no-kernel-cache") {
      o.kernel_cache = false;
    } else if (a == "--threads") {
      o.threads = static_cast<int>(parse_long("--threads", value(), 1, 4096));
    } else if (a == "--output-dir") {
      o.output_dir = value();
    } else if (a == "--camera") {
      o.camera = static_cast<int>(parse_long("--camera", value(), 0, 1 << 20));
    } else if (a == "--quiet" || a == "-q") {
      o.quiet = true;
    } else if (a == "--stats") {
      o.stats = true;
    } else if (a == "--strict") {
      o.load.strict = true;
    } else if (a == "--moments") {
      o.moments = true;
    } else if (a == "--resolution-scale") {
      const char* v = value();
      char* end = nullptr;
      double f = std::strtod(v, &end);
      if (!*v || *end || !(f > 0 && f <= 16))
        usage_error(std::string("--resolution-scale: '") + v + "' is not in (0, 16]");
      o.resolution_scale = f;
    } else if (a == "--spp") {
      o.render.spp = static_cast<int>(parse_long("--spp", value(), 1, 1 << 20));
    } else if (a == "--seed") {
      o.render.seed = static_cast<uint32_t>(parse_long("--seed", value(), 0, 4294967295L));
    } else if (a == "--filter") {
      std::string v = value();
      if (v == "box") o.render.filter = RT_FILTER_BOX;
      else if (v == "gaussian") o.render.filter = RT_FILTER_GAUSSIAN;
      else usage_error("--filter: '" + v + "' is not one of box, gaussian");
    } else if (a == "--filter-sigma") {
      const char* v = value();
      char* end = nullptr;
      double s = std::strtod(v, &end);
      if (*end || !(s > 0 && s < 100)) usage_error(std::string("--filter-sigma: '") + v + "' is not in (0, 100)");
      o.render.filter_sigma = static_cast<float>(s);
    } else if (a == "--lens") {
      std::string v = value();
      if (v == "square") o.render.lens = RT_LENS_SQUARE;
      else if (v == "disk") o.render.lens = RT_LENS_DISK;
      else usage_error("--lens: '" + v + "' is not one of square, disk");
    } else if (a == "--time-limit") {
      o.render.stop.time_limit_s = parse_positive("--time-limit", value());
    } else if (a == "--noise-target") {
      o.render.stop.noise_target = parse_positive("--noise-target", value());
    } else if (a == "--dielectric") {
      std::string v = value();
      if (v == "split") o.render.fresnel_choice = false;
      else if (v == "choose") o.render.fresnel_choice = true;
      else usage_error("--dielectric: '" + v + "' is not one of split, choose");
    } else if (a == "--fast-math") {
      o.render.fast_math = true;
    } else if (a == "--cull-back-faces") {
      o.render.cull_back_faces = true;
    } else if (a == "--background-on-secondary-miss") {
      o.render.background_on_secondary_miss = true;
    } else if (a == "--no-scene-epsilon") {
      o.render.use_scene_epsilon = false;
    } else if (a == "--bvh-bins") {
      o.render.bvh.bins = static_cast<int>(parse_long("--bvh-bins", value(), 2, 256));
    } else if (a == "--bvh-leaf") {
      o.render.bvh.max_leaf = static_cast<int>(parse_long("--bvh-leaf", value(), 1, 64));
    } else if (!a.empty() && a[0] == '-') {
      usage_error("unknown option '" + a + "'");
    } else if (o.scene.empty()) {
      o.scene = a;
    } else {
      usage_error("more than one scene file given ('" + o.scene + "', '" + a + "')");
    }
  }
  if (o.scene.empty() && !o.list_devices) usage_error("no scene file given");
  return o;
}

}  // namespace rt
