// The speed-accuracy trade of one scene, measured: renders a converged reference (CPU,
// many samples), then a grid of faster settings on both devices, and prints a table of
// render time against relative MSE and the Welch verdict against the reference. It also
// writes the table as TSV for bench/sweep.sh to plot.
//
// usage: sweep SCENE.xml [--camera N] [--scale F] [--ref-spp N] [--tsv FILE] (sweep --help)
//
// Every configuration is validated as it is timed: its error against the reference is in
// the same row, and a configuration whose Welch test fails is biased, not just noisy.
#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <fstream>
#include <memory>
#include <string>
#include <vector>

#include "device/device.h"
#include "family.h"
#include "flat_scene.h"
#include "integrator/render_scheduler.h"
#include "io/moments.h"
#include "render.h"
#include "util/args.h"
#include "welch.h"

namespace {

struct Args {
  std::string scene, tsv;
  int camera = 0;
  double scale = 0.25;
  int ref_spp = 1024;
};

struct Config {
  std::string axis, name, device;  // device: "cpu" or "cl"
  rt::RenderOptions opt;
  bool generic = false;
};

struct Row {
  Config config;
  int spp = 0;
  double build_ms = 0, seconds = 0, rel_mse = 0;
  uint64_t nonfinite = 0;
  std::string verdict;
};

// Relative MSE of `img` against `ref` (3 floats per pixel, radiance on the 0-255 scale):
// mean of (x - r)^2 / (r^2 + 1), the +1 (one level squared) keeping black pixels finite.
double RelativeMse(const std::vector<float>& img, const std::vector<float>& ref) {
  double s = 0;
  for (size_t i = 0; i < ref.size(); ++i) {
    double d = img[i] - ref[i];
    s += d * d / (static_cast<double>(ref[i]) * ref[i] + 1.0);
  }
  return s / ref.size();
}

rt::RenderResult Render(const rt::SceneDesc& scene, const Config& c, int camera,
                        rt::DevicePool& devices, double* build_ms) {
  rt::FlatScene flat = rt::flatten_scene(scene, c.opt);
  *build_ms = flat.stats.bvh_build_ms;
  rt::set_camera(flat, scene, camera, c.opt);
  rt::Progress quiet(false, "", 0);
  // The render's time excludes the program build and its warm-up launch.
  rt::DeviceOptions options;
  options.kind = c.device == "cl" ? rt::Device::kOpenCl : rt::Device::kCpu;
  options.generic_kernel = c.generic;
  std::string why;
  rt::RenderDevice* device = devices.get(options, &why);
  if (!device) throw std::runtime_error(why);
  return rt::render_camera(*device, flat, quiet);
}

Args Parse(int argc, char** argv) {
  using rt::Range;
  rt::OptionTable<Args> t(
      "sweep", "sweep SCENE.xml [options]",
      "Renders a converged CPU reference of SCENE, then a grid of faster settings on both\n"
      "devices, and prints render time, relative MSE and the Welch verdict of each.");
  t.section("Sweep")
      .integer("--camera", "N", Range::closed(0, 1 << 20), RT_FIELD(camera), "the camera")
      .real("--scale", "F", Range::left_open(0, 16), RT_FIELD(scale),
            "resolution scale of every render")
      .integer("--ref-spp", "N", Range::closed(1, 1 << 24), RT_FIELD(ref_spp),
               "samples per pixel of the converged reference")
      .text("--tsv", "FILE", RT_FIELD(tsv), "also write the table as TSV (for the plot)");
  Args a;
  std::vector<std::string> scenes = t.parse_or_exit(argc, argv, &a);
  if (scenes.size() != 1) t.usage_error("needs one SCENE.xml");
  a.scene = scenes[0];
  return a;
}

std::vector<Config> Grid(bool has_cl, bool dielectric) {
  std::vector<Config> grid;
  auto add = [&](std::string axis, std::string name, std::string device, rt::RenderOptions o,
                 bool generic = false) {
    if (device == "cl" && !has_cl) return;
    grid.push_back({axis, name, device, o, generic});
  };
  for (std::string dev : {"cpu", "cl"})
    for (int spp : {1, 4, 16, 64}) {
      rt::RenderOptions o;
      o.spp = spp;
      add("spp", "spp " + std::to_string(spp), dev, o);
    }
  rt::RenderOptions base;
  base.spp = 16;
  add("kernel", "generic kernel", "cl", base, true);
  rt::RenderOptions fast = base;
  fast.fast_math = true;
  add("math", "-cl-fast-relaxed-math", "cl", fast);
  rt::RenderOptions in_double = base;
  in_double.precision = rt::Precision::kDouble;
  add("precision", "--precision double", "cpu", in_double);
  add("precision", "--precision double", "cl", in_double);
  for (auto [bins, leaf] :
       {std::pair{4, 1}, std::pair{8, 2}, std::pair{32, 8}, std::pair{64, 16}}) {
    rt::RenderOptions o = base;
    o.bvh.bins = bins;
    o.bvh.max_leaf = leaf;
    std::string n = "bvh bins " + std::to_string(bins) + " leaf " + std::to_string(leaf);
    add("bvh", n, "cpu", o);
    add("bvh", n, "cl", o);
  }
  if (dielectric)
    for (std::string dev : {"cpu", "cl"})
      for (int spp : {16, 64}) {
        rt::RenderOptions o;
        o.spp = spp;
        o.fresnel_choice = true;
        add("dielectric", "choose by Fresnel, spp " + std::to_string(spp), dev, o);
      }
  return grid;
}

}  // namespace

int main(int argc, char** argv) {
  Args a = Parse(argc, argv);
  try {
    rt::SceneDesc scene = rt::load_scene(a.scene);
    for (auto& cam : scene.cameras) {
      cam.width = std::max(1, static_cast<int>(std::lround(cam.width * a.scale)));
      cam.height = std::max(1, static_cast<int>(std::lround(cam.height * a.scale)));
    }
    std::string why;
    rt::DevicePool devices;
    rt::DeviceOptions cl_options;
    cl_options.kind = rt::Device::kOpenCl;
    const bool has_cl = devices.get(cl_options, &why) != nullptr;
    if (!has_cl) std::fprintf(stderr, "note: no OpenCL device (%s); CPU rows only\n", why.c_str());
    bool dielectric = false;
    for (const Material& m : scene.materials) dielectric |= m.type == RT_MATERIAL_DIELECTRIC;

    Config ref_config{"reference", "reference", "cpu", {}, false};
    ref_config.opt.spp = a.ref_spp;
    ref_config.opt.seed = 1000;  // Independent of the candidates' seed 0.
    double ms;
    rt::RenderResult ref = Render(scene, ref_config, a.camera, devices, &ms);
    std::vector<float> ref_rgb = ref.rgb();
    rt::MomentImage ref_m = rt::moments_from_render(ref, {1000, ref.spp, "box", "cpu", a.scene, 0});
    std::printf("%s, camera %d at %dx%d; reference: CPU, %d spp, %.1f s (seed 1000)\n\n",
                a.scene.c_str(), a.camera, ref.width, ref.height, ref.spp, ref.seconds);
    std::printf(
        "| axis | setting | device | spp | BVH build ms | render s | rel. MSE | "
        "Welch (pooled) vs reference | non-finite |\n|---|---|---|---:|---:|---:|---:|---|---:|\n");
    std::vector<Row> rows;
    for (const Config& c : Grid(has_cl, dielectric)) {
      Row row;
      row.config = c;
      rt::RenderResult r = Render(scene, c, a.camera, devices, &row.build_ms);
      row.spp = r.spp;
      row.seconds = r.seconds;
      row.rel_mse = RelativeMse(r.rgb(), ref_rgb);
      row.nonfinite = r.nonfinite();
      if (r.spp >= 2) {
        rt::MomentImage m = rt::moments_from_render(r, {0, r.spp, "box", c.device, a.scene, 0});
        cmp::WelchOptions wo;
        wo.pooled = true;  // Few-sample renders can miss rare paths entirely.
        cmp::Family f = cmp::welch_test(ref_m, m, wo);
        cmp::Verdict v = cmp::decide(f, cmp::FamilyOptions());
        char buf[96];
        std::snprintf(buf, sizeof buf, "%s (%zu/%zu rejected)", v.pass ? "PASS" : "FAIL",
                      v.rejections, v.tests);
        row.verdict = buf;
      } else {
        row.verdict = "n/a (1 spp: no variance)";
      }
      std::printf("| %s | %s | %s | %d | %.1f | %.3f | %.3g | %s | %llu |\n", c.axis.c_str(),
                  c.name.c_str(), (c.device + (c.generic ? " generic" : "")).c_str(), row.spp,
                  row.build_ms, row.seconds, row.rel_mse, row.verdict.c_str(),
                  static_cast<unsigned long long>(row.nonfinite));
      std::fflush(stdout);
      rows.push_back(row);
    }
    if (!a.tsv.empty()) {
      std::ofstream t(a.tsv);
      t << "axis\tsetting\tdevice\tspp\tbuild_ms\tseconds\trel_mse\n";
      for (const Row& r : rows)
        t << r.config.axis << '\t' << r.config.name << '\t' << r.config.device
          << (r.config.generic ? "-generic" : "") << '\t' << r.spp << '\t' << r.build_ms << '\t'
          << r.seconds << '\t' << r.rel_mse << '\n';
    }
    return 0;
  } catch (const std::exception& e) {
    std::fprintf(stderr, "sweep: %s\n", e.what());
    return 1;
  }
}
