// compare: checks two renders against each other. This first version has `diff` (image
// metrics); the statistical subcommands build on per-pixel moment files.
#include <cstdio>
#include <cstdlib>
#include <string>

#include "image_metrics.h"

namespace {

const char* kUsage = R"(usage: compare diff A.png B.png [--threshold T] [--downsample K] [--out DIFF.png]

diff   Image metrics of B against A: mean absolute error (MAE), RMSE, PSNR, the
       fraction of pixels whose largest channel difference exceeds T (default 8),
       the largest difference, and the same after a K x K box downsample (default 4),
       which averages out sampling noise. --out writes |A - B| x 4 as a gray PNG.
       Exit status 0; 2 on bad usage or unreadable input.
)";

int diff(int argc, char** argv) {
  if (argc < 4) {
    std::fputs(kUsage, stderr);
    return 2;
  }
  int threshold = 8, k = 4;
  std::string out;
  for (int i = 4; i + 1 < argc; i += 2) {
    std::string o = argv[i];
    if (o == "--threshold") threshold = std::atoi(argv[i + 1]);
    else if (o == "--downsample") k = std::atoi(argv[i + 1]);
    else if (o == "--out") out = argv[i + 1];
    else {
      std::fprintf(stderr, "compare: unknown option '%s'\n", o.c_str());
      return 2;
    }
  }
  rt::Image8 a = rt::read_png(argv[2]), b = rt::read_png(argv[3]);
  rt::ImageDiff d = rt::diff_images(a, b, threshold);
  rt::ImageDiff dk = rt::diff_images(rt::downsample(a, k), rt::downsample(b, k), threshold);
  std::printf("mae %.4f rmse %.4f psnr %.2f over%d %.4f%% max %d identical %.2f%% | %dx%d: mae %.4f "
              "over%d %.4f%% max %d\n",
              d.mae, d.rmse, d.psnr, threshold, 100 * d.frac_over, d.max_abs,
              100 * d.frac_identical, k, k, dk.mae, threshold, 100 * dk.frac_over, dk.max_abs);
  if (!out.empty()) rt::write_png(out, rt::difference_image(a, b));
  return 0;
}

}  // namespace

int main(int argc, char** argv) {
  std::string cmd = argc > 1 ? argv[1] : "";
  try {
    if (cmd == "diff") return diff(argc, argv);
    if (cmd == "--help" || cmd == "-h") {
      std::fputs(kUsage, stdout);
      return 0;
    }
  } catch (const std::exception& e) {
    std::fprintf(stderr, "compare: error: %s\n", e.what());
    return 2;
  }
  std::fputs(kUsage, stderr);
  return 2;
}
