// The independent and the Sobol sampler (--sampler) on one camera: relative MSE against a
// converged reference at 16, 64 and 256 spp on the CPU reference (plain, and trimmed of the
// largest 0.1 % of its terms as bench/sweep trims a path tracer's heavy tail), and the render's
// CPU-seconds per million samples on both devices.
//
// usage: sampler_bench SCENE.xml [--camera N] [--scale F] [--ref-spp N] [--reps N] [--no-cl]
//
// The reference is the CPU's at --ref-spp with the Sobol sampler and seed 1000 (cached as
// bench/sweep caches its references); the candidates use seed 0, so the reference's own
// noise adds to every row alike. CPU-seconds are the median of --reps renders, user + system
// of the process (PoCL's threads included).
#include <algorithm>
#include <cmath>
#include <cstdio>
#include <string>
#include <vector>

#include "prepare/flat_scene.h"
#include "sweep_run.h"
#include "util/args.h"

namespace {

struct Args {
  std::string scene;
  int camera = 0;
  double scale = 0.5;
  int ref_spp = 1024;
  int reps = 1;
  bool no_cl = false;
};

Args Parse(int argc, char** argv) {
  using rt::Range;
  rt::OptionTable<Args> t("sampler_bench", "sampler_bench SCENE.xml [options]",
                          "Relative MSE and CPU-seconds of --sampler independent and sobol.");
  t.section("Bench")
      .integer("--camera", "N", Range::closed(0, 1 << 20), RT_FIELD(camera), "the camera")
      .real("--scale", "F", Range::left_open(0, 16), RT_FIELD(scale), "resolution scale")
      .integer("--ref-spp", "N", Range::closed(1, 1 << 20), RT_FIELD(ref_spp),
               "the reference's samples per pixel")
      .integer("--reps", "N", Range::closed(1, 99), RT_FIELD(reps), "renders per row (median)")
      .flag("--no-cl", RT_FIELD(no_cl), "the CPU reference only");
  Args a;
  std::vector<std::string> scenes = t.parse_or_exit(argc, argv, &a);
  if (scenes.size() != 1) t.usage_error("needs one SCENE.xml");
  a.scene = scenes[0];
  return a;
}

}  // namespace

int main(int argc, char** argv) {
  Args a = Parse(argc, argv);
  try {
    rt::SceneDesc scene = sweep::LoadScaledScene(a.scene, a.camera, a.scale);
    const rt::CameraDesc& cam = scene.cameras[a.camera];
    rt::DevicePool devices;
    sweep::Config ref_config{"reference", "reference", "cpu", {}, false, -1};
    ref_config.opt.spp = a.ref_spp;
    ref_config.opt.seed = 1000;
    ref_config.opt.sampler = rt::SamplerChoice::kSobol;
    sweep::Reference ref = sweep::ConvergedReference(a.scene, scene, ref_config, a.camera, devices,
                                                     sweep::DefaultCacheDir());
    const double floor = rt::noise_floor(ref.rgb, cam.tonemap ? cam.tonemap_params.key : 0.0);
    std::printf(
        "%s, camera %d at %dx%d; reference: CPU, sobol, %d spp, seed 1000, %s; load %.2f\n",
        a.scene.c_str(), a.camera, cam.width, cam.height, a.ref_spp,
        ref.cached ? "from the cache" : (std::to_string(ref.cpu_seconds) + " CPU-s").c_str(),
        sweep::LoadAverage());
    std::printf(
        "| spp | sampler | device | rel. MSE | trimmed | CPU-s | CPU-s per M samples |\n"
        "|---:|---|---|---:|---:|---:|---:|\n");
    // The devices' images are the same bits, so OpenCL renders only the first count, for its
    // cost.
    for (int spp : {16, 64, 256})
      for (const char* sampler : {"independent", "sobol"})
        for (const char* device : {"cpu", "cl"}) {
          if (std::string(device) == "cl" && (spp != 16 || a.no_cl)) continue;
          sweep::Config c{"sampler", sampler, device, {}, false, -1};
          c.opt.spp = spp;
          c.opt.sampler = std::string(sampler) == "sobol" ? rt::SamplerChoice::kSobol
                                                          : rt::SamplerChoice::kIndependent;
          sweep::Timed t = sweep::Render(scene, c, a.camera, devices, a.reps);
          const double samples = 1e-6 * spp * cam.width * cam.height;
          const std::vector<float> rgb = t.result.rgb();
          std::printf("| %d | %s | %s | %.4g | %.4g | %.2f | %.3f |\n", spp, sampler, device,
                      rt::relative_mse(rgb, ref.rgb, floor),
                      sweep::TrimmedRelativeMse(rgb, ref.rgb, floor, 0.001), t.cpu_seconds,
                      t.cpu_seconds / samples);
          std::fflush(stdout);
        }
    std::printf("load average at the end %.2f\n", sweep::LoadAverage());
  } catch (const std::exception& e) {
    std::fprintf(stderr, "sampler_bench: %s\n", e.what());
    return 1;
  }
}
