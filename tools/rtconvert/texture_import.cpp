#include "texture_import.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <filesystem>

#include "image/read_hdr.h"

namespace rtconvert {
namespace {

namespace fs = std::filesystem;

std::string lower(std::string s) {
  for (char& c : s) c = static_cast<char>(std::tolower(static_cast<unsigned char>(c)));
  return s;
}

// The renderer reads PNG and JPEG (and HDR files, which colour maps are not).
bool readable_format(const std::string& extension) {
  const std::string e = lower(extension);
  return e == "png" || e == "jpg" || e == "jpeg";
}

std::string safe_name(std::string s) {
  for (char& c : s)
    if (!std::isalnum(static_cast<unsigned char>(c)) && c != '-' && c != '_' && c != '.') c = '_';
  return s.empty() ? std::string("texture") : s.substr(0, 60);
}

}  // namespace

int wrap_texture_coordinates(rt::MeshDesc& mesh) {
  int outside = 0;
  std::vector<rt::Vec3d> positions;
  std::vector<std::array<double, 2>> uvs;
  std::map<std::array<long, 3>, int> copy;  // (vertex, shift u, shift v) -> new vertex.
  for (auto& tri : mesh.triangles) {
    long shift[2];
    for (int a = 0; a < 2; ++a) {
      double lo = 1e300, hi = -1e300;
      for (int k = 0; k < 3; ++k) {
        lo = std::min(lo, mesh.uvs[tri[k]][a]);
        hi = std::max(hi, mesh.uvs[tri[k]][a]);
      }
      shift[a] = lo >= 0 && hi <= 1 ? 0 : static_cast<long>(std::floor(lo));
      outside += hi - shift[a] > 1 + 1e-6 && a == 0;
    }
    for (int k = 0; k < 3; ++k) {
      auto [it, added] =
          copy.emplace(std::array<long, 3>{tri[k], shift[0], shift[1]}, positions.size());
      if (added) {
        positions.push_back(mesh.positions[tri[k]]);
        uvs.push_back({mesh.uvs[tri[k]][0] - shift[0], mesh.uvs[tri[k]][1] - shift[1]});
      }
      tri[k] = it->second;
    }
  }
  mesh.positions.swap(positions);
  mesh.uvs.swap(uvs);
  return outside;
}

// An image file or embedded image, checked to be one the renderer decodes; -1 (and a
// warning) when it is not.
int TextureImporter::image_of(const std::string& where, const std::string& path, bool degamma) {
  auto known = images_.find({path, degamma});
  if (known != images_.end()) return known->second;
  ImageFile f;
  f.degamma = degamma;
  if (const aiTexture* t = ai_.GetEmbeddedTexture(path.c_str())) {
    if (t->mHeight != 0 || !readable_format(t->achFormatHint)) {
      report_.warn(where + "embedded texture '" + path + "' is not PNG or JPEG: dropped");
      return images_[{path, degamma}] = -1;
    }
    f.bytes.assign(reinterpret_cast<const char*>(t->pcData), t->mWidth);
    std::string stem = fs::path(t->mFilename.C_Str()).stem().string();
    if (stem.empty()) stem = "texture" + std::to_string(out_.images.size());
    f.name = safe_name(stem) + "." + lower(t->achFormatHint);
  } else {
    // Relative to the model; files written on Windows may use backslashes.
    std::string p = path;
    std::replace(p.begin(), p.end(), '\\', '/');
    fs::path full(p);
    if (full.is_relative()) full = fs::path(file_).parent_path() / full;
    full = full.lexically_normal();
    // Files often name the image where it was on the author's disc ("D:/models/wood.jpg"):
    // the same name beside the model is what was meant.
    std::error_code ec;
    fs::path beside = fs::path(file_).parent_path() / full.filename();
    if (!fs::exists(full, ec) && fs::exists(beside, ec)) full = beside;
    const std::string extension = full.extension().string();  // ".png", or "".
    if (!readable_format(extension.empty() ? extension : extension.substr(1))) {
      report_.warn(where + "texture '" + path + "' is not PNG or JPEG: dropped");
      return images_[{path, degamma}] = -1;
    }
    try {
      rt::read_any_image(full.string());  // Decodes, so a broken file warns here, not later.
    } catch (const std::exception& e) {
      report_.warn(where + "texture dropped: " + e.what());
      return images_[{path, degamma}] = -1;
    }
    f.path = full.string();
  }
  out_.images.push_back(f);
  return images_[{path, degamma}] = static_cast<int>(out_.images.size()) - 1;
}

// A replace_kd or replace_ks map for the first texture of `type`. The other formats
// multiply the texture by the constant colour; the course replaces the colour by
// texture / Normalizer, which is the same product for a grey factor k with Normalizer
// 255 / k.
int TextureImporter::map_of(const std::string& where, aiTextureType type, float3 factor) {
  aiString path;
  aiTextureMapping mapping = aiTextureMapping_UV;
  unsigned uv_index = 0;
  if (material_->GetTexture(type, 0, &path, &mapping, &uv_index) != AI_SUCCESS) return -1;
  const std::string kind = aiTextureTypeToString(type);
  if (mapping != aiTextureMapping_UV || uv_index != 0) {
    report_.warn(where + kind + " texture '" + path.C_Str() +
                 "' uses a projection or a second UV set: dropped");
    return -1;
  }
  const float peak = std::max({factor.x, factor.y, factor.z}),
              low = std::min({factor.x, factor.y, factor.z});
  if (!(peak > 0)) return -1;  // Black times anything: the constant colour is right.
  if (peak - low > 1e-6f * peak)
    report_.warn(where + kind + " texture '" + path.C_Str() +
                 "': the colour factor is not grey; its largest component scales the texture");
  const int image = image_of(where, path.C_Str(), srgb_);
  if (image < 0) return -1;
  rt::TextureMapDesc t;
  t.element = where + kind + " texture";
  t.desc.type = RT_TEXTURE_IMAGE;
  t.desc.decal = type == aiTextureType_SPECULAR ? RT_DECAL_REPLACE_KS : RT_DECAL_REPLACE_KD;
  t.desc.interpolation = RT_INTERP_BILINEAR;  // Viewers filter linearly.
  t.desc.normalizer = 255.0f / peak;
  t.desc.bump_factor = t.desc.noise_scale = t.desc.checker_scale = 1;
  t.desc.white = make_float3(1, 1, 1);
  t.image = image;
  auto& maps = out_.scene.textures;
  for (size_t i = 0; i < maps.size(); ++i)
    if (maps[i].image == image && maps[i].desc.decal == t.desc.decal &&
        maps[i].desc.normalizer == t.desc.normalizer)
      return static_cast<int>(i);
  maps.push_back(t);
  return static_cast<int>(maps.size()) - 1;
}

const std::vector<int>& TextureImporter::maps_of(unsigned ai_index, const MappedMaterial& mat) {
  auto it = maps_.find(ai_index);
  if (it != maps_.end()) return it->second;
  std::vector<int>& out = maps_[ai_index];
  material_ = ai_.mMaterials[ai_index];
  const std::string where = file_ + ": material '" + mat.name + "': ";
  const Material& m = mat.material;
  const bool colour_used = m.type == RT_MATERIAL_PLAIN || m.type == RT_MATERIAL_MIRROR;
  bool diffuse_done = false;
  for (aiTextureType type : {aiTextureType_BASE_COLOR, aiTextureType_DIFFUSE}) {
    if (material_->GetTextureCount(type) == 0 || diffuse_done) continue;
    diffuse_done = true;  // glTF files list their base colour map under both types.
    if (!colour_used) {
      report_.warn(where + "colour texture on a " + material_type_name(m.type) +
                   " material: dropped");
      continue;
    }
    if (int t = map_of(where, type, m.diffuse); t >= 0) out.push_back(t);
  }
  if (material_->GetTextureCount(aiTextureType_SPECULAR) > 0 && colour_used)
    if (int t = map_of(where, aiTextureType_SPECULAR, m.specular); t >= 0) out.push_back(t);
  // The rest (normal, bump, roughness, metalness, emission, occlusion, opacity maps and
  // glTF's metallicRoughness, which Assimp calls "unknown") have no course counterpart.
  for (int type = aiTextureType_NONE + 1; type <= AI_TEXTURE_TYPE_MAX; ++type) {
    const auto t = static_cast<aiTextureType>(type);
    if (t == aiTextureType_BASE_COLOR || t == aiTextureType_DIFFUSE ||
        (t == aiTextureType_SPECULAR && colour_used))
      continue;
    for (unsigned k = 0; k < material_->GetTextureCount(t); ++k) {
      aiString path;
      material_->GetTexture(t, k, &path);
      report_.warn(where + aiTextureTypeToString(t) + " texture '" + path.C_Str() +
                   "' has no course counterpart: dropped");
    }
  }
  return out;
}

}  // namespace rtconvert
