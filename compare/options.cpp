#include "options.h"

namespace cmp {
namespace {

using Table = rt::OptionTable<CompareOptions>;
using rt::Range;

const char* kTolerances = "Float resolution";
const char* kVerdict = "Verdict (welch, paired, diff --moments)";
const char* kImages = "Images for a person";

// The float resolution of welch and diff --moments: r = R |mean| / n^(1/4) + A.
void add_welch_tolerances(Table& t) {
  t.section(kTolerances)
      .real("--rel-tol", "R", Range::closed(0, 1), RT_FIELD(welch.rel_tol),
            "float resolution r = R |mean| / n^(1/4) + A, added to the standard error")
      .real("--abs-tol", "A", Range::closed(0, 1e6), RT_FIELD(welch.abs_tol),
            "the absolute part A of the float resolution");
}

void add_verdict(Table& t) {
  t.section(kVerdict)
      .real("--alpha", "A", Range::closed(1e-12, 0.5), RT_FIELD(family.alpha),
            "family-wise false-alarm probability of the verdict")
      .flag("--bh", RT_FIELD(family.bh),
            "reject by Benjamini-Hochberg (FDR alpha') instead of Sidak; under H0 it fails "
            "with probability at most alpha' too, and it is more powerful when many cells "
            "are biased")
      .flag("--no-uniformity", RT_FIELD(family.uniformity),
            "leave the uniformity check out of the verdict (still printed)", false);
}

void add_images(Table& t, bool gain) {
  t.section(kImages).text("--out-dir", "DIR", RT_FIELD(out_dir),
                          "write <sub>-diff.png, <sub>-pvalue.png and <sub>-mask.png there");
  if (gain)
    t.real("--gain", "G", Range::closed(0, 1e6), RT_FIELD(gain),
           "difference image: 128 + G * (B - A) per channel (mid-gray is equal)");
}

Table make_welch() {
  Table t("compare welch", "compare welch A B [options]",
          "Welch's unequal-variance t-test per pixel (or tile) and channel; see compare --help.");
  t.section("welch")
      .flag("--pooled", RT_FIELD(welch.pooled),
            "per-sample variance of a pixel = the larger of the two renders' (same scene and "
            "sampler, other sample counts): a low-spp render that missed a pixel's rare "
            "bright paths reports zero variance; the default when the sample counts differ")
      .flag("--unpooled", RT_FIELD(unpooled),
            "each render's own per-sample variance even when the sample counts differ (a "
            "heavy-tailed path tracer then raises false alarms)")
      .integer("--tile", "K", Range::closed(1, 1 << 16), RT_FIELD(welch.tile),
               "test K x K tiles (mean of the pixel means, variances summed): power against "
               "small, spatially smooth biases")
      .flag("--allow-weighted", RT_FIELD(allow_weighted),
            "accept Gaussian-filtered moments (approximate)");
  add_welch_tolerances(t);
  add_verdict(t);
  add_images(t, true);
  return t;
}

Table make_paired() {
  Table t("compare paired", "compare paired A B [options]",
          "Sign tests on per-pixel differences of same-seed renders; see compare --help.");
  t.section("paired")
      .integer("--tile", "K", Range::closed(2, 1 << 16), RT_FIELD(paired.tile),
               "tile size of the sign tests")
      .real("--rel-tol", "R", Range::closed(0, 1), RT_FIELD(paired.rel_tol),
            "ties: |B - A| <= R |mean| + A are dropped")
      .real("--abs-tol", "A", Range::closed(0, 1e6), RT_FIELD(paired.abs_tol),
            "the absolute part A of a tie");
  add_verdict(t);
  add_images(t, true);
  return t;
}

Table make_exact() {
  Table t("compare exact", "compare exact A B [options]",
          "The first sample's primary hit of every pixel; see compare --help.");
  t.section("exact")
      .real("--t-tol", "T", Range::closed(0, 1), RT_FIELD(exact.t_tol),
            "relative tolerance of hit distances")
      .real("--n-tol", "N", Range::closed(0, 2), RT_FIELD(exact.n_tol),
            "tolerance of each normal component")
      .real("--max-fraction", "F", Range::closed(0, 1), RT_FIELD(exact.max_fraction),
            "FAIL when more than this share of the pixels mismatch");
  add_images(t, false);
  return t;
}

Table make_diff() {
  Table t("compare diff", "compare diff A.png B.png [options]",
          "Image metrics of B against A; see compare --help.");
  t.section("diff")
      .integer("--threshold", "T", Range::closed(0, 255), RT_FIELD(threshold),
               "count the pixels whose largest channel difference exceeds T")
      .integer("--downsample", "K", Range::closed(1, 1 << 16), RT_FIELD(downsample),
               "also compare after a K x K box downsample, which averages out sampling noise")
      .text("--out", "FILE", RT_FIELD(out), "write |A - B| x 4 as a gray PNG")
      .text("--moments", "B.moments.exr", RT_FIELD(moments),
            "also test B's moments against A as an 8-bit image without variance (a converged "
            "reference): Welch per cell with the reference's variance taken as its rounding "
            "error, 1/12 level^2, and B's means clamped to [0, 255]. H0: A is B's expected "
            "image, rounded. Verdict and exit status as for welch")
      .integer("--tile", "K", Range::closed(1, 1 << 16), RT_FIELD(welch.tile),
               "with --moments: test K x K tiles");
  add_welch_tolerances(t);
  add_verdict(t);
  add_images(t, false);
  return t;
}

// The list of course scenes `compare reference` looks a criterion up in.
#ifndef RT_COURSE_SCENES
#define RT_COURSE_SCENES "tests/course/course_scenes.txt"
#endif

Table make_report() {
  Table t("compare report", "compare report A B --out FILE.html|DIR [options]",
          "One HTML page for a person: A, B, a difference map, the worst tiles enlarged and "
          "a verdict in words; see compare --help.");
  t.section("report")
      .text("--out", "FILE|DIR", RT_FIELD(out),
            "the page to write (a directory: DIR/report.html); required")
      .integer("--tile", "K", Range::closed(2, 4096), RT_FIELD(report_tile),
               "tile edge in pixels: the cells of the test and of the enlargements")
      .integer("--worst", "N", Range::closed(0, 100), RT_FIELD(worst), "tiles to enlarge");
  add_verdict(t);
  return t;
}

Table make_reference() {
  CompareOptions d;
  d.scenes_list = RT_COURSE_SCENES;
  Table t("compare reference", "compare reference RENDER.png REFERENCE.png [options]",
          "Checks an existing render against the course's official image by the reference "
          "tests' criterion; see compare --help.",
          d);
  t.section("reference")
      .text("--criterion", "SPEC", RT_FIELD(criterion),
            "KIND[:LIMIT][,double:P] as in tests/course/course_scenes.txt, KIND hw12, hw3 or block: " +
                criterion_help())
      .default_is("the line of --scenes-list whose REFERENCE ends REFERENCE.png")
      .text("--scenes-list", "FILE", RT_FIELD(scenes_list),
            "the list of course scenes, images and criteria")
      .flag("--double", RT_FIELD(double_precision),
            "the render computed in double (RT_TEST_PRECISION=double): the criterion's "
            "double:P share of identical pixels applies");
  return t;
}

Table make_summary() {
  return Table("compare summary", "compare summary IMAGE",
               "Size, range, NaN and Inf counts and mean per channel of a PNG, EXR, HDR or "
               "moment file, and the samples when moments exist.");
}

const char* kIntro =
    R"(usage: compare SUBCOMMAND FILES [options]   (compare SUBCOMMAND --help: its options)

Checks a render B against a render A. A and B are moment files written by
`raytracer --moments` (<image>.moments.exr; the PNG's name is accepted too) or, for
diff, PNGs. Exit status: 0 PASS, 1 FAIL, 2 bad usage or unreadable input.
Each statistical verdict prints the tests made, the rejections, the smallest p-value
and the significance used, then a line "verdict: PASS" or "verdict: FAIL".

)";

const char* kWelch =
    R"(welch A B     Welch's unequal-variance t-test per pixel (or per tile) and channel
              (Jung, Hanika, Dachsbacher, JCGT 2020). Render A and B with different
              seeds.
   H0: in every cell both renders estimate the same expected (unclamped) radiance.
   t = (mean_B - mean_A) / sqrt(var_A/n_A + var_B/n_B + r^2), Welch-Satterthwaite
   degrees of freedom, two-sided p from Student's t; r is the float resolution
   (--rel-tol * |mean| / n^(1/4) + --abs-tol): rounding in the float sums of x and
   x^2 leaves even a constant pixel with a standard error of about
   4e-4 |mean| / n^(1/4). Cells with zero variance in
   both renders (every sample alike) are no test: equal means (within r) pass and
   are counted apart, different means are a
   deterministic failure. FAIL when a test is rejected at the Sidak level
   1 - (1 - alpha')^(1/m) over the m tests (or by Benjamini-Hochberg with --bh),
   when there is a deterministic failure, or when the p-values are not uniform:
   too many small ones. That check counts, per channel, the cells with p < 0.05
   against Binomial(cells, 0.05) (Bonferroni over R, G, B): many small shifts
   that no single test rejects add up there. With it on, alpha is split evenly
   (alpha' = alpha / 2), so the chance of failing two correct renders is at most
   alpha. A two-sided Kolmogorov-Smirnov test of all p-values against U(0,1) is
   printed for information only: on large images it flags the slight misfit of
   Student's t to non-normal radiance at few samples, and it shows p-values
   piled up near 1 under stratified sampling. Needs >= 2 samples per pixel and
   the box filter (the default). Stratified sampling (perfect-square spp) makes
   the sample variance overestimate the variance of the mean, so the test is
   conservative there and loses power; a non-square --spp draws independent
   samples and gives the nominal rate.
)";

const char* kPaired =
    R"(paired A B    Sign tests on per-pixel differences, for renders with the same --seed.
   H0: each pixel's difference B - A is symmetric about zero, independently across
   pixels (true for the same computation with other rounding, and for any two
   renders of the same image). Differences within the float resolution are ties and
   are dropped. One exact two-sided sign test per K x K tile and channel, plus one
   over the whole image per channel; verdict as for welch. With equal seeds a
   systematic difference changes nearly every pixel the same way, so this is far
   more sensitive than welch.
)";

const char* kExact =
    R"(exact A B     The first sample's primary hit of every pixel (same seed: same ray).
   H0: same instance and primitive ids (or both missed), distances within --t-tol
   relative and normals within --n-tol per component. FAIL when more than
   --max-fraction of the pixels mismatch.
)";

const char* kDiff =
    R"(diff A.png B.png   Image metrics of B against A: MAE, RMSE, PSNR, percentage of
   pixels whose largest channel difference exceeds --threshold, the largest
   difference, the share of identical pixels, and the same after a K x K box
   downsample. Exit status 0 (without --moments).
)";

const char* kReport =
    R"(report A B --out FILE.html|DIR   One self-contained HTML page (images embedded)
   for a person: A, B and the difference |B - A| (largest channel, viridis colour
   map) side by side, the worst tiles enlarged, their figures, and a verdict in
   words: "identical" (same pixels and means), "within noise" (the statistical test
   passes: paired for equal seeds, else welch, on the tiles, when both have moment
   files beside them), "biased here" (naming the rejected tiles), or for images
   without moments a difference summary (largest, mean, share of pixels differing).
   Exit status 0 (the page is written), 2 on bad input.
)";

const char* kReference =
    R"(reference RENDER.png REFERENCE.png   Checks an existing render against the course's
   official image by the criterion the reference tests use (tests/course/reference_check.cpp
   renders and applies the same code), without rendering again. The criterion is
   looked up in tests/course/course_scenes.txt by REFERENCE's path unless --criterion
   gives it. Exit status 0 PASS, 1 FAIL, 2 bad input.
)";

const char* kSummary =
    R"(summary IMAGE   Size, range, NaN and Inf counts and mean per channel; for a moment
   file (or a PNG with one beside it) also the samples per pixel and the variances.
)";

const char* kMaps = R"(The images, as PNG (--out-dir works with every subcommand):
  DIR/<sub>-diff.png    welch/paired: 128 + gain * (B - A) per channel (mid-gray is
                        equal); exact: relative distance difference, white at the
                        tolerance or on a mismatch; diff: |A - B| x 4
  DIR/<sub>-pvalue.png  welch/paired/diff --moments: the cell's smallest p as gray
                        (black p = 1, near white at the rejection level), red
                        rejected, magenta deterministic failure, dark blue not tested
  DIR/<sub>-mask.png    white where a cell fails (diff without --moments: pixels over
                        the threshold)
where <sub> is welch, paired, exact or diff.
)";

}  // namespace

const rt::OptionTable<CompareOptions>* subcommand_table(const std::string& name) {
  static const Table welch = make_welch(), paired = make_paired(), exact = make_exact(),
                     diff = make_diff(), report = make_report(), reference = make_reference(),
                     summary = make_summary();
  if (name == "report") return &report;
  if (name == "reference") return &reference;
  if (name == "summary") return &summary;
  if (name == "welch") return &welch;
  if (name == "paired") return &paired;
  if (name == "exact") return &exact;
  if (name == "diff") return &diff;
  return nullptr;
}

CompareOptions parse_subcommand(const char* sub, int argc, char** argv,
                                std::vector<std::string>* files, size_t count) {
  const Table& table = *subcommand_table(sub);
  CompareOptions o = table.defaults();
  *files = table.parse_or_exit(argc, argv, &o, 2);
  if (files->size() != count)
    table.usage_error(std::string(sub) + (count == 1 ? " takes one file" : " takes two files"));
  return o;
}

std::string compare_help() {
  const Table& welch = *subcommand_table("welch");
  std::string h = kIntro;
  h += kWelch + welch.section_help("welch") + welch.section_help(kTolerances);
  const Table& paired = *subcommand_table("paired");
  h += "\n" + (kPaired + paired.section_help("paired"));
  h += "\n" + (kExact + subcommand_table("exact")->section_help("exact"));
  const Table& diff = *subcommand_table("diff");
  h += "\n" + (kDiff + diff.section_help("diff"));
  const Table& report = *subcommand_table("report");
  h += "\n" + (kReport + report.section_help("report"));
  h += "\n" + (kReference + subcommand_table("reference")->section_help("reference"));
  h += std::string("\n") + kSummary;
  h += std::string("\nOptions of welch, paired, diff --moments and report:\n") +
       welch.section_help(kVerdict);
  h += std::string("\nImages for a person:\n") + welch.section_help(kImages) + kMaps;
  return h;
}

}  // namespace cmp
