// What `compare report` finds before it writes any HTML: the per-pixel difference, the
// tiles of the image with their figures, the worst of them, and the verdict in words.
// With moments on both sides the tiles are the cells of the statistical test (paired for
// equal seeds, welch otherwise); without, they are ranked by their mean difference.
#pragma once

#include <string>
#include <vector>

#include "family.h"
#include "image_metrics.h"
#include "inputs.h"
#include "paired.h"
#include "welch.h"

namespace cmp {

enum class Finding {
  kIdentical,    // The same bytes (and, with moments, the same means).
  kWithinNoise,  // The statistical test passes.
  kBiased,       // The statistical test fails: tiles named, or the whole image.
  kDiffer,       // No moments to test: a difference summary only.
};

struct TileFigures {
  int x = 0, y = 0, w = 0, h = 0;  // Pixels.
  double mean_abs = 0;             // Mean over the pixels of the largest channel |B - A|.
  int max_abs = 0;                 // Levels of the 8-bit images.
  double mean_a[3] = {0, 0, 0}, mean_b[3] = {0, 0, 0};  // Moments' radiance, else levels.
  bool tested = false;                                  // p and rejected hold the cell's test.
  double p = 1;                                         // Smallest p of the cell's channels.
  bool rejected = false;
};

struct ReportOptions {
  int tile = 16;  // Tile edge in pixels: the cells of the test and of the enlargements.
  int worst = 6;  // Tiles enlarged.
  FamilyOptions family;
  WelchOptions welch;
  PairedOptions paired;
};

struct Analysis {
  int width = 0, height = 0, tile = 16, tiles_x = 0, tiles_y = 0;
  std::vector<float> pixel_diff;  // Largest channel |B - A| per pixel, levels.
  double scale = 1;               // Of the difference map: its 99.9th percentile, at least 1.
  rt::ImageDiff diff;             // Of the 8-bit images.
  std::vector<TileFigures> tiles;
  std::vector<size_t> worst;  // Indices into tiles, worst first.
  std::string test;           // "paired", "welch" or "" (no test).
  std::string untested_why;   // Why the moments were not tested, when they were not.
  Family family;
  Verdict verdict;
  Finding finding = Finding::kDiffer;
  std::string words;  // The verdict in words.
};

// Ranks the tiles: rejected ones first, then the tested by smallest p, then by mean and
// largest difference; tiles without any difference are left out. At most `n`.
std::vector<size_t> worst_tiles(const std::vector<TileFigures>& tiles, size_t n);

// "(x0, y0)-(x1, y1)", the tile's first and last pixels.
std::string tile_name(const TileFigures& t);

// Analyses B against A (the same size: throws otherwise, naming both files).
Analysis analyse(const Side& a, const Side& b, const ReportOptions& o);

}  // namespace cmp
