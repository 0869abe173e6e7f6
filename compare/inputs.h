// The files `compare` reads, as a person names them: a PNG (with the moment file the
// raytracer wrote beside it, when there is one) or a moment file alone.
#pragma once

#include <string>

#include "io/moments.h"
#include "io/png_io.h"

namespace cmp {

struct Side {
  std::string path;
  rt::Image8 image;  // What a person sees: the PNG, or the moment file's means rounded.
  bool has_moments = false;
  rt::MomentImage moments;
  std::string moments_path;
};

// True for "*.moments.exr".
bool is_moment_file(const std::string& path);

// Reads a PNG and, when `with_moments`, the moment file beside it if present (a moment file
// of another size is left out, with a note in *note); or a moment file, whose means are
// clamped to [0, 255] and rounded for the image. Throws std::runtime_error naming the file.
Side load_side(const std::string& path, bool with_moments, std::string* note = nullptr);

// Throws std::runtime_error("A is WxH, B is WxH: ...") unless the two sizes are equal: the
// one line a size mismatch gives in every subcommand.
void require_same_size(const std::string& a, int wa, int ha, const std::string& b, int wb, int hb);

}  // namespace cmp
