#include "commands.h"

#include <cstdio>
#include <cstdlib>
#include <map>
#include <stdexcept>
#include <string>
#include <vector>

#include "exact.h"
#include "image_metrics.h"
#include "inputs.h"
#include "maps.h"
#include "options.h"
#include "paired.h"
#include "welch.h"

namespace cmp {
namespace {

// Accepts a moment file or the PNG it was written beside.
rt::MomentImage load(const std::string& path) {
  std::string p = path;
  if (p.size() > 4 && p.compare(p.size() - 4, 4, ".png") == 0) p = rt::moments_path_for(p);
  return rt::read_moments(p);
}

// Both files, of the same size (one line naming both sizes otherwise).
void load_pair(const std::vector<std::string>& files, rt::MomentImage* a, rt::MomentImage* b) {
  *a = load(files[0]);
  *b = load(files[1]);
  require_same_size(files[0], a->width, a->height, files[1], b->width, b->height);
}

// Two renders with the same means and sample counts everywhere need no test: say so, pass.
bool report_identical(const rt::MomentImage& a, const rt::MomentImage& b) {
  if (a.mean != b.mean || a.count != b.count) return false;
  std::printf(
      "  identical: A and B hold the same mean radiance and sample count in every "
      "pixel; nothing to test\nverdict: PASS\n");
  return true;
}

void describe(const char* label, const std::string& path, const rt::MomentImage& m) {
  std::printf("  %s: %s (%dx%d, %d spp, seed %u, %s)\n", label, path.c_str(), m.width, m.height,
              m.info.spp, m.info.seed, m.info.device.c_str());
}

// Both inputs, and `note` when their seeds are equal (`note_if_equal`) or when they differ.
void describe_inputs(const std::vector<std::string>& files, const rt::MomentImage& a,
                     const rt::MomentImage& b, bool note_if_equal, const char* note) {
  describe("A", files[0], a);
  describe("B", files[1], b);
  if ((a.info.seed == b.info.seed) == note_if_equal) std::printf("  note: %s\n", note);
}

void write_family_maps(const CompareOptions& o, const char* prefix, const Family& f,
                       const Verdict& v) {
  if (o.out_dir.empty()) return;
  write_map(o.out_dir, prefix, "diff", difference_map(f, o.gain));
  write_map(o.out_dir, prefix, "pvalue", pvalue_map(f, v));
  write_map(o.out_dir, prefix, "mask", mask_map(f));
}

}  // namespace

// The verdict of a family of tests: figures, maps for a person, and the exit status.
int conclude(const CompareOptions& o, const char* name, Family& f) {
  Verdict v = decide(f, o.family);
  print_verdict(v, o.family, f);
  write_family_maps(o, name, f, v);
  return v.pass ? 0 : 1;
}

int run_welch(int argc, char** argv) {
  std::vector<std::string> files;
  CompareOptions o = parse_subcommand("welch", argc, argv, &files);
  rt::MomentImage ma, mb;
  load_pair(files, &ma, &mb);
  check_testable(ma, mb, o.allow_weighted);
  std::printf("welch: per-cell Welch t-test, H0: equal expected radiance in every cell\n");
  describe_inputs(files, ma, mb, true,
                  "equal seeds: the samples are correlated and this test loses power "
                  "(use `compare paired`)");
  if (report_identical(ma, mb)) return 0;
  // At unequal sample counts the renders' means are skewed unequally, and a heavy-tailed
  // estimator (a path tracer: most samples 0, a few carry the light) then gives plain
  // per-pixel Welch false alarms (tests/compare/path_compare_test.cpp: 16 against 256 spp of the
  // course's Cornell box, p = 8e-8); the larger of the two variances keeps the level.
  if (!o.welch.pooled && !o.unpooled && ma.info.spp != mb.info.spp) {
    o.welch.pooled = true;
    std::printf(
        "note: the sample counts differ (%d, %d spp): per-sample variances pooled "
        "(--unpooled to keep each render's own)\n",
        ma.info.spp, mb.info.spp);
  }
  Family f = welch_test(ma, mb, o.welch);
  return conclude(o, "welch", f);
}

int run_paired(int argc, char** argv) {
  std::vector<std::string> files;
  CompareOptions o = parse_subcommand("paired", argc, argv, &files);
  rt::MomentImage ma, mb;
  load_pair(files, &ma, &mb);
  check_testable(ma, mb, true);
  const PairedOptions& po = o.paired;
  std::printf("paired: sign tests of per-pixel differences, H0: differences symmetric about 0\n");
  describe_inputs(files, ma, mb, false,
                  "different seeds: still a valid test, but not the sensitive paired "
                  "one (render both with the same --seed)");
  if (report_identical(ma, mb)) return 0;
  PairedFigures pf = paired_figures(ma, mb, po);
  std::printf(
      "  pixel-channels beyond float resolution %zu of %zu (%.3f %%, %zu positive), "
      "largest |B - A| %.4g (%.3g standard errors)\n",
      pf.differing, pf.values, pf.values ? 100.0 * pf.differing / pf.values : 0.0, pf.positive,
      pf.max_abs, pf.max_z);
  Family f = paired_test(ma, mb, po);
  return conclude(o, "paired", f);
}

int run_exact(int argc, char** argv) {
  std::vector<std::string> files;
  CompareOptions o = parse_subcommand("exact", argc, argv, &files);
  rt::MomentImage ma, mb;
  load_pair(files, &ma, &mb);
  const ExactOptions& eo = o.exact;
  std::printf("exact: first-sample hits, H0: same ids, distances and normals within tolerance\n");
  describe_inputs(files, ma, mb, false,
                  "different seeds: first samples are different rays unless the "
                  "scene has 1 spp and no randomness in the camera");
  ExactReport r = exact_test(ma, mb, eo);
  std::printf("  pixels %zu (%zu hits in both), hit/miss mismatches %zu, id mismatches %zu\n",
              r.pixels, r.hits, r.hit_mismatch, r.id_mismatch);
  std::printf(
      "  distance over tolerance %zu (largest relative difference %.3g, tolerance "
      "%.3g), normal over tolerance %zu (largest component difference %.3g, tolerance "
      "%.3g)\n",
      r.t_over, r.max_t_rel, eo.t_tol, r.n_over, r.max_n, eo.n_tol);
  std::printf("  failing pixels %zu (%.4f %%; allowed %.4f %%)\n", r.failing,
              r.pixels ? 100.0 * r.failing / r.pixels : 0.0, 100 * eo.max_fraction);
  std::printf("verdict: %s\n", r.pass ? "PASS" : "FAIL");
  if (!o.out_dir.empty()) {
    const std::string& dir = o.out_dir;
    // Relative distance difference, full white at the tolerance (and on any mismatch).
    write_map(dir, "exact", "diff", gray_map(ma.width, ma.height, r.t_rel, 255.0 / eo.t_tol));
    write_map(dir, "exact", "mask", mask_map(ma.width, ma.height, r.fail));
  }
  return r.pass ? 0 : 1;
}

int run_diff(int argc, char** argv) {
  std::vector<std::string> files;
  CompareOptions o = parse_subcommand("diff", argc, argv, &files);
  int threshold = o.threshold, k = o.downsample;
  rt::Image8 ia = rt::read_png(files[0]), ib = rt::read_png(files[1]);
  require_same_size(files[0], ia.width, ia.height, files[1], ib.width, ib.height);
  rt::ImageDiff d = rt::diff_images(ia, ib, threshold);
  rt::ImageDiff dk = rt::diff_images(rt::downsample(ia, k), rt::downsample(ib, k), threshold);
  std::printf(
      "mae %.4f rmse %.4f psnr %.2f over%d %.4f%% max %d identical %.2f%% | %dx%d: mae "
      "%.4f rmse %.4f psnr %.2f over%d %.4f%% max %d\n",
      d.mae, d.rmse, d.psnr, threshold, 100 * d.frac_over, d.max_abs, 100 * d.frac_identical, k, k,
      dk.mae, dk.rmse, dk.psnr, threshold, 100 * dk.frac_over, dk.max_abs);
  if (!o.out.empty()) rt::write_png(o.out, rt::difference_image(ia, ib));
  const std::string& dir = o.out_dir;
  int status = 0;
  if (!o.moments.empty()) {
    rt::MomentImage mb = rt::read_moments(o.moments);
    require_same_size(files[0], ia.width, ia.height, o.moments, mb.width, mb.height);
    const WelchOptions& wo = o.welch;
    const FamilyOptions& fo = o.family;
    std::printf(
        "diff --moments: Welch test of B's moments against the 8-bit A, H0: A is B's "
        "expected image, rounded\n");
    std::printf("  moments of B: %s (%d spp, seed %u, %s)\n", o.moments.c_str(), mb.info.spp,
                mb.info.seed, mb.info.device.c_str());
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
