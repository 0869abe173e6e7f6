// How an output says it holds fewer samples than its camera asks (a render interrupted, or
// an image written by --checkpoint while the render runs): the text "<spp> of <asked>"
// under the key kSamplesMarkKey, as a PNG tEXt chunk, a JPEG comment ("rt:samples=..."),
// or an OpenEXR string attribute (images and moment files). A finished image carries no
// mark at all, so its bytes are those of a render that was never interrupted.
#pragma once

#include <string>

namespace rt {

constexpr const char* kSamplesMarkKey = "rt:samples";

// "123 of 900".
std::string samples_mark_text(int spp, int asked);

enum class OutputState { kMissing, kComplete, kPartial };

struct OutputStatus {
  OutputState state = OutputState::kMissing;
  std::string mark;  // kPartial: the mark.
};

// What the output at `path` (PNG, JPEG or EXR by its extension, as image_format_of) holds:
// missing, finished (no mark), or partial. A file that cannot be parsed counts as finished:
// the renderer's writes are atomic, so it is someone else's, not a render cut short.
// Never throws.
OutputStatus output_status(const std::string& path);

}  // namespace rt
