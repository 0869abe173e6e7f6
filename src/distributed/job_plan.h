// The work of a distributed job: the images to render (rank 0 lists them from the scene
// files, leaving out existing ones under --skip-existing) and the tasks they are cut into.
// Animations are spread as whole images (frames as tasks, as render-farm managers such as
// Flamenco do); when there are too few images to keep every rank busy to the end, images
// are cut into bands of rows (tiles, as OSPRay's MPI module does), which a rank that
// finishes early takes more of. The sampler is keyed by pixel, sample, dimension and seed,
// so the cut changes no pixel.
#pragma once

#include <string>
#include <vector>

#include "app/cli.h"
#include "scene/scene.h"

namespace rt {

struct PlannedImage {
  int scene = 0, camera = 0;  // Index into CliOptions::scenes; camera in that file.
  int width = 0, height = 0;
  std::string path;  // The output file.
  CameraDesc desc;   // The camera as loaded (its outputs, e.g. tone mapping, follow it).
};

// A band of rows [row_begin, row_end) of one image, all of its samples.
struct TileTask {
  int image = 0, scene = 0, camera = 0, row_begin = 0, row_end = 0;
};

struct JobPlan {
  std::vector<PlannedImage> images;
  std::vector<TileTask> tasks;  // In the order they are handed out.
  int tile_rows = 0;            // 0: whole images.
};

// Tiles start on multiples of this many rows (every device's row alignment divides it).
constexpr int kTileRowMultiple = 32;

// Lists the images of `opt.scenes` and cuts them for `ranks` ranks: --tile-rows when given
// (rounded up to kTileRowMultiple); else whole images when there are at least
// kTasksPerRank * ranks of them, else about that many tiles. A stop rule (--time-limit,
// --noise-target) keeps images whole, so the one rank that renders an image decides its
// sample count for every pixel. Throws one line on a bad scene file.
JobPlan plan_job(const CliOptions& opt, int ranks);

}  // namespace rt
