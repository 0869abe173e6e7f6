// The figures bench/cycles_anchor.sh prints, from linear EXR images (ours and Cycles'):
//
//   cycles_metrics error REF.exr IMG.exr [--trim SHARE]
//     "relmse R trimmed T": the mean over pixels and R, G, B of (x - r)^2 / (r^2 + 1e-2),
//     and the same without the largest SHARE of those terms (default 0.001, the 0.1 %
//     worst values), which a few fireflies would otherwise decide.
//   cycles_metrics agree A.exr B.exr [--block K]
//     "ratio M r g b": mean of B / mean of A, over all channels and per channel;
//     "block_rms E scaled S blocks N": the root mean square over K x K blocks (default 8)
//     and channels of mean_B / mean_A - 1, and the same after dividing B by M (the shape
//     of the difference once the overall scale is taken out); blocks whose mean in A is
//     below 1e-3 are left out (N: the blocks counted).
//
// Exit status 0, 1 for unreadable or mismatched images, 2 for bad usage.
#include <algorithm>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <exception>
#include <functional>
#include <string>
#include <vector>

#include "image/read_hdr.h"

namespace {

constexpr double kFloor = 1e-2;  // f^2 of (x - r)^2 / (r^2 + f^2): dark pixels weigh less.

int Usage() {
  std::fprintf(stderr,
               "usage: cycles_metrics error REF.exr IMG.exr [--trim SHARE]\n"
               "       cycles_metrics agree A.exr B.exr [--block K]\n");
  return 2;
}

double Channel(const rt::ImageF& im, size_t pixel, int c) {
  return im.pixels[pixel * im.channels + c];
}

int Error(const rt::ImageF& ref, const rt::ImageF& img, double trim) {
  std::vector<double> terms;
  terms.reserve(ref.size() * 3);
  for (size_t p = 0; p < ref.size(); ++p)
    for (int c = 0; c < 3; ++c) {
      const double r = Channel(ref, p, c), x = Channel(img, p, c);
      const double d = std::isfinite(x) ? x - r : 1e30;
      terms.push_back(d * d / (r * r + kFloor));
    }
  double sum = 0;
  for (double t : terms) sum += t;
  const size_t keep = terms.size() - static_cast<size_t>(trim * terms.size());
  std::nth_element(terms.begin(), terms.begin() + keep, terms.end());
  double kept = 0;
  for (size_t i = 0; i < keep; ++i) kept += terms[i];
  std::printf("relmse %.6g trimmed %.6g\n", sum / terms.size(), kept / keep);
  return 0;
}

int Agree(const rt::ImageF& a, const rt::ImageF& b, int block) {
  double sa[3] = {0, 0, 0}, sb[3] = {0, 0, 0};
  for (size_t p = 0; p < a.size(); ++p)
    for (int c = 0; c < 3; ++c) {
      sa[c] += Channel(a, p, c);
      sb[c] += Channel(b, p, c);
    }
  const double ratio = (sb[0] + sb[1] + sb[2]) / (sa[0] + sa[1] + sa[2]);
  std::printf("ratio %.5f %.5f %.5f %.5f\n", ratio, sb[0] / sa[0], sb[1] / sa[1], sb[2] / sa[2]);
  double e2 = 0, s2 = 0;
  long n = 0;
  for (int by = 0; by + block <= a.height; by += block)
    for (int bx = 0; bx + block <= a.width; bx += block)
      for (int c = 0; c < 3; ++c) {
        double ma = 0, mb = 0;
        for (int y = by; y < by + block; ++y)
          for (int x = bx; x < bx + block; ++x) {
            ma += a.at(x, y, c);
            mb += b.at(x, y, c);
          }
        ma /= block * block;
        mb /= block * block;
        if (!(ma >= 1e-3)) continue;
        e2 += (mb / ma - 1) * (mb / ma - 1);
        s2 += (mb / (ma * ratio) - 1) * (mb / (ma * ratio) - 1);
        ++n;
      }
  if (n == 0) {
    std::fprintf(stderr, "cycles_metrics: no block of A is brighter than 1e-3\n");
    return 1;
  }
  std::printf("block_rms %.5f scaled %.5f blocks %ld\n", std::sqrt(e2 / n), std::sqrt(s2 / n), n);
  return 0;
}

}  // namespace

int main(int argc, char** argv) {
  if (argc != 4 && argc != 6) return Usage();
  const std::string cmd = argv[1];
  double trim = 0.001;
  int block = 8;
  if (argc == 6) {
    const std::string opt = argv[4];
    char* end = nullptr;
    const double v = std::strtod(argv[5], &end);
    if (*end != '\0') return Usage();
    if (cmd == "error" && opt == "--trim" && v >= 0 && v < 1) {
      trim = v;
    } else if (cmd == "agree" && opt == "--block" && v >= 1 && v <= 256 && v == std::floor(v)) {
      block = static_cast<int>(v);
    } else {
      return Usage();
    }
  }
  if (cmd != "error" && cmd != "agree") return Usage();
  try {
    const rt::ImageF a = rt::read_exr(argv[2]);
    const rt::ImageF b = rt::read_exr(argv[3]);
    if (a.width != b.width || a.height != b.height || a.channels < 3 || b.channels < 3) {
      std::fprintf(stderr, "cycles_metrics: %s is %dx%d, %s is %dx%d (both RGB needed)\n", argv[2],
                   a.width, a.height, argv[3], b.width, b.height);
      return 1;
    }
    return cmd == "error" ? Error(a, b, trim) : Agree(a, b, block);
  } catch (const std::exception& e) {
    std::fprintf(stderr, "cycles_metrics: %s\n", e.what());
    return 1;
  }
}
