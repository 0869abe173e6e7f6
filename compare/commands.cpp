#include "commands.h"

#include <cstdio>
#include <cstdlib>
#include <map>
#include <stdexcept>
#include <string>
#include <vector>

#include "exact.h"
#include "image_metrics.h"
#include "maps.h"
#include "paired.h"
#include "welch.h"

namespace cmp {
namespace {

// Bad usage: reported by main() with exit status 2.
struct UsageError : std::runtime_error {
  using std::runtime_error::runtime_error;
};

// "--name value" options and "--flag" switches after the positional arguments.
struct Args {
  std::vector<std::string> positional;
  std::map<std::string, std::string> values;

  Args(int argc, char** argv, const std::vector<std::string>& flags,
       const std::vector<std::string>& valued) {
    for (int i = 2; i < argc; ++i) {
      std::string a = argv[i];
      auto in = [&](const std::vector<std::string>& v) {
        for (const auto& s : v)
          if (s == a) return true;
        return false;
      };
      if (in(flags)) {
        values[a] = "1";
      } else if (in(valued)) {
        if (i + 1 >= argc) throw UsageError(a + " needs a value");
        values[a] = argv[++i];
      } else if (a.size() > 1 && a[0] == '-') {
        throw UsageError("unknown option '" + a + "' for " + argv[1]);
      } else {
        positional.push_back(a);
      }
    }
  }
  bool has(const std::string& k) const { return values.count(k) > 0; }
  std::string str(const std::string& k, const std::string& def = "") const {
    return has(k) ? values.at(k) : def;
  }
  double num(const std::string& k, double def, double lo, double hi) const {
    if (!has(k)) return def;
    char* end = nullptr;
    double v = std::strtod(values.at(k).c_str(), &end);
    if (*end || !(v >= lo && v <= hi))
      throw UsageError(k + ": '" + values.at(k) + "' is not a number in [" +
                       std::to_string(lo) + ", " + std::to_string(hi) + "]");
    return v;
  }
};

const std::vector<std::string> kFamilyFlags = {"--bh", "--no-uniformity", "--allow-weighted",
                                               "--pooled"};
const std::vector<std::string> kFamilyValues = {"--alpha", "--tile", "--rel-tol", "--abs-tol",
                                                "--out-dir", "--gain"};

std::vector<std::string> join(std::vector<std::string> a, const std::vector<std::string>& b) {
  a.insert(a.end(), b.begin(), b.end());
  return a;
}

// Accepts a moment file or the PNG it was written beside.
rt::MomentImage load(const std::string& path) {
  std::string p = path;
  if (p.size() > 4 && p.compare(p.size() - 4, 4, ".png") == 0) p = rt::moments_path_for(p);
  return rt::read_moments(p);
}

void describe(const char* label, const std::string& path, const rt::MomentImage& m) {
  std::printf("  %s: %s (%dx%d, %d spp, seed %u, %s)\n", label, path.c_str(), m.width, m.height,
              m.info.spp, m.info.seed, m.info.device.c_str());
}

FamilyOptions family_options(const Args& a) {
  FamilyOptions o;
  o.alpha = a.num("--alpha", 0.01, 1e-12, 0.5);
  o.bh = a.has("--bh");
  o.uniformity = !a.has("--no-uniformity");
  return o;
}

void write_family_maps(const Args& a, const char* prefix, const Family& f, const Verdict& v) {
  if (!a.has("--out-dir")) return;
  std::string dir = a.str("--out-dir");
  write_map(dir, prefix, "diff", difference_map(f, a.num("--gain", 4, 0, 1e6)));
  write_map(dir, prefix, "pvalue", pvalue_map(f, v));
  write_map(dir, prefix, "mask", mask_map(f));
}

void need_two(const Args& a, const char* what) {
  if (a.positional.size() != 2) throw UsageError(std::string(what) + " takes two files");
}

}  // namespace

// The verdict of a family of tests: figures, maps for a person, and the exit status.
int conclude(const Args& a, const char* name, Family& f, const FamilyOptions& fo) {
  Verdict v = decide(f, fo);
  print_verdict(v, fo, f);
  write_family_maps(a, name, f, v);
  return v.pass ? 0 : 1;
}

int run_welch(int argc, char** argv) {
  Args a(argc, argv, kFamilyFlags, kFamilyValues);
  need_two(a, "welch");
  rt::MomentImage ma = load(a.positional[0]), mb = load(a.positional[1]);
  check_testable(ma, mb, a.has("--allow-weighted"));
  WelchOptions wo;
  wo.tile = static_cast<int>(a.num("--tile", 1, 1, 1 << 16));
  wo.pooled = a.has("--pooled");
  wo.rel_tol = a.num("--rel-tol", wo.rel_tol, 0, 1);
  wo.abs_tol = a.num("--abs-tol", wo.abs_tol, 0, 1e6);
  FamilyOptions fo = family_options(a);
  std::printf("welch: per-cell Welch t-test, H0: equal expected radiance in every cell\n");
  describe("A", a.positional[0], ma);
  describe("B", a.positional[1], mb);
  if (ma.info.seed == mb.info.seed)
    std::printf("  note: equal seeds: the samples are correlated and this test loses power "
                "(use `compare paired`)\n");
  Family f = welch_test(ma, mb, wo);
  return conclude(a, "welch", f, fo);
}

int run_paired(int argc, char** argv) {
  Args a(argc, argv, kFamilyFlags, kFamilyValues);
  need_two(a, "paired");
  rt::MomentImage ma = load(a.positional[0]), mb = load(a.positional[1]);
  check_testable(ma, mb, true);
  PairedOptions po;
  po.tile = static_cast<int>(a.num("--tile", po.tile, 2, 1 << 16));
  po.rel_tol = a.num("--rel-tol", po.rel_tol, 0, 1);
  po.abs_tol = a.num("--abs-tol", po.abs_tol, 0, 1e6);
  FamilyOptions fo = family_options(a);
  std::printf("paired: sign tests of per-pixel differences, H0: differences symmetric about 0\n");
  describe("A", a.positional[0], ma);
  describe("B", a.positional[1], mb);
  if (ma.info.seed != mb.info.seed)
    std::printf("  note: different seeds: still a valid test, but not the sensitive paired "
                "one (render both with the same --seed)\n");
  PairedFigures pf = paired_figures(ma, mb, po);
  std::printf("  pixel-channels beyond float resolution %zu of %zu (%.3f %%, %zu positive), "
              "largest |B - A| %.4g (%.3g standard errors)\n",
              pf.differing, pf.values, pf.values ? 100.0 * pf.differing / pf.values : 0.0,
              pf.positive, pf.max_abs, pf.max_z);
  Family f = paired_test(ma, mb, po);
  return conclude(a, "paired", f, fo);
}

int run_exact(int argc, char** argv) {
  Args a(argc, argv, {}, {"--t-tol", "--n-tol", "--max-fraction", "--out-dir"});
  need_two(a, "exact");
  rt::MomentImage ma = load(a.positional[0]), mb = load(a.positional[1]);
  ExactOptions eo;
  eo.t_tol = a.num("--t-tol", eo.t_tol, 0, 1);
  eo.n_tol = a.num("--n-tol", eo.n_tol, 0, 2);
  eo.max_fraction = a.num("--max-fraction", 0, 0, 1);
  std::printf("exact: first-sample hits, H0: same ids, distances and normals within tolerance\n");
  describe("A", a.positional[0], ma);
  describe("B", a.positional[1], mb);
  if (ma.info.seed != mb.info.seed)
    std::printf("  note: different seeds: first samples are different rays unless the "
                "scene has 1 spp and no randomness in the camera\n");
  ExactReport r = exact_test(ma, mb, eo);
  std::printf("  pixels %zu (%zu hits in both), hit/miss mismatches %zu, id mismatches %zu\n",
              r.pixels, r.hits, r.hit_mismatch, r.id_mismatch);
  std::printf("  distance over tolerance %zu (largest relative difference %.3g, tolerance "
              "%.3g), normal over tolerance %zu (largest component difference %.3g, tolerance "
              "%.3g)\n",
              r.t_over, r.max_t_rel, eo.t_tol, r.n_over, r.max_n, eo.n_tol);
  std::printf("  failing pixels %zu (%.4f %%; allowed %.4f %%)\n", r.failing,
              r.pixels ? 100.0 * r.failing / r.pixels : 0.0, 100 * eo.max_fraction);
  std::printf("verdict: %s\n", r.pass ? "PASS" : "FAIL");
  if (a.has("--out-dir")) {
    std::string dir = a.str("--out-dir");
    // Relative distance difference, full white at the tolerance (and on any mismatch).
    write_map(dir, "exact", "diff", gray_map(ma.width, ma.height, r.t_rel, 255.0 / eo.t_tol));
    write_map(dir, "exact", "mask", mask_map(ma.width, ma.height, r.fail));
  }
  return r.pass ? 0 : 1;
}

int run_diff(int argc, char** argv) {
  Args a(argc, argv, join(kFamilyFlags, {}),
         join(kFamilyValues, {"--threshold", "--downsample", "--out", "--moments"}));
  need_two(a, "diff");
  int threshold = static_cast<int>(a.num("--threshold", 8, 0, 255));
  int k = static_cast<int>(a.num("--downsample", 4, 1, 1 << 16));
  rt::Image8 ia = rt::read_png(a.positional[0]), ib = rt::read_png(a.positional[1]);
  rt::ImageDiff d = rt::diff_images(ia, ib, threshold);
  rt::ImageDiff dk = rt::diff_images(rt::downsample(ia, k), rt::downsample(ib, k), threshold);
  std::printf("mae %.4f rmse %.4f psnr %.2f over%d %.4f%% max %d identical %.2f%% | %dx%d: mae "
              "%.4f rmse %.4f psnr %.2f over%d %.4f%% max %d\n",
              d.mae, d.rmse, d.psnr, threshold, 100 * d.frac_over, d.max_abs,
              100 * d.frac_identical, k, k, dk.mae, dk.rmse, dk.psnr, threshold,
              100 * dk.frac_over, dk.max_abs);
  if (a.has("--out")) rt::write_png(a.str("--out"), rt::difference_image(ia, ib));
  std::string dir = a.str("--out-dir");
  int status = 0;
  if (a.has("--moments")) {
    rt::MomentImage mb = rt::read_moments(a.str("--moments"));
    WelchOptions wo;
    wo.tile = static_cast<int>(a.num("--tile", 1, 1, 1 << 16));
    wo.rel_tol = a.num("--rel-tol", wo.rel_tol, 0, 1);
    wo.abs_tol = a.num("--abs-tol", wo.abs_tol, 0, 1e6);
    FamilyOptions fo = family_options(a);
    std::printf("diff --moments: Welch test of B's moments against the 8-bit A, H0: A is B's "
                "expected image, rounded\n");
    std::printf("  moments of B: %s (%d spp, seed %u, %s)\n", a.str("--moments").c_str(),
                mb.info.spp, mb.info.seed, mb.info.device.c_str());
    Family f = welch_vs_image(ia, mb, wo);
    Verdict v = decide(f, fo);
    print_verdict(v, fo, f);
    if (!dir.empty()) {
      write_map(dir, "diff", "pvalue", pvalue_map(f, v));
      write_map(dir, "diff", "mask", mask_map(f));
    }
    status = v.pass ? 0 : 1;
  } else if (!dir.empty()) {
    std::vector<uint8_t> over(static_cast<size_t>(ia.width) * ia.height, 0);
    for (size_t i = 0; i < over.size(); ++i)
      for (int c = 0; c < 3; ++c)
        over[i] |= std::abs(ia.rgb[i * 3 + c] - ib.rgb[i * 3 + c]) > threshold;
    write_map(dir, "diff", "mask", mask_map(ia.width, ia.height, over));
  }
  if (!dir.empty()) write_map(dir, "diff", "diff", rt::difference_image(ia, ib));
  return status;
}

}  // namespace cmp
