// Whether a path tracer's estimator has finite variance: renders one camera at several
// sample counts and prints relative MSE x spp against a converged reference of the same
// estimator (bench/sweep_run.h: cached, seed 1000). For an estimator of finite variance
// the product stays flat as spp grows; one whose samples' variance is unbounded (light
// samples near a light, weight 1 / d^2) shows it growing, since ever rarer, ever larger
// samples keep arriving. Also the CPU-seconds per sample (CPU reference, the process's
// user + system time).
//
// usage: estimator_variance SCENE.xml [--camera N] [--scale F] [--ref-spp N]
//                           [--path-estimator course|mis] [--reps N]
#include <algorithm>
#include <cmath>
#include <cstdio>
#include <stdexcept>
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
  int ref_spp = 4096;
  bool mis = false;
  int reps = 1;
};

Args Parse(int argc, char** argv) {
  using rt::Range;
  Args a;
  rt::OptionTable<Args> t("estimator_variance", "estimator_variance SCENE.xml [options]",
                          "Relative MSE x spp of a path-traced camera at 16, 64 and 256 spp.");
  t.section("Estimator")
      .integer("--camera", "N", Range::closed(0, 1 << 20), RT_FIELD(camera), "the camera")
      .real("--scale", "F", Range::left_open(0, 16), RT_FIELD(scale), "resolution scale")
      .integer("--ref-spp", "N", Range::closed(1, 1 << 24), RT_FIELD(ref_spp),
               "samples per pixel of the reference")
      .choice("--path-estimator",
              std::vector<std::pair<std::string, bool>>{{"course", false}, {"mis", true}},
              RT_FIELD(mis), "the path tracer's estimator")
      .integer("--reps", "N", Range::closed(1, 99), RT_FIELD(reps),
               "renders per row; the median CPU time is kept");
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
    const double key = cam.tonemap ? cam.tonemap_params.key : 0.0;
    rt::DevicePool devices;
    sweep::Config ref_config{"reference", "reference", "cpu", {}, false, -1};
    ref_config.opt.spp = a.ref_spp;
    ref_config.opt.seed = 1000;
    ref_config.opt.mis = a.mis;
    sweep::Reference ref = sweep::ConvergedReference(a.scene, scene, ref_config, a.camera, devices,
                                                     sweep::DefaultCacheDir());
    const double floor = rt::noise_floor(ref.rgb, key);
    std::printf("%s, camera %d at %dx%d, --path-estimator %s; reference %d spp (%s); load %.2f\n",
                a.scene.c_str(), a.camera, cam.width, cam.height, a.mis ? "mis" : "course",
                a.ref_spp, ref.cached ? "cached" : "rendered", sweep::LoadAverage());
    std::printf("| spp | rel. MSE | rel. MSE x spp | trimmed x spp | CPU-s | CPU-us / sample |\n");
    std::printf("|---:|---:|---:|---:|---:|---:|\n");
    for (int spp : {16, 64, 256}) {
      sweep::Config c{"spp", "spp", "cpu", {}, false, -1};
      c.opt.spp = spp;
      c.opt.mis = a.mis;
      sweep::Timed t = sweep::Render(scene, c, a.camera, devices, a.reps);
      const std::vector<float> rgb = t.result.rgb();
      const double mse = rt::relative_mse(rgb, ref.rgb, floor);
      const double trimmed = sweep::TrimmedRelativeMse(rgb, ref.rgb, floor, 0.001);
      const double samples = static_cast<double>(cam.width) * cam.height * spp;
      std::printf("| %d | %.4g | %.3g | %.3g | %.2f | %.3f |\n", spp, mse, mse * spp, trimmed * spp,
                  t.cpu_seconds, 1e6 * t.cpu_seconds / samples);
    }
  } catch (const std::exception& e) {
    std::fprintf(stderr, "estimator_variance: %s\n", e.what());
    return 1;
  }
  return 0;
}
