// Images for an HTML page: PNGs as data: URIs (so the page needs no files beside it), and
// the crops and nearest-neighbour enlargements of tiles a person looks at closely.
#pragma once

#include <string>
#include <vector>

#include "io/png_io.h"

namespace cmp {

std::string base64(const std::vector<uint8_t>& bytes);

// "data:image/png;base64,...". The PNG is encoded by rt::write_png through a private
// temporary directory, removed again; throws std::runtime_error if that fails.
std::string png_data_uri(const rt::Image8& image);

// The w x h pixels at (x, y) (clipped to the image).
rt::Image8 crop(const rt::Image8& image, int x, int y, int w, int h);

// Every pixel repeated `zoom` x `zoom` times (zoom >= 1).
rt::Image8 enlarge(const rt::Image8& image, int zoom);

// `text` with &, <, >, " and ' escaped for HTML text and attribute values.
std::string html_escape(const std::string& text);

}  // namespace cmp
