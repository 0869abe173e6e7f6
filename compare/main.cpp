// compare: checks two renders against each other, statistically (welch, paired), exactly
// (exact) or by image metrics (diff). See compare/README.md for the method and its
// calibration.
#include <cstdio>
#include <string>

#include "commands.h"

namespace {

const char* kUsage = R"(usage: compare SUBCOMMAND A B [options]

Checks a render B against a render A. A and B are moment files written by
`raytracer --moments` (<image>.moments.exr; the PNG's name is accepted too) or, for
diff, PNGs. Exit status: 0 PASS, 1 FAIL, 2 bad usage or unreadable input.
Each statistical verdict prints the tests made, the rejections, the smallest p-value
and the significance used, then a line "verdict: PASS" or "verdict: FAIL".

welch A B     Welch's unequal-variance t-test per pixel (or per tile) and channel
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
   --pooled        per-sample variance of a pixel = the larger of the two renders'
                   (same scene and sampler, other sample counts): a low-spp render
                   that missed a pixel's rare bright paths reports zero variance
   --tile K        test K x K tiles (mean of the pixel means, variances summed):
                   power against small, spatially smooth biases (default 1)
paired A B    Sign tests on per-pixel differences, for renders with the same --seed.
   H0: each pixel's difference B - A is symmetric about zero, independently across
   pixels (true for the same computation with other rounding, and for any two
   renders of the same image). Differences within the float resolution are ties and
   are dropped. One exact two-sided sign test per K x K tile and channel, plus one
   over the whole image per channel; verdict as for welch. With equal seeds a
   systematic difference changes nearly every pixel the same way, so this is far
   more sensitive than welch.
   --tile K        tile size of the sign tests (default 8, at least 2)
exact A B     The first sample's primary hit of every pixel (same seed: same ray).
   H0: same instance and primitive ids (or both missed), distances within --t-tol
   relative (default 1e-4) and normals within --n-tol per component (default 1e-4).
   FAIL when more than --max-fraction of the pixels (default 0) mismatch.
diff A.png B.png   Image metrics of B against A: MAE, RMSE, PSNR, percentage of
   pixels whose largest channel difference exceeds --threshold T (default 8), the
   largest difference, the share of identical pixels, and the same after a K x K
   box downsample (--downsample K, default 4), which averages out sampling noise.
   Exit status 0. --out FILE writes |A - B| x 4 as a gray PNG.
   --moments B.moments.exr   also test B's moments against A as an 8-bit image
                   without variance (a converged reference): Welch per cell with the
                   reference's variance taken as its rounding error, 1/12 level^2,
                   and B's means clamped to [0, 255]. H0: A is B's expected image,
                   rounded. Verdict and exit status as for welch.

Options of welch, paired and diff --moments:
  --alpha A        family-wise false-alarm probability of the verdict (default 0.01)
  --bh             reject by Benjamini-Hochberg (FDR alpha') instead of Sidak; under
                   H0 it fails with probability at most alpha' too, and it is more
                   powerful when many cells are biased
  --no-uniformity  leave the uniformity check out of the verdict (still printed)
  --rel-tol R, --abs-tol A   float resolution: welch and diff r = R |mean| / n^(1/4)
                   + A (default 6e-4, 1e-6), paired ties |B - A| <= R |mean| + A
                   (default 1e-4, 1e-6)
  --allow-weighted  accept Gaussian-filtered moments (welch; approximate)

Images for a person (every subcommand): --out-dir DIR writes, as PNG,
  DIR/<sub>-diff.png    welch/paired: 128 + gain * (B - A) per channel (--gain, default
                        4; mid-gray is equal); exact: relative distance difference,
                        white at the tolerance or on a mismatch; diff: |A - B| x 4
  DIR/<sub>-pvalue.png  welch/paired/diff --moments: the cell's smallest p as gray
                        (black p = 1, near white at the rejection level), red
                        rejected, magenta deterministic failure, dark blue not tested
  DIR/<sub>-mask.png    white where a cell fails (diff without --moments: pixels over
                        the threshold)
where <sub> is welch, paired, exact or diff.
)";

}  // namespace

int main(int argc, char** argv) {
  std::string cmd = argc > 1 ? argv[1] : "";
  if (cmd == "--help" || cmd == "-h" || cmd == "help") {
    std::fputs(kUsage, stdout);
    return 0;
  }
  try {
    if (cmd == "welch") return cmp::run_welch(argc, argv);
    if (cmd == "paired") return cmp::run_paired(argc, argv);
    if (cmd == "exact") return cmp::run_exact(argc, argv);
    if (cmd == "diff") return cmp::run_diff(argc, argv);
  } catch (const std::exception& e) {
    std::fprintf(stderr, "compare: error: %s\n", e.what());
    return 2;
  }
  std::fprintf(stderr, "compare: %s\n(see compare --help)\n",
               cmd.empty() ? "no subcommand given" : ("unknown subcommand '" + cmd + "'").c_str());
  return 2;
}
