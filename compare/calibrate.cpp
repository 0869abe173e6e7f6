// compare_calibrate: measures how trustworthy `compare`'s verdicts are on a real scene.
// It renders the scene with the CPU reference N times with fresh seeds and runs the tests
// on pairs: A against an unbiased B (how often a correct render is failed: the false-alarm
// rate) and A against B with a planted bias (how often the bias is caught). Renders stay in
// memory; the statistics are exactly those of the `compare` executable.
//
// usage: compare_calibrate SCENE.xml [options]; its options: compare_calibrate --help.
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <sstream>
#include <string>
#include <vector>

#include "family.h"
#include "prepare/flat_scene.h"
#include "io/moments.h"
#include "paired.h"
#include "planted_bias.h"
#include "device/cpu/cpu_device.h"
#include "integrator/render_scheduler.h"
#include "util/args.h"
#include "welch.h"

namespace {

struct Config {
  std::string scene;
  int camera = 0, spp = 0, trials = 100, threads = 0, paired_tile = 8;
  double scale = 0.1, false_alarm_risk = 0;
  std::vector<double> alphas = {0.01};
  std::vector<int> tiles = {1, 8};
  std::vector<std::string> biases = {"light:1.02", "roughness:1.1", "shift:1"};
  std::vector<std::string> expects;
};

rt::OptionTable<Config> make_table() {
  using rt::Range;
  rt::OptionTable<Config> t(
      "compare_calibrate", "compare_calibrate SCENE.xml [options]",
      "Renders SCENE with the CPU reference --trials times with fresh seeds and prints how\n"
      "often compare's tests fail an unbiased render (false alarms) and catch planted\n"
      "biases. Exit status: 0 every assertion held, 1 one failed, 2 bad usage or input.");
  auto number = [](Range r) {
    return [r](const std::string& s) { return rt::parse_number(s, r); };
  };
  auto whole = [](Range r) {
    return [r](const std::string& s) { return static_cast<int>(rt::parse_whole(s, r)); };
  };
  auto word = [](const std::string& s) { return s; };
  t.section("Renders")
      .integer("--camera", "N", Range::closed(0, 1 << 20), RT_FIELD(camera), "the camera")
      .real("--scale", "F", Range::left_open(0, 16), RT_FIELD(scale), "resolution scale")
      .integer("--spp", "N", Range::closed(0, 1 << 20), RT_FIELD(spp),
               "samples per pixel; 0: the scene's NumSamples")
      .integer("--trials", "N", Range::closed(1, 1 << 20), RT_FIELD(trials),
               "renders of A (and of each B)")
      .integer("--threads", "N", Range::closed(0, 4096), RT_FIELD(threads),
               "CPU threads; 0: all cores")
      .list("--biases", "SPEC[,SPEC...]", RT_FIELD(biases), word,
            "planted biases: light:F, roughness:F or shift:P (see planted_bias.h)");
  t.section("Tests")
      .list("--alpha", "A[,A...]", RT_FIELD(alphas), number(Range::open(0, 1)),
            "significance levels of the verdicts")
      .list("--tiles", "K[,K...]", RT_FIELD(tiles), whole(Range::closed(1, 1 << 16)),
            "Welch tile sizes")
      .integer("--paired-tile", "K", Range::closed(2, 1 << 16), RT_FIELD(paired_tile),
               "tile size of the paired sign tests");
  t.section("Assertions")
      .real("--false-alarm-risk", "R", Range::closed(0, 1), RT_FIELD(false_alarm_risk),
            "fail when an A-vs-A row has so many false alarms that a test at its nominal "
            "level would show as many with probability <= R; 0: no check")
      .list("--expect", "METHOD:TILE:KIND:AMOUNT:RATE", RT_FIELD(expects), word,
            "fail when that row's detection rate (at the first alpha) is below RATE, e.g. "
            "paired:8:light:1.02:0.99; METHOD: welch, welch-bh, paired (repeatable)",
            true);
  return t;
}

Config parse(int argc, char** argv) {
  static const rt::OptionTable<Config> table = make_table();
  Config c;
  std::vector<std::string> scenes = table.parse_or_exit(argc, argv, &c);
  if (scenes.size() != 1) table.usage_error("needs one SCENE.xml");
  c.scene = scenes[0];
  return c;
}

// A scene variant flattened once; each render only changes the seed.
struct Variant {
  cmp::PlantedBias bias;
  rt::FlatScene flat;
};

rt::MomentImage render(Variant& v, uint32_t seed, int threads) {
  v.flat.header.seed = seed;
  rt::Progress quiet(false, "", 0);
  rt::CpuDevice cpu(threads);
  rt::RenderResult r = rt::render_camera(cpu, v.flat, rt::KernelConfig(), quiet);
  rt::MomentInfo info;
  info.seed = seed;
  info.spp = v.flat.header.camera.samples;
  info.device = "cpu-reference";
  return rt::moments_from_render(r, info);
}

// One row of the table: a test method on one bias, counted at every alpha.
struct Row {
  std::string method;
  int tile = 1;
  size_t bias = 0;  // index into the variants; 0 is unbiased
  std::vector<long> rejected, by_cells, by_uniformity;
  // Pooled over every single test of every trial: how many had p below 0.05, 0.01, 0.001.
  long tests = 0, below[3] = {0, 0, 0};
};

cmp::Family family_for(const Row& row, const rt::MomentImage& a, const rt::MomentImage& b) {
  if (row.method == "paired") {
    cmp::PairedOptions po;
    po.tile = row.tile;
    return cmp::paired_test(a, b, po);
  }
  cmp::WelchOptions wo;
  wo.tile = row.tile;
  return cmp::welch_test(a, b, wo);
}

// The smallest k with P(Binomial(n, alpha) >= k) <= risk: that many false alarms would be
// a sign that the test runs above its nominal level.
long alarm_limit(long n, double alpha, double risk) {
  for (long k = 0; k <= n; ++k)
    if (cmp::binomial_upper_tail(k, n, alpha) <= risk) return k;
  return n + 1;
}

}  // namespace

int main(int argc, char** argv) {
  Config cfg = parse(argc, argv);
  std::vector<Variant> variants;
  rt::RenderOptions ro;
  ro.spp = cfg.spp;
  int width = 0, height = 0, spp = 0;
  try {
    rt::SceneDesc base = rt::load_scene(cfg.scene);
    rt::CameraDesc& cam = base.cameras.at(cfg.camera);
    cam.width = std::max(1, static_cast<int>(std::lround(cam.width * cfg.scale)));
    cam.height = std::max(1, static_cast<int>(std::lround(cam.height * cfg.scale)));
    std::vector<std::string> specs = {"none"};
    specs.insert(specs.end(), cfg.biases.begin(), cfg.biases.end());
    for (const std::string& spec : specs) {
      Variant v;
      v.bias = cmp::PlantedBias::parse(spec);
      rt::SceneDesc s = base;
      cmp::apply_bias(v.bias, cfg.camera, &s);
      v.flat = rt::prepare_scene(s, ro);
      rt::prepare_camera(v.flat, s, cfg.camera, ro);
      variants.push_back(std::move(v));
    }
    width = cam.width;
    height = cam.height;
    spp = variants[0].flat.header.camera.samples;
  } catch (const std::exception& e) {
    std::fprintf(stderr, "compare_calibrate: %s\n", e.what());
    return 2;
  }

  std::vector<Row> rows;
  for (size_t b = 0; b < variants.size(); ++b) {
    for (int t : cfg.tiles) rows.push_back({"welch", t, b, {}, {}, {}});
    rows.push_back({"welch-bh", 1, b, {}, {}, {}});
    rows.push_back({"paired", cfg.paired_tile, b, {}, {}, {}});
  }
  for (Row& r : rows) {
    r.rejected.assign(cfg.alphas.size(), 0);
    r.by_cells.assign(cfg.alphas.size(), 0);
    r.by_uniformity.assign(cfg.alphas.size(), 0);
  }

  for (int trial = 0; trial < cfg.trials; ++trial) {
    // Seeds 2i and 2i + 1: A and the independent B; paired rows reuse A's seed for B.
    uint32_t sa = 2u * trial, sb = sa + 1;
    rt::MomentImage a = render(variants[0], sa, cfg.threads);
    std::vector<rt::MomentImage> indep, same;
    for (size_t b = 0; b < variants.size(); ++b) {
      indep.push_back(render(variants[b], sb, cfg.threads));
      same.push_back(b == 0 ? rt::MomentImage{} : render(variants[b], sa, cfg.threads));
    }
    for (Row& row : rows) {
      // Unbiased paired rows use independent seeds: equal seeds would give identical images.
      bool paired_same = row.method == "paired" && row.bias != 0;
      cmp::Family f = family_for(row, a, paired_same ? same[row.bias] : indep[row.bias]);
      for (const cmp::Cell& cell : f.cells)
        for (int c = 0; c < 3; ++c) {
          if (cell.status[c] != cmp::CellStatus::kTested) continue;
          ++row.tests;
          row.below[0] += cell.p[c] < 0.05;
          row.below[1] += cell.p[c] < 0.01;
          row.below[2] += cell.p[c] < 0.001;
        }
      for (size_t k = 0; k < cfg.alphas.size(); ++k) {
        cmp::FamilyOptions fo;
        fo.alpha = cfg.alphas[k];
        fo.bh = row.method == "welch-bh";
        cmp::Verdict v = cmp::decide(f, fo);
        row.rejected[k] += !v.pass;
        row.by_cells[k] += v.rejections > 0 || v.deterministic > 0;
        row.by_uniformity[k] += v.uniform_rejected;
      }
    }
    if ((trial + 1) % 10 == 0) std::fprintf(stderr, "  %d/%d trials\n", trial + 1, cfg.trials);
  }

  std::printf(
      "calibration: %s camera %d at %dx%d, %d spp, %d trials (CPU reference; seeds "
      "2i vs 2i+1, paired biased rows 2i vs 2i)\n",
      cfg.scene.c_str(), cfg.camera, width, height, spp, cfg.trials);
  std::printf("%-9s %4s %-16s %6s %9s %7s %-17s %6s %6s\n", "test", "tile", "bias", "alpha",
              "failed/N", "rate", "95% CI", "cells", "unif");
  int failures = 0;
  for (const Row& row : rows)
    for (size_t k = 0; k < cfg.alphas.size(); ++k) {
      double lo, hi, rate = static_cast<double>(row.rejected[k]) / cfg.trials;
      cmp::clopper_pearson(row.rejected[k], cfg.trials, 0.95, &lo, &hi);
      std::string flag;
      if (row.bias == 0 && cfg.false_alarm_risk > 0) {
        long limit = alarm_limit(cfg.trials, cfg.alphas[k], cfg.false_alarm_risk);
        if (row.rejected[k] >= limit) {
          flag = "  FALSE-ALARM RATE ABOVE NOMINAL (limit " + std::to_string(limit) + ")";
          ++failures;
        }
      }
      for (const std::string& e : cfg.expects) {
        // METHOD:TILE:BIAS:RATE, BIAS as given to --biases (e.g. light:1.02).
        std::vector<std::string> p;
        std::stringstream ss(e);
        for (std::string item; std::getline(ss, item, ':');) p.push_back(item);
        if (p.size() != 5 || row.bias == 0) continue;
        cmp::PlantedBias want = cmp::PlantedBias::parse(p[2] + ":" + p[3]);
        const cmp::PlantedBias& have = variants[row.bias].bias;
        if (p[0] == row.method && std::atoi(p[1].c_str()) == row.tile && want.kind == have.kind &&
            want.amount == have.amount && k == 0 && rate < std::atof(p[4].c_str())) {
          flag = "  DETECTION BELOW " + p[4];
          ++failures;
        }
      }
      char ci[40];
      std::snprintf(ci, sizeof ci, "[%.3f, %.3f]", lo, hi);
      std::printf("%-9s %4d %-16s %6.3g %4ld/%-4d %7.4f %-17s %6ld %6ld%s\n", row.method.c_str(),
                  row.tile, variants[row.bias].bias.label().c_str(), cfg.alphas[k], row.rejected[k],
                  cfg.trials, rate, ci, row.by_cells[k], row.by_uniformity[k], flag.c_str());
    }
  std::printf("per-test calibration under H0 (A vs A, pooled over trials): share of p below\n");
  for (const Row& row : rows)
    if (row.bias == 0 && row.tests > 0)
      std::printf("  %-9s tile %2d: %ld tests, p<0.05 %.4f, p<0.01 %.4f, p<0.001 %.5f\n",
                  row.method.c_str(), row.tile, row.tests, row.below[0] / double(row.tests),
                  row.below[1] / double(row.tests), row.below[2] / double(row.tests));
  std::printf(
      "columns: cells = verdicts failed by a cell test or a deterministic failure, "
      "unif = by the uniformity check\n");
  std::printf("%s: %d assertion(s) failed\n", failures ? "FAIL" : "PASS", failures);
  return failures ? 1 : 0;
}
