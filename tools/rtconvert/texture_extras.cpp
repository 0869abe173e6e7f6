// The course's texture maps in a glTF file's extras, their images in its binary chunk.
#include <cctype>
#include <map>

#include "course_extras.h"

namespace rtconvert {

json texture_to_json(const rt::TextureMapDesc& t, bool degamma) {
  const TextureDesc& d = t.desc;
  return {{"type", d.type},
          {"decal", d.decal},
          {"interpolation", d.interpolation},
          {"normalizer", d.normalizer},
          {"bumpFactor", d.bump_factor},
          {"noiseScale", d.noise_scale},
          {"noiseConversion", d.noise_conversion},
          {"checkerScale", d.checker_scale},
          {"checkerOffset", d.checker_offset},
          {"black", to_json(d.black)},
          {"white", to_json(d.white)},
          {"image", t.image},
          {"degamma", degamma}};
}

// A file name from the JSON: letters, digits, '-' and '_' (no "..", no '/'), and an
// extension the renderer reads.
std::string safe_image_name(const std::string& name, size_t index) {
  size_t dot = name.find_last_of('.');
  std::string stem = name.substr(0, dot), ext = dot == std::string::npos ? "" : name.substr(dot);
  for (char& c : stem)
    if (!std::isalnum(static_cast<unsigned char>(c)) && c != '-') c = '_';
  for (char& c : ext) c = static_cast<char>(std::tolower(static_cast<unsigned char>(c)));
  if (stem.empty()) stem = "image" + std::to_string(index);
  if (ext != ".png" && ext != ".jpg" && ext != ".jpeg" && ext != ".exr" && ext != ".hdr" &&
      ext != ".pic")
    ext = ".png";
  return stem.substr(0, 60) + ext;
}

void textures_from_json(const json& scene_extras, const json& gltf, const std::string& file,
                        ImportedScene& out) {
  const json images = scene_extras.value("images", json::array());
  for (size_t i = 0; i < images.size(); ++i) {
    ImageFile f;
    f.bytes = read_glb_view(file, gltf, images[i].at("bufferView").get<int>());
    f.name = safe_image_name(images[i].value("name", ""), i);
    f.degamma = images[i].value("degamma", false);
    out.images.push_back(f);
  }
  for (const json& j : scene_extras.value("textures", json::array())) {
    rt::TextureMapDesc t;
    TextureDesc& d = t.desc;
    d.type = j.at("type").get<int>();
    d.decal = j.at("decal").get<int>();
    d.interpolation = j.at("interpolation").get<int>();
    d.normalizer = j.at("normalizer").get<float>();
    d.bump_factor = j.at("bumpFactor").get<float>();
    d.noise_scale = j.at("noiseScale").get<float>();
    d.noise_conversion = j.at("noiseConversion").get<int>();
    d.checker_scale = j.at("checkerScale").get<float>();
    d.checker_offset = j.at("checkerOffset").get<float>();
    d.black = float3_from(j.at("black"));
    d.white = float3_from(j.at("white"));
    t.element = "extras." + std::string(kExtrasKey) + ".textures[" +
                std::to_string(out.scene.textures.size()) + "]";
    // The XML writer indexes its keyword tables with these: out of range is malformed.
    const bool image = d.type == RT_TEXTURE_IMAGE;
    t.image = image ? j.at("image").get<int>() : -1;
    if (d.type < 0 || d.type > 2 || d.decal < 0 || d.decal > 6 || d.interpolation < 0 ||
        d.interpolation > 1 || d.noise_conversion < 0 || d.noise_conversion > 1 ||
        !(d.normalizer > 0) ||
        (image && (t.image < 0 || t.image >= static_cast<int>(images.size()))))
      throw ConvertError(file + ": " + t.element + ": a value is out of range: " + j.dump());
    out.scene.textures.push_back(t);
  }
  out.scene.background_texture = scene_extras.value("backgroundTexture", -1);
  if (out.scene.background_texture >= static_cast<int>(out.scene.textures.size()))
    throw ConvertError(file + ": extras." + kExtrasKey + ".backgroundTexture names no texture");
}

}  // namespace rtconvert
