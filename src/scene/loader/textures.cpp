// Texture maps, images and texture coordinates.
#include <tinyxml2.h>

#include <cctype>
#include <cerrno>
#include <cfloat>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <filesystem>
#include <map>
#include <sstream>

#include "cl/material/brdf.h"
#include "util/errors.h"
#include "image/read_hdr.h"
#include "image/read_ldr.h"
#include "scene/loader/loader.h"
#include "scene/ply.h"
#include "scene/scene.h"
#include "scene/xml_text.h"

namespace rt {
namespace loader {

// One of the words `names` (the course's spelling), as its index.
static int keyword(const std::string& word, std::initializer_list<const char*> names) {
  int i = 0;
  for (const char* n : names) {
    if (word == n) return i;
    ++i;
  }
  return -1;
}

static std::string trimmed(const std::string& s) {
  size_t a = s.find_first_not_of(" \t\r\n"), b = s.find_last_not_of(" \t\r\n");
  return a == std::string::npos ? std::string() : s.substr(a, b - a + 1);
}

// degamma="true" on a TextureMap (hw6/sponza.xml): its colours were stored gamma-encoded,
// so they are decoded with the course's gamma of 2.2, as a material's degamma decodes its
// reflectances, on the image's own scale (0..255 stays 0..255). The decoded values are no
// longer whole 8-bit numbers, so the image is kept as floats (max_value 0, as HDR images;
// see flat_textures.cpp).
static void decode_gamma(ImageF& im) {
  const float scale = im.max_value > 0 ? im.max_value : 1.0f;
  for (float& v : im.pixels) v = scale * std::pow(v / scale, 2.2f);
  im.max_value = 0;
}

TextureMapDesc Loader::read_texture_map(const XMLElement* e,
                                        const std::map<std::string, std::string>& images,
                                        std::map<std::pair<std::string, bool>, int>& loaded) {
  TextureMapDesc t;
  t.element = path_of(e);
  TextureDesc& d = t.desc;
  const char* type = e->Attribute("type");
  d.type = keyword(type ? type : "", {"image", "perlin", "checkerboard"});
  if (d.type < 0) fail(e, "type '" + shorten(type) + "' is not image, perlin or checkerboard");
  const XMLElement* mode = child(e, "DecalMode", true);
  d.decal =
      keyword(trimmed(text_of(mode)), {"replace_kd", "blend_kd", "replace_ks", "replace_background",
                                       "replace_normal", "bump_normal", "replace_all"});
  if (d.decal < 0) fail_value(mode, "is not a DecalMode of the course");
  d.interpolation = RT_INTERP_NEAREST;
  if (const XMLElement* in = child(e, "Interpolation", false)) {
    d.interpolation = keyword(trimmed(text_of(in)), {"nearest", "bilinear"});
    if (d.interpolation < 0) fail_value(in, "is neither nearest nor bilinear");
  }
  d.normalizer = static_cast<float>(child_number(e, "Normalizer", 255));
  if (!(d.normalizer > 0)) fail_value(child(e, "Normalizer", true), "must be positive");
  d.bump_factor = static_cast<float>(child_number(e, "BumpFactor", 1));
  d.noise_scale = static_cast<float>(child_number(e, "NoiseScale", 1));
  if (!(d.noise_scale > 0)) fail_value(child(e, "NoiseScale", true), "must be positive");
  d.noise_conversion = RT_NOISE_LINEAR;
  if (const XMLElement* nc = child(e, "NoiseConversion", false)) {
    d.noise_conversion = keyword(trimmed(text_of(nc)), {"linear", "absval"});
    if (d.noise_conversion < 0) fail_value(nc, "is neither linear nor absval");
  }
  d.checker_scale = static_cast<float>(child_number(e, "Scale", 1));
  d.checker_offset = static_cast<float>(child_number(e, "Offset", 0));
  d.black = to_float3(child_vec3(e, "BlackColor", {0, 0, 0}));
  d.white = to_float3(child_vec3(e, "WhiteColor", {1, 1, 1}));
  if (d.type == RT_TEXTURE_IMAGE) {
    const XMLElement* ie = child(e, "ImageId", true);
    std::string id = trimmed(text_of(ie));
    auto it = images.find(id);
    if (it == images.end()) fail(ie, "no Image with id '" + shorten(id) + "'");
    bool degamma = false;
    if (const char* dg = e->Attribute("degamma")) {
      if (std::string(dg) != "true" && std::string(dg) != "false")
        fail(e, "degamma '" + shorten(dg) + "' is neither true nor false");
      degamma = std::string(dg) == "true";
    }
    // A degammaed map gets its own decoded copy: other maps may use the image as stored.
    auto [slot, fresh] =
        loaded.emplace(std::make_pair(id, degamma), static_cast<int>(scene_.images.size()));
    if (fresh) {
      std::filesystem::path path(it->second);
      if (path.is_relative()) path = std::filesystem::path(file_).parent_path() / path;
      // An HDR file (.exr, .hdr) keeps its linear values, divided by the Normalizer like
      // any image's (hw5's sphere_point_hdr_texture sets it to 1); nothing degammas them.
      try {
        scene_.inputs.push_back(path.string());
        scene_.images.push_back(read_any_image(path.string()));
      } catch (const std::exception& err) {
        fail(ie, std::string("image ") + err.what());
      }
      if (std::string bad = first_invalid_texel(scene_.images.back()); !bad.empty())
        fail(ie, "image " + path.string() + ": " + bad + " (values must be finite and >= 0)");
      if (degamma) decode_gamma(scene_.images.back());
    }
    t.image = slot->second;
  } else if (d.decal == RT_DECAL_REPLACE_NORMAL || d.decal == RT_DECAL_REPLACE_BACKGROUND) {
    fail(mode, "'" + trimmed(text_of(mode)) + "' needs an image texture");
  }
  return t;
}

void Loader::read_textures(const XMLElement* scene) {
  const XMLElement* ts = child(scene, "Textures", false);
  if (!ts) return;
  std::map<std::string, std::string> images;  // Image id -> file, read when first used.
  if (const XMLElement* list = child(ts, "Images", false))
    for (auto* im = list->FirstChildElement("Image"); im; im = im->NextSiblingElement("Image")) {
      const char* id = im->Attribute("id");
      if (!id) fail(im, "missing id attribute");
      std::string path = trimmed(text_of(im));
      if (path.empty()) fail(im, "empty file name");
      images[id] = path;
    }
  std::map<std::pair<std::string, bool>, int> loaded;  // (Image id, degamma) -> image.
  for (auto* e = ts->FirstChildElement("TextureMap"); e; e = e->NextSiblingElement("TextureMap")) {
    const char* id = e->Attribute("id");
    if (!id) fail(e, "missing id attribute");
    TextureMapDesc t = read_texture_map(e, images, loaded);
    if (t.desc.decal == RT_DECAL_REPLACE_BACKGROUND) {
      if (scene_.background_texture >= 0)
        fail(e, "a second replace_background texture (only one background is allowed)");
      scene_.background_texture = static_cast<int>(scene_.textures.size());
    }
    texture_ids_[id] = static_cast<int>(scene_.textures.size());
    scene_.textures.push_back(t);
  }
}

void Loader::read_texcoords(const XMLElement* scene) {
  const XMLElement* td = child(scene, "TexCoordData", false);
  if (!td) return;
  auto v = data_numbers(td, 2, "texture coordinate pair", false);
  if (v.size() % 2 != 0) fail(td, std::to_string(v.size()) + " numbers is not a multiple of 2");
  for (size_t i = 0; i + 1 < v.size(); i += 2) texcoords_.push_back({v[i], v[i + 1]});
}

std::vector<int> Loader::textures_of(const XMLElement* e) const {
  std::vector<int> out;
  const XMLElement* t = child(e, "Textures", false);
  if (!t) return out;
  std::istringstream in(text_of(t));
  std::string id;
  while (in >> id) {
    auto it = texture_ids_.find(id);
    if (it == texture_ids_.end()) fail(t, "no TextureMap with id '" + shorten(id) + "'");
    if (scene_.textures[it->second].desc.decal == RT_DECAL_REPLACE_BACKGROUND) continue;
    out.push_back(it->second);
  }
  if (out.size() > RT_MAX_OBJECT_TEXTURES)
    fail_value(t, "lists more than " + std::to_string(RT_MAX_OBJECT_TEXTURES) + " textures");
  return out;
}

// Image textures on a mesh need texture coordinates for every vertex.
void Loader::check_texture_coordinates() const {
  for (const ObjectDesc& o : scene_.objects) {
    if (o.kind != ObjectDesc::kMesh || !scene_.meshes[o.mesh].uvs.empty()) continue;
    for (int t : o.textures)
      if (scene_.textures[t].desc.type == RT_TEXTURE_IMAGE)
        throw input_error(file_, o.element,
                          "uses an image texture (" + scene_.textures[t].element +
                              ") but has no texture coordinates (TexCoordData or PLY u v)");
  }
}

}  // namespace loader
}  // namespace rt
