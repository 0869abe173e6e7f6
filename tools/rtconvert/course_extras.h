// The course's values that glTF cannot hold natively, kept under `extras.ceng795` of the
// glTF element they belong to (scene, camera, material, node, light), and the GLB
// container around glTF's JSON. Doubles are written in their shortest round-trip form, so
// a scene exported and imported again carries the same bits.
#pragma once

#include <nlohmann/json.hpp>
#include <string>
#include <vector>

#include "convert.h"
#include "scene/scene.h"

namespace rtconvert {

using json = nlohmann::json;

inline constexpr const char* kExtrasKey = "ceng795";

json to_json(rt::Vec3d v);
json to_json(float3 v);
json to_json(const rt::Mat4& m);
rt::Vec3d vec3d_from(const json& j);
float3 float3_from(const json& j);
rt::Mat4 mat4_from(const json& j);

json camera_to_json(const rt::CameraDesc& c);
rt::CameraDesc camera_from_json(const json& j);
json material_to_json(const Material& m);
Material material_from_json(const json& j);
json area_light_to_json(const AreaLight& a);
AreaLight area_light_from_json(const json& j);
json point_light_to_json(const PointLight& p);
PointLight point_light_from_json(const json& j);
// Directional and spot lights (SceneDesc::lights of those types), member by member.
json device_light_to_json(const Light& l);
Light device_light_from_json(const json& j);
// Background, ambient light, epsilons and recursion depth.
json settings_to_json(const rt::SceneDesc& s);
void settings_from_json(const json& j, rt::SceneDesc& s);

// The JSON of a .glb or .gltf file; a null value when the file is neither.
json read_gltf_json(const std::string& path);
// Replaces the JSON chunk of a .glb file, keeping its binary chunk; each of `blobs` (image
// files) is appended to the binary chunk as bufferView gltf["bufferViews"].size() + k,
// which the caller's JSON may already name.
void rewrite_glb_json(const std::string& path, json gltf,
                      const std::vector<std::string>& blobs = {});
// The bytes of bufferView `view` of a .glb file's binary chunk.
std::string read_glb_view(const std::string& path, const json& gltf, int view);

// Texture maps (scene extras "textures", "backgroundTexture", and "images": each image's
// bufferView and file name, for any format the course reads, not only glTF's PNG and JPEG).
json texture_to_json(const rt::TextureMapDesc& t, bool degamma);
// The course's texture maps of an rtconvert .glb, their images taken out of its binary
// chunk (written beside the XML by write_course_xml).
void textures_from_json(const json& scene_extras, const json& gltf, const std::string& file,
                        ImportedScene& out);

}  // namespace rtconvert
