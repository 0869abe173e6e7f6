// The path tracer against the course's path-traced references (hw6/reference/pathTracing):
// renders each path-traced camera of a scene with the CPU reference (all of it, or a
// regular subset of 4x4 blocks within --budget samples) and prints one row per camera.
//
// The references are 100-spp renders, so two correct renders differ by their noise. The
// figure of merit is the 4x4-block MAE (8-bit levels, after a 4x4 box downsample) of the
// render's PNG (tone mapped with its own statistics, as raytracer writes it; estimated from
// the subset's statistics with --budget) against the reference's PNG, next to noise floors:
//   floorP  the same figure between the reference and its partner, the reference of the
//           same scene and renderer whose expected PNG agrees: Russian roulette toggled with
//           next-event estimation, importance sampling toggled without it (the
//           pairs: diffuse/diffuse_importance, diffuse_next/diffuse_next_russian...);
//   floorH  the reference against a second render of its own kind, by the three-cornered
//           hat with the render and the importance-toggled reference as the other corners
//           (see below): the floor the target means.
// MAErs / floorR / hatR: the same figures with the render and the partner tone mapped with
// the reference's statistics, which leaves the pixels' noise and bias alone (and no error
// from estimating the render's own statistics on a subset); --check uses these. "mean": ratio of
// mean linear luminance, render over reference, on the same pixels; "zero%": pixels with no light
// at all, which drive the log-average of the tone mapping (and so every pixel of the PNG).
//
// usage: path_reference SCENE.xml REFDIR [--budget SAMPLES] [--camera N] [--spp N] [--seed N]
//                       [--check]
#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <string>
#include <vector>

#include "block_subset.h"
#include "compare/image_metrics.h"
#include "image/read_hdr.h"
#include "image/tonemap.h"
#include "integrator/render.h"
#include "io/png_io.h"
#include "prepare/flat_scene.h"

namespace {

using rt::bench::block_mae;
using rt::bench::crop;
using rt::bench::crop8;
using rt::bench::encode;
using rt::bench::mean_luminance;
using rt::bench::Subset;

struct Options {
  bool check = false;  // Test the render against the reference (exit status 1 on a miss).
  double budget = 0;   // Samples per camera; 0: every pixel.
  int camera = -1;
  int spp = 0;
  uint32_t seed = 0;
};

std::string toggled(const std::string& name, const std::string& word, size_t at) {
  size_t pos = name.find(word);
  if (pos != std::string::npos) return name.substr(0, pos) + name.substr(pos + word.size());
  return name.substr(0, at) + word + name.substr(at);
}

// The partner for the three-cornered hat: importance sampling toggled, whose noise is
// closest to the reference's own, so the difference of squares stays well conditioned.
std::string hat_partner(const std::string& name) {
  // Names read scene[_next][_importance][_russian].
  size_t at = name.find('_');
  if (at == std::string::npos) at = name.size();
  if (name.compare(at, 5, "_next") == 0) at += 5;
  return toggled(name, "_importance", at);
}

// The partner of a reference, for its floor figures: Russian roulette toggled with
// next-event estimation, importance sampling toggled without it (without next-event
// estimation Russian roulette changes the noise, hence the tone mapping, too much:
// diffuse vs diffuse_russian differ by 31.6).
std::string pair_partner(const std::string& name) {
  if (name.find("_next") != std::string::npos) return toggled(name, "_russian", name.size());
  return hat_partner(name);
}

std::string stem(const std::string& file) { return file.substr(0, file.find_last_of('.')); }

double zero_percent(const rt::ImageF& img) {
  size_t zero = 0;
  for (size_t i = 0; i < img.size(); ++i)
    zero += img.pixels[i * 3] <= 0 && img.pixels[i * 3 + 1] <= 0 && img.pixels[i * 3 + 2] <= 0;
  return 100.0 * zero / std::max<size_t>(1, img.size());
}

// --check: the render and the reference estimate the same image. Three criteria, each with
// a false-alarm probability below 1e-4 for a correct renderer:
//  * bias: the mean over blocks of the difference of 4x4-block mean luminances (linear),
//    against its standard error from the blocks' own spread (the blocks are independent,
//    so this covers both images' noise): |z| <= 4;
//  * noise kind: the share of pixels without any light differs by at most 4.5 binomial
//    standard errors (sqrt(2 p (1 - p) / n)); it sets the PNG's tone mapping;
//  * the block MAE (reference's tone mapping) is at most 1.15 times the three-cornered-hat
//    floor (a correct render sits about as far from the reference as a second render of
//    its kind would), or 1.15 times the pair floor when the hat is undefined.
bool check_render(const rt::ImageF& mine, const rt::ImageF& ref, double mae, double floor) {
  double z = rt::bench::block_bias_z(mine, ref);
  double p = zero_percent(ref) / 100, dz = (zero_percent(mine) - zero_percent(ref)) / 100;
  double se_zero = std::sqrt(2 * p * (1 - p) / mine.size());
  bool ok_bias = std::fabs(z) <= 4, ok_zero = std::fabs(dz) <= 4.5 * se_zero + 1e-12;
  bool ok_mae = mae <= 1.15 * floor;
  std::printf(
      "check: bias z = %+.2f (|z| <= 4) %s; zero pixels %+.2f %% (<= %.2f) %s; "
      "block MAE %.2f <= 1.15 x floor %.2f %s\n",
      z, ok_bias ? "ok" : "FAIL", 100 * dz, 450 * se_zero, ok_zero ? "ok" : "FAIL", mae, floor,
      ok_mae ? "ok" : "FAIL");
  return ok_bias && ok_zero && ok_mae;
}

int run(const std::string& scene_file, const std::string& refdir, const Options& o) {
  rt::SceneDesc scene = rt::load_scene(scene_file);
  rt::RenderOptions ro;
  ro.seed = o.seed;
  ro.spp = o.spp;
  rt::FlatScene flat = rt::prepare_scene(scene, ro);
  bool failed = false, skipped = false;
  std::printf("%-30s %4s %6s %6s %11s | %6s %6s %6s %5s %5s | %6s %6s %6s %5s | %6s\n", "camera",
              "spp", "pixels", "mean", "zero% me/rf", "MAE", "floorP", "floorH", "r(P)", "r(H)",
              "MAErs", "floorR", "hatR", "r(R)", "sec");
  for (size_t c = 0; c < scene.cameras.size(); ++c) {
    const rt::CameraDesc& desc = scene.cameras[c];
    if (!desc.path_tracing || (o.camera >= 0 && o.camera != static_cast<int>(c))) continue;
    std::string name = stem(desc.image_name);
    std::string ref_exr = refdir + "/" + name + ".exr", ref_png = refdir + "/" + name + ".png";
    std::string pair_png = refdir + "/" + pair_partner(name) + ".png";
    std::string par = hat_partner(name);
    std::string par_exr = refdir + "/" + par + ".exr", par_png = refdir + "/" + par + ".png";
    if (!std::ifstream(ref_exr) || !std::ifstream(par_exr) || !std::ifstream(pair_png)) {
      std::printf("SKIP: %s: %s or %s is missing\n", name.c_str(), ref_exr.c_str(),
                  par_exr.c_str());
      skipped = true;
      continue;
    }
    rt::prepare_camera(flat, scene, static_cast<int>(c), ro);
    const Camera& cam = flat.header.camera;
    Subset sub = rt::bench::make_subset(cam, o.budget);
    rt::ImageF ref = rt::read_exr(ref_exr), partner = rt::read_exr(par_exr);
    rt::Image8 ref8 = rt::read_png(ref_png), par8 = rt::read_png(par_png);
    const rt::PhotographicParams& tp = desc.tonemap_params;
    rt::PhotographicScale ref_scale = rt::PhotographicStatistics(ref, tp);
    auto start = std::chrono::steady_clock::now();
    rt::ImageF mine = rt::bench::render_subset(flat, sub);
    double seconds =
        std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
    rt::Image8 ref_sub = crop8(ref8, sub), par_sub = crop8(par8, sub);
    rt::ImageF ref_lin = crop(ref, sub), par_lin = crop(partner, sub);
    // The literal figure: the render tone mapped with its own statistics, estimated from
    // the subset when only a subset is rendered (a regular sample of the image's blocks).
    rt::Image8 mine8 = rt::TonemapPhotographic(mine, tp);
    double mae = block_mae(mine8, ref_sub);
    double floor_pair = block_mae(crop8(rt::read_png(pair_png), sub), ref_sub);
    // The reference's own floor (reference against a second render of its own kind) by the
    // three-cornered hat: with independent noise, MAE^2 adds like variance (exactly for
    // Gaussian block noise), so floor^2 = 2 var(ref) = MAE(ref, partner)^2 +
    // MAE(ref, render)^2 - MAE(partner, render)^2, whatever the render's own noise and bias.
    double floor_ref_par = block_mae(par_sub, ref_sub);
    double mae_partner = block_mae(mine8, par_sub);
    double floor_hat = std::sqrt(
        std::max(0.0, floor_ref_par * floor_ref_par + mae * mae - mae_partner * mae_partner));
    // With the reference's statistics: noise and bias of the pixels alone (and no error
    // from estimating the render's statistics on a subset), with its own hat floor.
    rt::Image8 mine_rs = encode(mine, ref_scale, tp), par_rs = encode(par_lin, ref_scale, tp);
    double mae_rs = block_mae(mine_rs, ref_sub);
    double floor_rs = block_mae(par_rs, ref_sub);
    double mae_par_rs = block_mae(mine_rs, par_rs);
    double hat_rs =
        std::sqrt(std::max(0.0, floor_rs * floor_rs + mae_rs * mae_rs - mae_par_rs * mae_par_rs));
    std::printf(
        "%-30s %4d %5.1f%% %6.4f %5.1f %5.1f | %6.2f %6.2f %6.2f %5.2f %5.2f | %6.2f %6.2f "
        "%6.2f %5.2f | %6.1f\n",
        name.c_str(), cam.samples, 100.0 / (sub.stride * sub.stride),
        mean_luminance(mine) / mean_luminance(ref_lin), zero_percent(mine), zero_percent(ref_lin),
        mae, floor_pair, floor_hat, mae / floor_pair, mae / floor_hat, mae_rs, floor_rs, hat_rs,
        mae_rs / hat_rs, seconds);
    if (o.check && !check_render(mine, ref_lin, mae_rs, hat_rs > 0 ? hat_rs : floor_rs))
      failed = true;
    std::fflush(stdout);
  }
  if (o.check) std::printf("%s\n", failed ? "FAIL" : skipped ? "SKIP" : "PASS");
  return failed ? 1 : (o.check && skipped) ? 77 : 0;
}

}  // namespace

int main(int argc, char** argv) {
  if (argc < 3) {
    std::fprintf(stderr,
                 "usage: path_reference SCENE.xml REFDIR [--budget SAMPLES] [--camera N] "
                 "[--spp N] [--seed N] [--check]\n");
    return 2;
  }
  Options o;
  for (int i = 3; i < argc; i += 2) {
    std::string k = argv[i];
    double v = i + 1 < argc ? std::atof(argv[i + 1]) : 0;
    if (k == "--check") {
      o.check = true;
      --i;
      continue;
    }
    if (k == "--budget")
      o.budget = v;
    else if (k == "--camera")
      o.camera = static_cast<int>(v);
    else if (k == "--spp")
      o.spp = static_cast<int>(v);
    else if (k == "--seed")
      o.seed = static_cast<uint32_t>(v);
    else {
      std::fprintf(stderr, "path_reference: unknown option %s\n", k.c_str());
      return 2;
    }
  }
  // As a test (--check), a clone without the course's scenes beside it skips, saying why.
  if (o.check && !std::filesystem::exists(argv[1])) {
    std::printf("SKIP: %s is not here (the course's scenes, ../shared)\n", argv[1]);
    return 77;
  }
  try {
    return run(argv[1], argv[2], o);
  } catch (const std::exception& e) {
    std::fprintf(stderr, "path_reference: %s\n", e.what());
    return 1;
  }
}
