// Image textures of an imported file as the course's TextureMaps: a diffuse or base colour
// map becomes replace_kd, a specular map replace_ks; every other kind warns and is dropped.
#pragma once

#include <assimp/scene.h>

#include <map>
#include <string>
#include <vector>

#include "convert.h"
#include "material_map.h"

namespace rtconvert {

// The other formats repeat a texture outside [0, 1]^2, the course clamps to the edge
// texels. Each triangle whose coordinates leave [0, 1] is moved by whole repeats to start
// in [0, 1) (its vertices copied where triangles sharing them move differently); returns
// the number of triangles still outside, which span more than one repeat.
int wrap_texture_coordinates(rt::MeshDesc& mesh);

class TextureImporter {
 public:
  // `srgb`: the file's colour textures are sRGB-encoded (glTF says so), so the maps get
  // degamma="true", the course's gamma-2.2 decoding.
  TextureImporter(const aiScene& ai, const std::string& file, bool srgb, ImportedScene& out,
                  Report& report)
      : ai_(ai), file_(file), srgb_(srgb), out_(out), report_(report) {}

  // The TextureMaps (indices into out.scene.textures) of Assimp material `ai_index`,
  // mapped as `mat`; made on first use, empty when it has none the course can render.
  const std::vector<int>& maps_of(unsigned ai_index, const MappedMaterial& mat);

 private:
  int image_of(const std::string& where, const std::string& path, bool degamma);
  int map_of(const std::string& where, aiTextureType type, float3 factor);

  const aiScene& ai_;
  std::string file_;
  bool srgb_;
  ImportedScene& out_;
  Report& report_;
  std::map<unsigned, std::vector<int>> maps_;
  std::map<std::pair<std::string, bool>, int> images_;  // (source, degamma) -> image.
  const aiMaterial* material_ = nullptr;
};

}  // namespace rtconvert
