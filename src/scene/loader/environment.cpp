// The environment light of hw5 (SphericalDirectionalLight): its image, mapping and sampler.
#include <tinyxml2.h>

#include <cmath>
#include <cstring>
#include <filesystem>
#include <string>

#include "cl/light/environment_map.h"
#include "image/read_hdr.h"
#include "image/read_ldr.h"
#include "scene/loader/loader.h"
#include "scene/scene.h"
#include "scene/xml_text.h"
#include "util/errors.h"

namespace rt {
namespace loader {

namespace {

std::string trimmed(const std::string& s) {
  size_t a = s.find_first_not_of(" \t\r\n"), b = s.find_last_not_of(" \t\r\n");
  return a == std::string::npos ? std::string() : s.substr(a, b - a + 1);
}

}  // namespace

// The map is read here, when the light is read, so a missing or unreadable file fails the
// load before anything renders. HDR files (.exr, .hdr, .pic) hold radiance; a PNG or JPEG
// map is read on its 0..255 scale as radiance, as a replace_background image is.
void Loader::read_environment_light(const XMLElement* light, const XMLElement* scene) {
  if (scene_.environment_map.width > 0)
    fail(light, "a second environment light (only one SphericalDirectionalLight is allowed)");
  Light env{};
  env.type = RT_LIGHT_ENVIRONMENT;
  const char* type = light->Attribute("type");
  std::string mapping = type ? type : "latlong";
  if (mapping == "latlong")
    RT_ENV_MAPPING(&env) = RT_ENV_LATLONG;
  else if (mapping == "probe")
    RT_ENV_MAPPING(&env) = RT_ENV_PROBE;
  else
    fail(light, "type '" + shorten(mapping) + "' is neither latlong nor probe");
  RT_ENV_SAMPLING(&env) = RT_ENV_SAMPLE_IMPORTANCE;
  if (const XMLElement* s = child(light, "Sampler", false)) {
    std::string sampler = trimmed(text_of(s));
    if (sampler == "uniform")
      RT_ENV_SAMPLING(&env) = RT_ENV_SAMPLE_UNIFORM;
    else if (sampler == "cosine")
      RT_ENV_SAMPLING(&env) = RT_ENV_SAMPLE_COSINE;
    else if (sampler != "importance")
      fail_value(s, "is not a Sampler (uniform, cosine or importance)");
  }
  const XMLElement* id_e = child(light, "ImageId", true);
  std::string id = trimmed(text_of(id_e));
  const XMLElement* images = child(scene, "Textures", false);
  images = images ? child(images, "Images", false) : nullptr;
  const XMLElement* image = images ? images->FirstChildElement("Image") : nullptr;
  while (image && !(image->Attribute("id") && id == image->Attribute("id")))
    image = image->NextSiblingElement("Image");
  if (!image) fail(id_e, "no Image with id '" + shorten(id) + "' in Textures > Images");
  std::filesystem::path path(trimmed(text_of(image)));
  if (path.empty()) fail(image, "empty file name");
  if (path.is_relative()) path = std::filesystem::path(file_).parent_path() / path;
  ImageF map;
  try {
    scene_.inputs.push_back(path.string());
    map = read_any_image(path.string());
  } catch (const std::exception& err) {
    fail(id_e, std::string("environment map ") + err.what());
  }
  if (map.channels != 1 && map.channels < 3) fail(id_e, "environment map: not an RGB image");
  if (std::string bad = first_invalid_texel(map); !bad.empty())
    fail(id_e,
         "environment map " + path.string() + ": " + bad + " (radiance must be finite and >= 0)");
  scene_.environment_map = std::move(map);
  scene_.lights.push_back(env);  // prepare_scene places the map, prepare_camera the sizes.
}

}  // namespace loader
}  // namespace rt
