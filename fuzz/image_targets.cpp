// The image readers' fuzz targets (declared in fuzz/targets.h). The readers take a path, so
// each input goes through a file of the scratch folder (fuzz/scratch.h) named with the
// extension that picks the reader, as a texture or environment map named in a scene would.
#include <stdexcept>
#include <string>

#include "fuzz/scratch.h"
#include "fuzz/targets.h"
#include "image/read_hdr.h"
#include "image/read_ldr.h"

namespace rt {
namespace {

// Reads the bytes as `name` through read_any_image (the texture loader's entry point). A
// refusal must be one line naming the file; an image must be as large as it says it is.
void read_image(const std::string& name, const uint8_t* data, size_t size) {
  const std::string path = fuzz_scratch_file(name, data, size);
  ImageF img;
  try {
    img = read_any_image(path);
  } catch (const std::runtime_error& e) {
    const std::string what = e.what();
    if (what.rfind(path + ": ", 0) != 0 || what.find('\n') != std::string::npos)
      throw std::logic_error("a refusal not in one line naming the file: " + what);
    return;
  }
  if (img.width <= 0 || img.height <= 0 || img.channels < 1 || img.channels > 4 ||
      img.pixels.size() != img.size() * img.channels)
    throw std::logic_error("an image whose pixels do not match its size");
  // The check the texture loader runs on HDR images; here for its reads of every texel.
  (void)first_invalid_texel(img);
}

}  // namespace

void fuzz_png(const uint8_t* data, size_t size) { read_image("in.png", data, size); }
void fuzz_jpeg(const uint8_t* data, size_t size) { read_image("in.jpg", data, size); }
void fuzz_exr(const uint8_t* data, size_t size) { read_image("in.exr", data, size); }
void fuzz_hdr(const uint8_t* data, size_t size) { read_image("in.hdr", data, size); }

}  // namespace rt
