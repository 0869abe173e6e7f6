#include "course_extras.h"

#include <cstdint>
#include <cstring>
#include <fstream>
#include <iterator>

#include "convert.h"

namespace rtconvert {

json to_json(rt::Vec3d v) { return json::array({v.x, v.y, v.z}); }
json to_json(float3 v) { return json::array({v.x, v.y, v.z}); }
json to_json(const rt::Mat4& m) { return json(m.m); }
rt::Vec3d vec3d_from(const json& j) {
  return {j.at(0).get<double>(), j.at(1).get<double>(), j.at(2).get<double>()};
}
float3 float3_from(const json& j) {
  return make_float3(j.at(0).get<float>(), j.at(1).get<float>(), j.at(2).get<float>());
}
rt::Mat4 mat4_from(const json& j) {
  rt::Mat4 m;
  for (int i = 0; i < 16; ++i) m.m[i] = j.at(i).get<double>();
  return m;
}

json camera_to_json(const rt::CameraDesc& c) {
  return {{"imageName", c.image_name},
          {"position", to_json(c.position)},
          {"gaze", to_json(c.gaze)},
          {"up", to_json(c.up)},
          {"nearPlane", {c.left, c.right, c.bottom, c.top}},
          {"nearDistance", c.near_distance},
          {"resolution", {c.width, c.height}},
          {"numSamples", c.samples},
          {"apertureSize", c.aperture},
          {"focusDistance", c.focus_distance},
          {"leftHanded", c.left_handed},
          {"tonemap", c.tonemap},
          {"tonemapKey", c.tonemap_params.key},
          {"tonemapBurnPercent", c.tonemap_params.burn_percent},
          {"tonemapSaturation", c.tonemap_params.saturation},
          {"tonemapGamma", c.tonemap_params.gamma},
          {"pathTracing", c.path_tracing},
          {"pathFlags", c.path_flags}};
}

rt::CameraDesc camera_from_json(const json& j) {
  rt::CameraDesc c;
  c.image_name = j.at("imageName").get<std::string>();
  c.position = vec3d_from(j.at("position"));
  c.gaze = vec3d_from(j.at("gaze"));
  c.up = vec3d_from(j.at("up"));
  const json& np = j.at("nearPlane");
  c.left = np.at(0).get<double>();
  c.right = np.at(1).get<double>();
  c.bottom = np.at(2).get<double>();
  c.top = np.at(3).get<double>();
  c.near_distance = j.at("nearDistance").get<double>();
  c.width = j.at("resolution").at(0).get<int>();
  c.height = j.at("resolution").at(1).get<int>();
  c.samples = j.at("numSamples").get<int>();
  c.aperture = j.at("apertureSize").get<double>();
  c.focus_distance = j.at("focusDistance").get<double>();
  // Files of rtconvert before these were kept lack them: the loader's defaults.
  c.left_handed = j.value("leftHanded", false);
  c.tonemap = j.value("tonemap", false);
  c.tonemap_params.key = j.value("tonemapKey", c.tonemap_params.key);
  c.tonemap_params.burn_percent = j.value("tonemapBurnPercent", c.tonemap_params.burn_percent);
  c.tonemap_params.saturation = j.value("tonemapSaturation", c.tonemap_params.saturation);
  c.tonemap_params.gamma = j.value("tonemapGamma", c.tonemap_params.gamma);
  c.path_tracing = j.value("pathTracing", false);
  c.path_flags = j.value("pathFlags", 0);
  return c;
}

json material_to_json(const Material& m) {
  const std::string type = material_type_name(m.type);
  return {{"type", type.empty() ? "plain" : type},
          {"ambientReflectance", to_json(m.ambient)},
          {"diffuseReflectance", to_json(m.diffuse)},
          {"specularReflectance", to_json(m.specular)},
          {"mirrorReflectance", to_json(m.mirror)},
          {"absorptionCoefficient", to_json(m.absorption)},
          {"phongExponent", m.phong_exponent},
          {"refractionIndex", m.refraction_index},
          {"absorptionIndex", m.absorption_index},
          {"roughness", m.roughness},
          {"brdf", m.brdf},
          {"brdfFlags", m.brdf_flags}};
}

Material material_from_json(const json& j) {
  Material m{};
  m.type = material_type_from_name(j.at("type").get<std::string>());
  m.ambient = float3_from(j.at("ambientReflectance"));
  m.diffuse = float3_from(j.at("diffuseReflectance"));
  m.specular = float3_from(j.at("specularReflectance"));
  m.mirror = float3_from(j.at("mirrorReflectance"));
  m.absorption = float3_from(j.at("absorptionCoefficient"));
  m.phong_exponent = j.at("phongExponent").get<float>();
  m.refraction_index = j.at("refractionIndex").get<float>();
  m.absorption_index = j.at("absorptionIndex").get<float>();
  m.roughness = j.at("roughness").get<float>();
  m.brdf = j.value("brdf", 0);
  m.brdf_flags = j.value("brdfFlags", 0);
  // The XML writer names the model and flags from these: anything else is malformed.
  if (m.brdf < 0 || m.brdf > 4 || m.brdf_flags < 0 || m.brdf_flags > 3)
    throw ConvertError("extras: material brdf " + std::to_string(m.brdf) + ", brdfFlags " +
                       std::to_string(m.brdf_flags) + " name no BRDF of the course");
  return m;
}

json area_light_to_json(const AreaLight& a) {
  return {{"corner", to_json(a.corner)},     {"edge1", to_json(a.edge1)},
          {"edge2", to_json(a.edge2)},       {"normal", to_json(a.normal)},
          {"radiance", to_json(a.radiance)}, {"area", a.area}};
}

AreaLight area_light_from_json(const json& j) {
  AreaLight a{};
  a.corner = vec3d_from(j.at("corner"));
  a.edge1 = float3_from(j.at("edge1"));
  a.edge2 = float3_from(j.at("edge2"));
  a.normal = float3_from(j.at("normal"));
  a.radiance = float3_from(j.at("radiance"));
  a.area = j.at("area").get<float>();
  return a;
}

json point_light_to_json(const PointLight& p) {
  return {{"position", to_json(p.position)}, {"intensity", to_json(p.intensity)}};
}

PointLight point_light_from_json(const json& j) {
  PointLight p{};
  p.position = vec3d_from(j.at("position"));
  p.intensity = float3_from(j.at("intensity"));
  return p;
}

json device_light_to_json(const Light& l) {
  return {{"type", l.type == RT_LIGHT_SPOT ? "spot" : "directional"},
          {"position", to_json(l.position)},
          {"direction", to_json(l.normal)},
          {"emission", to_json(l.emission)},
          {"cosFalloff", RT_SPOT_COS_FALLOFF(&l)},
          {"cosCoverage", RT_SPOT_COS_COVERAGE(&l)}};
}

Light device_light_from_json(const json& j) {
  Light l{};
  const std::string type = j.at("type").get<std::string>();
  if (type != "spot" && type != "directional")
    throw ConvertError("extras: light type '" + type + "' is neither spot nor directional");
  l.type = type == "spot" ? RT_LIGHT_SPOT : RT_LIGHT_DIRECTIONAL;
  l.position = float3_from(j.at("position"));
  l.normal = float3_from(j.at("direction"));
  l.emission = float3_from(j.at("emission"));
  if (l.type == RT_LIGHT_SPOT) {
    RT_SPOT_COS_FALLOFF(&l) = j.at("cosFalloff").get<float>();
    RT_SPOT_COS_COVERAGE(&l) = j.at("cosCoverage").get<float>();
  }
  return l;
}

json settings_to_json(const rt::SceneDesc& s) {
  return {{"backgroundColor", to_json(s.background)},
          {"ambientLight", to_json(s.ambient)},
          {"shadowRayEpsilon", s.shadow_epsilon},
          {"intersectionTestEpsilon", s.intersection_epsilon},
          {"maxRecursionDepth", s.max_depth}};
}

void settings_from_json(const json& j, rt::SceneDesc& s) {
  s.background = vec3d_from(j.at("backgroundColor"));
  s.ambient = vec3d_from(j.at("ambientLight"));
  s.shadow_epsilon = j.at("shadowRayEpsilon").get<double>();
  s.intersection_epsilon = j.at("intersectionTestEpsilon").get<double>();
  s.max_depth = j.at("maxRecursionDepth").get<int>();
}

namespace {

constexpr uint32_t kGlbMagic = 0x46546C67;   // "glTF"
constexpr uint32_t kChunkJson = 0x4E4F534A;  // "JSON"

uint32_t u32(const std::string& b, size_t at) {
  uint32_t v;
  std::memcpy(&v, b.data() + at, 4);
  return v;
}

std::string read_all(const std::string& path) {
  std::ifstream in(path, std::ios::binary);
  if (!in) throw ConvertError(path + ": cannot open");
  return std::string(std::istreambuf_iterator<char>(in), {});
}

}  // namespace

json read_gltf_json(const std::string& path) {
  std::string ext = path.substr(path.find_last_of('.') + 1);
  for (char& c : ext) c = static_cast<char>(std::tolower(static_cast<unsigned char>(c)));
  if (ext != "glb" && ext != "gltf") return nullptr;
  std::string bytes = read_all(path);
  std::string text = bytes;
  if (bytes.size() >= 20 && u32(bytes, 0) == kGlbMagic) {
    uint32_t length = u32(bytes, 12);
    if (u32(bytes, 16) != kChunkJson || 20 + static_cast<size_t>(length) > bytes.size())
      throw ConvertError(path + ": GLB: the first chunk is not a complete JSON chunk");
    text = bytes.substr(20, length);
  }
  json j = json::parse(text, nullptr, false);
  if (j.is_discarded()) throw ConvertError(path + ": glTF: the JSON does not parse");
  return j;
}

void rewrite_glb_json(const std::string& path, json gltf, const std::vector<std::string>& blobs) {
  std::string bytes = read_all(path);
  if (bytes.size() < 20 || u32(bytes, 0) != kGlbMagic || u32(bytes, 16) != kChunkJson)
    throw ConvertError(path + ": Assimp wrote no GLB JSON chunk");
  std::string rest = bytes.substr(20 + u32(bytes, 12));  // The binary chunk, if any.
  auto put = [](std::string& out, uint32_t v) { out.append(reinterpret_cast<char*>(&v), 4); };
  if (!blobs.empty()) {
    // The binary chunk is buffer 0; the blobs go after its data, each 4-byte aligned.
    std::string data = rest.size() >= 8 ? rest.substr(8, u32(rest, 0)) : std::string();
    if (!gltf.contains("buffers") || gltf["buffers"].empty()) gltf["buffers"] = {json::object()};
    for (const std::string& blob : blobs) {
      while (data.size() % 4) data += '\0';
      gltf["bufferViews"].push_back(
          {{"buffer", 0}, {"byteOffset", data.size()}, {"byteLength", blob.size()}});
      data += blob;
    }
    while (data.size() % 4) data += '\0';
    gltf["buffers"][0]["byteLength"] = data.size();
    rest.clear();
    put(rest, static_cast<uint32_t>(data.size()));
    put(rest, 0x004E4942);  // "BIN"
    rest += data;
  }
  std::string text = gltf.dump();
  while (text.size() % 4) text += ' ';  // Chunks are 4-byte aligned, JSON padded with spaces.
  std::string out;
  put(out, kGlbMagic);
  put(out, 2);
  put(out, static_cast<uint32_t>(12 + 8 + text.size() + rest.size()));
  put(out, static_cast<uint32_t>(text.size()));
  put(out, kChunkJson);
  out += text + rest;
  write_file_atomically(path, out);
}

std::string read_glb_view(const std::string& path, const json& gltf, int view) {
  const json& v = gltf.at("bufferViews").at(view);
  if (v.value("buffer", 0) != 0)
    throw ConvertError(path + ": glTF bufferView " + std::to_string(view) + " is not in the GLB");
  std::string bytes = read_all(path);
  if (bytes.size() < 20 || u32(bytes, 0) != kGlbMagic)
    throw ConvertError(path + ": glTF images outside a GLB container are not read");
  size_t bin = 20 + u32(bytes, 12);
  size_t offset = v.value("byteOffset", size_t{0}), length = v.at("byteLength").get<size_t>();
  if (bin + 8 > bytes.size() || offset + length > u32(bytes, bin))
    throw ConvertError(path + ": glTF bufferView " + std::to_string(view) +
                       " lies outside the binary chunk");
  return bytes.substr(bin + 8 + offset, length);
}

}  // namespace rtconvert
