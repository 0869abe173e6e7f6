// The course's texture maps in a glTF file's extras, their images in its binary chunk.
#include <cctype>
#include <map>

#include "course_extras.h"

namespace rtconvert {

json texture_to_json(const rt::TextureMapDesc& t, int gltf_image, bool degamma) {
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
          {"image", gltf_image},
          {"degamma", degamma}};
}

void textures_from_json(const json& scene_extras, const json& gltf, const std::string& file,
                        ImportedScene& out) {
  std::map<std::pair<int, bool>, int> images;  // (glTF image, degamma) -> out.images.
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
    t.element = "extras texture " + std::to_string(out.scene.textures.size());
    const int gi = j.at("image").get<int>();
    if (d.type == RT_TEXTURE_IMAGE) {
      const bool degamma = j.at("degamma").get<bool>();
      auto [it, fresh] = images.emplace(std::make_pair(gi, degamma), out.images.size());
      if (fresh) {
        const json& image = gltf.at("images").at(gi);
        ImageFile f;
        f.bytes = read_glb_view(file, gltf, image.at("bufferView").get<int>());
        // The name becomes a file name: only letters, digits, '-' and '_' (no '..', no '/').
        std::string name = image.value("name", "");
        for (char& c : name)
          if (!std::isalnum(static_cast<unsigned char>(c)) && c != '-') c = '_';
        if (name.empty()) name = "image" + std::to_string(gi);
        f.name =
            name.substr(0, 60) + (image.value("mimeType", "") == "image/jpeg" ? ".jpg" : ".png");
        f.degamma = degamma;
        out.images.push_back(f);
      }
      t.image = it->second;
    }
    out.scene.textures.push_back(t);
  }
  out.scene.background_texture = scene_extras.value("backgroundTexture", -1);
}

}  // namespace rtconvert
