// The speed-accuracy trade of one scene, measured: renders a converged reference (CPU,
// many samples, cached), then a grid of faster settings on both devices (bench/sweep_grid.h),
// and prints a table of render time in CPU-seconds against relative MSE and the Welch
// verdict against the reference. It also writes the table as TSV for bench/sweep.sh to plot.
//
// usage: sweep SCENE.xml [--camera N] [--scale F] [--ref-spp N] [--reps N] [--tsv FILE]
//        [--cache DIR | --no-cache]   (sweep --help)
//
// Every configuration is validated as it is timed: its error against the reference is in
// the same row, and a configuration whose Welch test fails is biased, not just noisy.
// A path-traced camera's estimators converge to different images (the bounce limit, the
// course's roulette), so each is measured against the reference of its own class, and its
// bias against the full light transport is a column of its own.
#include <cmath>
#include <cstdio>
#include <fstream>
#include <map>
#include <string>
#include <vector>

#include "family.h"
#include "prepare/flat_scene.h"
#include "sweep_grid.h"
#include "sweep_run.h"
#include "util/args.h"
#include "welch.h"

namespace {

struct Args {
  std::string scene, tsv, cache = sweep::DefaultCacheDir();
  int camera = 0;
  double scale = 0.25;
  int ref_spp = 1024;
  int reps = 1;
  bool no_cache = false;
};

constexpr double kTrim = 0.001;  // The share of largest error terms TrimmedRelativeMse drops.

struct Row {
  sweep::Config config;
  int spp = 0;
  double build_ms = 0, cpu_s = 0, wall_s = 0, rel_mse = 0, noise2 = 0;
  double rel_mse_full = 0, bias_full = 0;  // Path tracing: against the full transport.
  double trimmed = 0, trimmed_full = 0;    // Path tracing: the largest 0.1 % dropped.
  uint64_t nonfinite = 0;
  std::string verdict, vs_float;
};

Args Parse(int argc, char** argv) {
  using rt::Range;
  rt::OptionTable<Args> t(
      "sweep", "sweep SCENE.xml [options]",
      "Renders a converged CPU reference of SCENE (cached), then a grid of faster settings on\n"
      "both devices, and prints render CPU-seconds, relative MSE and the Welch verdict of each.");
  t.section("Sweep")
      .integer("--camera", "N", Range::closed(0, 1 << 20), RT_FIELD(camera), "the camera")
      .real("--scale", "F", Range::left_open(0, 16), RT_FIELD(scale),
            "resolution scale of every render")
      .integer("--ref-spp", "N", Range::closed(1, 1 << 24), RT_FIELD(ref_spp),
               "samples per pixel of the converged reference")
      .integer("--reps", "N", Range::closed(1, 99), RT_FIELD(reps),
               "render each setting N times and keep the median CPU time")
      .text("--tsv", "FILE", RT_FIELD(tsv), "also write the table as TSV (for the plot)")
      .text("--cache", "DIR", RT_FIELD(cache),
            "where converged references are kept between runs (default "
            "$XDG_CACHE_HOME/raytracer/sweep)")
      .flag("--no-cache", RT_FIELD(no_cache), "always render the references, keep none");
  Args a;
  std::vector<std::string> scenes = t.parse_or_exit(argc, argv, &a);
  if (scenes.size() != 1) t.usage_error("needs one SCENE.xml");
  a.scene = scenes[0];
  if (a.no_cache) a.cache.clear();
  return a;
}

std::string WelchVerdict(const rt::MomentImage& ref, const rt::RenderResult& r,
                         const std::string& device) {
  if (r.spp < 2) return "n/a (1 spp: no variance)";
  rt::MomentImage m = rt::moments_from_render(r, {0, r.spp, "box", device, "", 0});
  cmp::WelchOptions wo;
  wo.pooled = true;  // Few-sample renders can miss rare paths entirely.
  cmp::Family f = cmp::welch_test(ref, m, wo);
  cmp::Verdict v = cmp::decide(f, cmp::FamilyOptions());
  char buf[96];
  std::snprintf(buf, sizeof buf, "%s (%zu/%zu rejected)", v.pass ? "PASS" : "FAIL", v.rejections,
                v.tests);
  return buf;
}

// The double image against the float one of the same device, seed and spp: the share of
// values within one output level, and the largest difference in levels.
std::string VsFloat(const std::vector<float>& d, const std::vector<float>& f, double floor) {
  if (f.size() != d.size() || f.empty()) return "";
  size_t within = 0;
  double worst = 0;
  for (size_t i = 0; i < f.size(); ++i) {
    const double levels = std::fabs(d[i] - f[i]) / floor;
    within += levels <= 1.0;
    worst = std::max(worst, levels);
  }
  char buf[64];
  std::snprintf(buf, sizeof buf, "%.3f %% within 1 level, max %.2g", 100.0 * within / f.size(),
                worst);
  return buf;
}

void PrintRow(const Row& r, bool path) {
  std::printf("| %s | %s | %s%s | %d | %.3f | %.3f | %.3g | %.3g | %s |", r.config.axis.c_str(),
              r.config.name.c_str(), r.config.device.c_str(), r.config.generic ? " generic" : "",
              r.spp, r.cpu_s, r.wall_s, r.rel_mse, r.noise2, r.verdict.c_str());
  if (path)
    std::printf(" %.3g | %.3g | %.3g | %+.2f %% |", r.trimmed, r.rel_mse_full, r.trimmed_full,
                100.0 * r.bias_full);
  std::printf(" %s | %llu |\n", r.vs_float.c_str(), static_cast<unsigned long long>(r.nonfinite));
  std::fflush(stdout);
}

void WriteTsv(const std::string& path, const std::vector<Row>& rows) {
  std::ofstream t(path);
  t << "axis\tsetting\tdevice\tspp\tbuild_ms\tcpu_s\twall_s\trel_mse\tnoise2\trel_mse_full\t"
       "bias_full\ttrimmed\ttrimmed_full\n";
  for (const Row& r : rows)
    t << r.config.axis << '\t' << r.config.name << '\t' << r.config.device
      << (r.config.generic ? "-generic" : "") << '\t' << r.spp << '\t' << r.build_ms << '\t'
      << r.cpu_s << '\t' << r.wall_s << '\t' << r.rel_mse << '\t' << r.noise2 << '\t'
      << r.rel_mse_full << '\t' << r.bias_full << '\t' << r.trimmed << '\t' << r.trimmed_full
      << '\n';
}

}  // namespace

int main(int argc, char** argv) {
  Args a = Parse(argc, argv);
  try {
    rt::SceneDesc scene = sweep::LoadScaledScene(a.scene, a.camera, a.scale);
    const rt::CameraDesc& cam = scene.cameras[a.camera];
    const bool path = cam.path_tracing;
    const double key = cam.tonemap ? cam.tonemap_params.key : 0.0;
    std::string why;
    rt::DevicePool devices;
    rt::DeviceOptions cl_options;
    cl_options.kind = rt::Device::kOpenCl;
    const bool has_cl = devices.get(cl_options, &why) != nullptr;
    if (!has_cl) std::fprintf(stderr, "note: no OpenCL device (%s); CPU rows only\n", why.c_str());
    bool dielectric = false;
    for (const Material& m : scene.materials) dielectric |= m.type == RT_MATERIAL_DIELECTRIC;

    const double load_before = sweep::LoadAverage();
    std::map<sweep::ReferenceClass, sweep::Reference> refs;
    auto reference = [&](const sweep::ReferenceClass& k) -> const sweep::Reference& {
      auto it = refs.find(k);
      if (it != refs.end()) return it->second;
      const sweep::Config c = sweep::ReferenceConfig(k, a.ref_spp);
      sweep::Reference r = sweep::ConvergedReference(a.scene, scene, c, a.camera, devices, a.cache);
      char took[64];
      std::snprintf(took, sizeof took, "%.1f CPU-s", r.cpu_seconds);
      std::printf("reference%s%s: CPU, %d spp, seed 1000, %s\n", path ? " " : "",
                  path ? sweep::EstimatorName(c.path_flags, k.unbiased_roulette).c_str() : "",
                  a.ref_spp, r.cached ? "from the cache" : took);
      return refs.emplace(k, std::move(r)).first->second;
    };
    std::printf(
        "%s, camera %d%s at %dx%d; load average %.2f at the start\n", a.scene.c_str(), a.camera,
        path ? (" (path traced: " + sweep::EstimatorName(cam.path_flags, false) + ")").c_str() : "",
        cam.width, cam.height, load_before);
    const sweep::Reference* full = path ? &reference(sweep::FullTransport()) : nullptr;
    const std::vector<sweep::Config> grid =
        path ? sweep::PathTracingGrid(has_cl) : sweep::RayTracingGrid(has_cl, dielectric);
    for (const sweep::Config& c : grid) reference(sweep::ClassOf(c, path, cam.path_flags));
    const double floor = rt::noise_floor(full ? full->rgb : refs.begin()->second.rgb, key);
    std::printf(
        "\nrender CPU-s: user + system of the process (median of %d); rel. MSE: mean of "
        "(x - r)^2 / (r^2 + f^2), f = %.3g (one output level); est.: relative_noise^2, "
        "what --noise-target sees%s\n\n",
        a.reps, floor, path ? "; trimmed: the largest 0.1 % of the terms dropped" : "");
    std::printf(
        "| axis | setting | device | spp | render CPU-s | wall s | rel. MSE | est. | "
        "Welch (pooled) vs reference |%s double vs float | non-finite |\n"
        "|---|---|---|---:|---:|---:|---:|---:|---|%s---|---:|\n",
        path ? " trimmed | rel. MSE vs full transport | trimmed | mean vs full |" : "",
        path ? "---:|---:|---:|---:|" : "");
    std::vector<Row> rows;
    std::map<std::string, std::vector<float>> float_images;  // "device spp" of the spp axis.
    for (const sweep::Config& c : grid) {
      const sweep::Reference& ref = reference(sweep::ClassOf(c, path, cam.path_flags));
      sweep::Timed t = sweep::Render(scene, c, a.camera, devices, a.reps);
      const std::vector<float> rgb = t.result.rgb();
      Row row;
      row.config = c;
      row.spp = t.result.spp;
      row.build_ms = t.build_ms;
      row.cpu_s = t.cpu_seconds;
      row.wall_s = t.result.seconds;
      row.rel_mse = rt::relative_mse(rgb, ref.rgb, floor);
      const double noise = rt::relative_noise(t.result.accum, t.result.width, floor);
      row.noise2 = noise * noise;
      row.nonfinite = t.result.nonfinite();
      row.verdict = WelchVerdict(ref.moments, t.result, c.device);
      if (full) {
        row.rel_mse_full = rt::relative_mse(rgb, full->rgb, floor);
        row.bias_full = sweep::MeanBias(rgb, full->rgb);
        row.trimmed = sweep::TrimmedRelativeMse(rgb, ref.rgb, floor, kTrim);
        row.trimmed_full = sweep::TrimmedRelativeMse(rgb, full->rgb, floor, kTrim);
      }
      const std::string same = c.device + " " + std::to_string(row.spp);
      if (c.axis == "spp") float_images[same] = rgb;
      if (c.axis == "precision") row.vs_float = VsFloat(rgb, float_images[same], floor);
      PrintRow(row, path);
      rows.push_back(row);
    }
    std::printf("\nload average %.2f at the end (2 cores, shared)\n", sweep::LoadAverage());
    if (!a.tsv.empty()) WriteTsv(a.tsv, rows);
    return 0;
  } catch (const std::exception& e) {
    std::fprintf(stderr, "sweep: %s\n", e.what());
    return 1;
  }
}
