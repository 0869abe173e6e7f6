// One camera of a scene against its reference image where a full render is out of reach
// (hw6/veach-ajar: 1280 x 720 at 2500 spp): renders a regular subset of 4x4 blocks at the
// camera's full sample count with the CPU reference (block_subset.h) and compares it with
// the reference's EXR (linear radiance, no tone mapper in between) and PNG, next to the
// noise both sides are expected to carry.
//
// Noise: each pixel's sample variance s^2 (the film's sum of squares) gives the variance
// of our mean, s^2 / n; the reference's is taken as ours at its own sample count
// (s^2 / n_ref), the same renderer's estimate of the same integral. Figures:
//   linear    mean luminance ratio (render / reference) with its standard error; the bias
//             z over 4x4 blocks from the blocks' own spread; the per-channel MAE against
//             the MAE expected from noise alone (E|d| = sqrt(2 v / pi) for d ~ N(0, v));
//             chi2 = mean of d^2 / v (1 for noise alone; heavy-tailed paths raise it);
//   tone map  both sides tone mapped with the reference EXR's statistics (the whole
//             image's): 4x4-block MAE in 8-bit levels against the reference's PNG, and the
//             same figure expected from noise alone (a parametric bootstrap: our pixels
//             against our pixels plus Gaussian noise of variance v, 8 draws); "tm check"
//             is the reference EXR through our tone mapper against its own PNG;
//   per object the same linear figures for the pixels whose camera ray hits each object
//             instance, to find a convention that differs on one material.
//
// usage: subset_reference SCENE.xml CAMERA REF.exr REF.png [--budget SAMPLES] [--seed N]
//                         [--spp N] [--ref-spp N] [--save FILE | --load FILE]
// --save writes the rendered subset (means, variances, instances) so that --load can
// compare it again without rendering.
#include <chrono>
#include <cstdio>
#include <fstream>
#include <map>
#include <random>
#include <stdexcept>
#include <string>
#include <vector>

#include "block_subset.h"
#include "image/read_hdr.h"
#include "integrator/render.h"

namespace {

using rt::ImageF;
using rt::bench::Subset;

struct Options {
  double budget = 1e7;
  int spp = 0, ref_spp = 0;
  uint32_t seed = 0;
  std::string save, load;
};

// The rendered subset: what --save writes and --load reads back.
struct Rendered {
  Subset sub;
  int spp = 0;
  double seconds = 0;
  ImageF mean, variance;
  std::vector<int> instance;
};

void save(const std::string& path, const Rendered& r) {
  std::ofstream f(path, std::ios::binary);
  int head[5] = {r.sub.stride, r.sub.width, r.sub.height, r.spp, 0};
  f.write(reinterpret_cast<const char*>(head), sizeof head);
  f.write(reinterpret_cast<const char*>(&r.seconds), sizeof r.seconds);
  for (const std::vector<float>* v : {&r.mean.pixels, &r.variance.pixels})
    f.write(reinterpret_cast<const char*>(v->data()), v->size() * sizeof(float));
  f.write(reinterpret_cast<const char*>(r.instance.data()), r.instance.size() * sizeof(int));
  if (!f) throw std::runtime_error(path + ": cannot write");
}

Rendered load(const std::string& path) {
  std::ifstream f(path, std::ios::binary);
  int head[5];
  Rendered r;
  f.read(reinterpret_cast<char*>(head), sizeof head);
  f.read(reinterpret_cast<char*>(&r.seconds), sizeof r.seconds);
  r.sub.stride = head[0];
  r.sub.width = head[1];
  r.sub.height = head[2];
  r.spp = head[3];
  r.mean = rt::bench::blank(r.sub);
  r.variance = rt::bench::blank(r.sub);
  r.instance.resize(r.mean.size());
  for (std::vector<float>* v : {&r.mean.pixels, &r.variance.pixels})
    f.read(reinterpret_cast<char*>(v->data()), v->size() * sizeof(float));
  f.read(reinterpret_cast<char*>(r.instance.data()), r.instance.size() * sizeof(int));
  if (!f) throw std::runtime_error(path + ": cannot read a saved subset");
  return r;
}

// Linear figures over the pixels `use` selects.
struct Linear {
  size_t pixels = 0;
  double mine = 0, ref = 0, var_mean = 0;      // Mean luminances; variance of their difference.
  double mae = 0, expected_mae = 0, chi2 = 0;  // Per channel, over the pixels.
};

template <typename Use>
Linear linear(const ImageF& mine, const ImageF& var, const ImageF& ref, double n, double n_ref,
              Use use) {
  const double w[3] = {0.2126, 0.7152, 0.0722};
  Linear l;
  for (size_t i = 0; i < mine.size(); ++i) {
    if (!use(i)) continue;
    ++l.pixels;
    double sd_lum = 0;
    for (int k = 0; k < 3; ++k) {
      double d = mine.pixels[i * 3 + k] - ref.pixels[i * 3 + k];
      double v = var.pixels[i * 3 + k] * (1 / n + 1 / n_ref);
      l.mine += w[k] * mine.pixels[i * 3 + k];
      l.ref += w[k] * ref.pixels[i * 3 + k];
      l.mae += std::fabs(d);
      l.expected_mae += std::sqrt(2 * v / M_PI);
      l.chi2 += v > 0 ? d * d / v : 0;
      // The channels' noise is taken as fully correlated (a bound on the luminance's).
      sd_lum += w[k] * std::sqrt(v);
    }
    l.var_mean += sd_lum * sd_lum;
  }
  double p = static_cast<double>(std::max<size_t>(1, l.pixels));
  l.mine /= p;
  l.ref /= p;
  l.var_mean /= p * p;
  l.mae /= 3 * p;
  l.expected_mae /= 3 * p;
  l.chi2 /= 3 * p;
  return l;
}

void print_linear(const char* what, const Linear& l) {
  std::printf("| %s | %zu | %.4f | %.4f | %.4f ± %.4f | %.4f | %.4f | %.2f |\n", what, l.pixels,
              l.mine, l.ref, l.mine / l.ref, std::sqrt(l.var_mean) / l.ref, l.mae, l.expected_mae,
              l.chi2);
}

// Mean |difference| of horizontal neighbours inside the 4x4 blocks, per channel: the
// image's own noise (plus its detail), the same figure for both sides when their noise is
// alike.
double neighbour_mae(const ImageF& img) {
  double sum = 0;
  size_t count = 0;
  for (int y = 0; y < img.height; ++y)
    for (int x = 0; x + 1 < img.width; ++x) {
      if (x % 4 == 3) continue;
      for (int k = 0; k < 3; ++k) sum += std::fabs(img.at(x + 1, y, k) - img.at(x, y, k));
      count += 3;
    }
  return sum / std::max<size_t>(1, count);
}

int run(const std::string& scene_file, int camera, const std::string& ref_exr,
        const std::string& ref_png, const Options& o) {
  rt::SceneDesc scene = rt::load_scene(scene_file);
  if (camera < 0 || camera >= static_cast<int>(scene.cameras.size()))
    throw std::runtime_error(scene_file + ": no camera " + std::to_string(camera));
  rt::RenderOptions ro;
  ro.seed = o.seed;
  ro.spp = o.spp;
  rt::FlatScene flat = rt::prepare_scene(scene, ro);
  rt::prepare_camera(flat, scene, camera, ro);
  Rendered r;
  if (!o.load.empty()) {
    r = load(o.load);
  } else {
    r.sub = rt::bench::make_subset(flat.header.camera, o.budget);
    r.spp = flat.header.camera.samples;
    auto start = std::chrono::steady_clock::now();
    r.mean = rt::bench::render_subset(flat, r.sub, &r.variance, &r.instance);
    r.seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
    if (!o.save.empty()) save(o.save, r);
  }
  const rt::CameraDesc& desc = scene.cameras[camera];
  double n = r.spp, n_ref = o.ref_spp > 0 ? o.ref_spp : desc.samples;
  ImageF ref_full = rt::read_exr(ref_exr);
  ImageF ref = rt::bench::crop(ref_full, r.sub);
  std::printf(
      "%s camera %d: %d spp (reference %g), subset %dx%d pixels (%.2f %% of %dx%d: every "
      "%d-th 4x4 block each way), %.0f s\n\n",
      scene_file.c_str(), camera, r.spp, n_ref, r.sub.width, r.sub.height,
      100.0 / (r.sub.stride * r.sub.stride), ref_full.width, ref_full.height, r.sub.stride,
      r.seconds);

  std::printf(
      "| pixels | n | mean lum (ours) | mean lum (ref) | ratio ± se | MAE | "
      "expected MAE | chi2 |\n|---|---:|---:|---:|---:|---:|---:|---:|\n");
  print_linear("all", linear(r.mean, r.variance, ref, n, n_ref, [](size_t) { return true; }));
  // Pixels grouped by what their camera ray hits: the material and first texture (ids as
  // in the scene file), which name the objects of a scene like veach-ajar.
  std::vector<std::string> label(r.instance.size(), "no hit");
  for (size_t i = 0; i < r.instance.size(); ++i)
    if (r.instance[i] >= 0) {
      int texture = flat.instance_textures[r.instance[i]].ids[0];
      label[i] = "material " + std::to_string(flat.instances[r.instance[i]].material + 1) +
                 (texture >= 0 ? ", texture " + std::to_string(texture + 1) : "");
    }
  std::map<std::string, int> groups;
  for (const std::string& l : label) ++groups[l];
  for (const auto& [what, count] : groups)
    print_linear(what.c_str(), linear(r.mean, r.variance, ref, n, n_ref,
                                      [&](size_t i) { return label[i] == what; }));
  std::printf("\nbias z over %d blocks (their own spread): %+.2f\n",
              (r.sub.width / 4) * (r.sub.height / 4), rt::bench::block_bias_z(r.mean, ref));
  std::printf("neighbour MAE (noise plus detail): ours %.4f, reference %.4f (ratio %.3f)\n",
              neighbour_mae(r.mean), neighbour_mae(ref),
              neighbour_mae(r.mean) / neighbour_mae(ref));

  if (desc.tonemap && !ref_png.empty()) {
    const rt::PhotographicParams& tp = desc.tonemap_params;
    rt::PhotographicScale scale = rt::PhotographicStatistics(ref_full, tp);
    rt::Image8 ref8 = rt::bench::crop8(rt::read_png(ref_png), r.sub);
    rt::Image8 mine8 = rt::bench::encode(r.mean, scale, tp);
    double tm_check = rt::diff_images(rt::bench::encode(ref, scale, tp), ref8).mae;
    // Noise alone: our pixels against themselves plus the difference's Gaussian noise.
    std::mt19937 rng(1);
    std::normal_distribution<double> gauss;
    double floor = 0;
    const int draws = 8;
    for (int d = 0; d < draws; ++d) {
      ImageF noisy = r.mean;
      for (size_t i = 0; i < noisy.pixels.size(); ++i)
        noisy.pixels[i] = static_cast<float>(std::max(
            0.0,
            noisy.pixels[i] + gauss(rng) * std::sqrt(r.variance.pixels[i] * (1 / n + 1 / n_ref))));
      floor += rt::bench::block_mae(mine8, rt::bench::encode(noisy, scale, tp)) / draws;
    }
    std::printf(
        "tone mapped with the reference's statistics: block MAE %.3f, expected from "
        "noise %.3f (ratio %.2f); pixel MAE %.3f; tm check (reference EXR -> PNG) "
        "pixel MAE %.3f\n",
        rt::bench::block_mae(mine8, ref8), floor, rt::bench::block_mae(mine8, ref8) / floor,
        rt::diff_images(mine8, ref8).mae, tm_check);
  }
  return 0;
}

}  // namespace

int main(int argc, char** argv) {
  if (argc < 5) {
    std::fprintf(stderr,
                 "usage: subset_reference SCENE.xml CAMERA REF.exr REF.png [--budget SAMPLES] "
                 "[--seed N] [--spp N] [--ref-spp N] [--save FILE | --load FILE]\n");
    return 2;
  }
  Options o;
  for (int i = 5; i + 1 < argc; i += 2) {
    std::string k = argv[i], v = argv[i + 1];
    if (k == "--budget")
      o.budget = std::atof(v.c_str());
    else if (k == "--seed")
      o.seed = static_cast<uint32_t>(std::atol(v.c_str()));
    else if (k == "--spp")
      o.spp = std::atoi(v.c_str());
    else if (k == "--ref-spp")
      o.ref_spp = std::atoi(v.c_str());
    else if (k == "--save")
      o.save = v;
    else if (k == "--load")
      o.load = v;
    else {
      std::fprintf(stderr, "subset_reference: unknown option %s\n", k.c_str());
      return 2;
    }
  }
  try {
    return run(argv[1], std::atoi(argv[2]), argv[3], argv[4], o);
  } catch (const std::exception& e) {
    std::fprintf(stderr, "subset_reference: %s\n", e.what());
    return 1;
  }
}
