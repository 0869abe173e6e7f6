// Textures flattened for the devices: every image once, as packed 8-bit RGB texels (HDR
// images: the bits of three floats per texel) one after the other, and a descriptor per
// TextureMap pointing at its image.
#include <algorithm>
#include <cstring>

#include "prepare_stages.h"

namespace rt {

namespace {

// Images whose values are not whole 8-bit numbers: HDR files, which their readers mark with
// max_value 0 (image/image.h), and degammaed textures (loader/textures.cpp).
bool is_hdr(const ImageF& im) { return im.max_value == 0.0f; }

}  // namespace

void flatten_textures(const SceneDesc& scene, FlatScene& f) {
  std::vector<int> first(scene.images.size());
  for (size_t i = 0; i < scene.images.size(); ++i) {
    const ImageF& im = scene.images[i];
    first[i] = static_cast<int>(f.texels.size());
    if (is_hdr(im)) {
      for (size_t p = 0; p < im.size(); ++p)
        for (int c = 0; c < 3; ++c) {
          uint32_t bits;
          std::memcpy(&bits, &im.pixels[p * im.channels + (im.channels >= 3 ? c : 0)], 4);
          f.texels.push_back(bits);
        }
      continue;
    }
    for (size_t p = 0; p < im.size(); ++p) {
      uint32_t packed = 0;
      for (int c = 0; c < 3; ++c) {
        float v = im.pixels[p * im.channels + (im.channels >= 3 ? c : 0)];
        packed |= static_cast<uint32_t>(std::min(255.0f, std::max(0.0f, v))) << (8 * c);
      }
      f.texels.push_back(packed);
    }
  }
  for (const TextureMapDesc& t : scene.textures) {
    TextureDesc d = t.desc;
    if (t.image >= 0) {
      d.first_texel = first[t.image];
      d.width = scene.images[t.image].width;
      d.height = scene.images[t.image].height;
      d.hdr = is_hdr(scene.images[t.image]) ? 1 : 0;
    }
    f.textures.push_back(d);
  }
}

}  // namespace rt
