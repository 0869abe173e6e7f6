// Renders a course scene with the CPU reference and checks it against the course's
// official image. To keep the default suite fast it may render only a regular subset of
// pixels (or of 4x4 blocks): each metric over a regular subset estimates the same metric
// over the whole image, at full resolution and at the scene's own sample count.
//
// The criterion and its thresholds are compare/reference_criterion.h, which
// `compare reference` applies to an existing render.
//
// A camera with <Tonemap> writes radiance to an EXR and its PNG through the photographic
// operator, whose log-average and burn-out need the whole image: the subset's pixels are
// mapped with the statistics of the course's own EXR beside REFERENCE.png (which reproduces
// the course's PNG; tests/image/tonemap_test.cpp), so the check still estimates the full image.
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <fstream>
#include <string>
#include <thread>
#include <vector>

#include "app/cli.h"
#include "compare/image_metrics.h"
#include "compare/reference_criterion.h"
#include "device/cpu/cpu_kernel.h"
#include "image/read_hdr.h"
#include "image/tonemap.h"
#include "integrator/render.h"
#include "io/png_io.h"
#include "prepare/flat_scene.h"

namespace {

struct Args {
  cmp::ReferenceCriterion criterion;
  int camera = 0;
  double budget = 0;  // Samples to spend; 0: the whole image.
  rt::Quantize quantize = rt::Quantize::kTruncate;
  rt::RenderOptions render;
};

// Turns a pixel's mean radiance into 8 bits as the raytracer writes it.
struct PixelEncoder {
  rt::Quantize quantize = rt::Quantize::kRound;
  bool tonemap = false;
  rt::PhotographicParams params;
  rt::PhotographicScale scale;

  void encode(const float rgb[3], uint8_t out[3]) const {
    if (tonemap) {
      rt::TonemapPixel(rgb, scale, params, out);
      return;
    }
    rt::Image8 px = rt::to_8bit(1, 1, {rgb[0], rgb[1], rgb[2]}, quantize);
    for (int k = 0; k < 3; ++k) out[k] = px.rgb[k];
  }
};

rt::OptionTable<Args> make_table() {
  rt::OptionTable<Args> t(
      "reference_check", "reference_check SCENE.xml REFERENCE.png [options]",
      "Renders a course scene with the CPU reference (all of it, or a regular subset of\n"
      "pixels within --budget samples) and checks it against the course's official image.\n"
      "Exit status: 0 pass, 1 fail, 2 bad usage, 77 skipped (files missing).");
  t.section("Check")
      .choice("--criterion",
              std::vector<std::pair<std::string, std::string>>{
                  {"hw12", "hw12"}, {"hw3", "hw3"}, {"block", "block"}},
              RT_FIELD(criterion.kind), cmp::criterion_help())
      .real("--min-identical", "P", rt::Range::closed(0, 100), RT_FIELD(criterion.min_identical),
            "percent of pixels that must be byte-identical to the reference")
      .default_is(std::to_string(cmp::kHw12Identical).substr(0, 4) + " for hw12, none for hw3")
      .real("--double-min-identical", "P", rt::Range::closed(0, 100),
            RT_FIELD(criterion.double_min_identical),
            "percent of pixels that must be byte-identical when rendering in double "
            "(RT_TEST_PRECISION=double): the course renders in float, so double lands on "
            "the other side of more of its rounding decisions (tests/course/course_scenes.txt)")
      .default_is("--min-identical")
      .real("--max-bias", "B", rt::Range::closed(0, 255), RT_FIELD(criterion.max_bias),
            "largest |mean bias| (render minus reference) an hw3 image may have, in levels")
      .default_is(std::to_string(cmp::kHw3Bias).substr(0, 4))
      .real("--max-block-mae", "M", rt::Range::closed(0, 255), RT_FIELD(criterion.max_block_mae),
            "largest 4x4-downsampled MAE a `block` image may have, in levels")
      .default_is(std::to_string(cmp::kBlockDownMae).substr(0, 3))
      .real("--budget", "SAMPLES", rt::Range::positive(), RT_FIELD(budget),
            "render a regular subset of pixels (or of 4x4 blocks for hw3) costing about this "
            "many samples")
      .default_is("every pixel")
      .integer("--camera", "N", rt::Range::closed(0, 1 << 20), RT_FIELD(camera),
               "the camera to render")
      .choice("--quantize", rt::quantize_choices(), RT_FIELD(quantize),
              "radiance to 8 bits, as raytracer --quantize");
  t.include(rt::device_option_table(), RT_FIELD(render));
  return t;
}

// Renders the blocks (block x block pixels) whose block coordinates are multiples of
// `stride`, into a compact image of just those pixels.
rt::Image8 render_subset(const rt::FlatScene& flat, bool in_double, int block, int stride,
                         rt::Image8* ref_out, const rt::Image8& ref, const PixelEncoder& encoder) {
  const Camera& cam = flat.header.camera;
  int bx = cam.width / block, by = cam.height / block;
  int nx = (bx + stride - 1) / stride, ny = (by + stride - 1) / stride;
  rt::Image8 out;
  out.width = nx * block;
  out.height = ny * block;
  out.rgb.assign(static_cast<size_t>(out.width) * out.height * 3, 0);
  *ref_out = out;
  SceneData sd = flat.view();
  const rt::CpuPixelFunction accumulate =
      in_double ? rt::accumulate_pixel_double : rt::accumulate_pixel_float;
  std::vector<std::thread> pool;
  int threads = std::max(1u, std::thread::hardware_concurrency());
  for (int t = 0; t < threads; ++t)
    pool.emplace_back([&, t] {
      for (int row = t; row < out.height; row += threads) {
        int y = (row / block) * stride * block + row % block;
        for (int col = 0; col < out.width; ++col) {
          int x = (col / block) * stride * block + col % block;
          PixelAccum acc{};
          PrimaryInfo info;
          accumulate(&sd, x, y, 0, cam.samples, &acc, &info);
          const float rgb[3] = {acc.sum.x / acc.sum.w, acc.sum.y / acc.sum.w,
                                acc.sum.z / acc.sum.w};
          size_t o = (static_cast<size_t>(row) * out.width + col) * 3;
          size_t r = (static_cast<size_t>(y) * ref.width + x) * 3;
          encoder.encode(rgb, &out.rgb[o]);
          for (int k = 0; k < 3; ++k) ref_out->rgb[o + k] = ref.rgb[r + k];
        }
      }
    });
  for (auto& th : pool) th.join();
  return out;
}

}  // namespace

int main(int argc, char** argv) {
  const rt::OptionTable<Args> table = make_table();
  Args a;
  std::vector<std::string> files = table.parse_or_exit(argc, argv, &a);
  if (files.size() != 2) table.usage_error("needs SCENE.xml and REFERENCE.png");
  for (const std::string& f : files)
    if (!std::ifstream(f)) {
      std::printf("SKIP: %s is not present (the course's scenes live in ../shared/scenes)\n",
                  f.c_str());
      return 77;
    }
  try {
    rt::SceneDesc scene = rt::load_scene(files[0]);
    // RT_TEST_PRECISION=double reruns the reference tests in double (README: precision).
    const char* precision = std::getenv("RT_TEST_PRECISION");
    if (precision && std::strcmp(precision, "double") == 0)
      a.render.precision = rt::Precision::kDouble;
    // The CPU reference computes in double, so --precision auto is double here.
    std::string notice;
    a.render.precision = rt::resolve_precision(a.render.precision, true, "cpu-reference", &notice);
    const bool in_double = rt::kernel_config(a.render).double_precision;
    rt::FlatScene flat = rt::prepare_scene(scene, a.render);
    rt::prepare_camera(flat, scene, a.camera, a.render);
    rt::Image8 ref = rt::read_png(files[1]);
    const Camera& cam = flat.header.camera;
    if (ref.width != cam.width || ref.height != cam.height) {
      std::fprintf(stderr, "size mismatch: render %dx%d, reference %dx%d\n", cam.width, cam.height,
                   ref.width, ref.height);
      return 1;
    }
    bool hw3 = a.criterion.kind == "hw3", by_block = a.criterion.kind == "block";
    int block = hw3 || by_block ? 4 : 1;
    double total = static_cast<double>(cam.width) * cam.height * cam.samples;
    int stride =
        a.budget > 0 ? std::max(1, static_cast<int>(std::ceil(std::sqrt(total / a.budget)))) : 1;
    PixelEncoder encoder;
    encoder.quantize = a.quantize;
    const rt::CameraDesc& desc = scene.cameras[a.camera];
    if (desc.tonemap) {
      std::string exr = files[1].substr(0, files[1].find_last_of('.')) + ".exr";
      if (!std::ifstream(exr)) {
        std::printf("SKIP: %s: the camera tone maps, and %s is not present\n", files[0].c_str(),
                    exr.c_str());
        return 77;
      }
      encoder.tonemap = true;
      encoder.params = desc.tonemap_params;
      encoder.scale = rt::PhotographicStatistics(rt::read_exr(exr), desc.tonemap_params);
    }
    rt::Image8 ref_subset;
    rt::Image8 img = render_subset(flat, in_double, block, stride, &ref_subset, ref, encoder);
    cmp::ReferenceResult r =
        cmp::check_reference(img, ref_subset, a.criterion, in_double);
    char detail[160];
    std::snprintf(detail, sizeof detail, "%dx%d, %d spp, stride %d (%.1f %% of the pixels)",
                  cam.width, cam.height, cam.samples, stride, 100.0 / (stride * stride));
    cmp::print_reference_result(files[1], detail, r, a.criterion,
                                static_cast<long>(img.width) * img.height);
    return r.pass ? 0 : 1;
  } catch (const std::exception& e) {
    // Scenes whose large PLY files could not be fetched (see SOURCES.md) are skipped.
    if (std::string(e.what()).find("cannot open") != std::string::npos) {
      std::printf("SKIP: scene incomplete: %s\n", e.what());
      return 77;
    }
    std::fprintf(stderr, "reference_check: %s\n", e.what());
    return 1;
  }
}
