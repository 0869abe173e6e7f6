// The course XML elements of materials, BRDFs, cameras, lights and textures.
#include <cmath>
#include <map>
#include <tuple>

#include "cl/material/brdf.h"
#include "xml_format.h"

namespace rtconvert {
namespace xml {

std::string text(const std::string& s) {
  std::string out;
  for (char c : s) {
    switch (c) {
      case '&':
        out += "&amp;";
        break;
      case '<':
        out += "&lt;";
        break;
      case '>':
        out += "&gt;";
        break;
      case '"':
        out += "&quot;";
        break;
      case '\'':
        out += "&apos;";
        break;
      default:
        out += c;
    }
  }
  return out;
}

namespace {

const char* brdf_name(int brdf) {
  switch (brdf) {
    case RT_BRDF_ORIGINAL_PHONG:
      return "OriginalPhong";
    case RT_BRDF_MODIFIED_BLINN_PHONG:
      return "ModifiedBlinnPhong";
    case RT_BRDF_MODIFIED_PHONG:
      return "ModifiedPhong";
    case RT_BRDF_TORRANCE_SPARROW:
      return "TorranceSparrow";
    default:
      return "OriginalBlinnPhong";
  }
}

}  // namespace

void write_brdfs_and_materials(std::ostream& x, const std::vector<Material>& materials) {
  // One BRDF per (model, flags, exponent): the loader takes the exponent from the BRDF.
  // The original Blinn-Phong without flags is what a material without BRDF has.
  std::map<std::tuple<int, int, float>, int> ids;
  for (const Material& m : materials)
    if (m.brdf != 0 || m.brdf_flags != 0)
      ids.emplace(std::make_tuple(m.brdf, m.brdf_flags, m.phong_exponent), 0);
  if (!ids.empty()) {
    x << "  <BRDFs>\n";
    int next = 1;
    for (auto& [key, id] : ids) {
      auto [brdf, flags, exponent] = key;
      id = next++;
      x << "    <" << brdf_name(brdf) << " id=\"" << id << "\""
        << ((flags & RT_BRDF_NORMALIZED) ? " normalized=\"true\"" : "")
        << ((flags & RT_BRDF_KD_FRESNEL) ? " kdfresnel=\"true\"" : "") << ">\n      <Exponent>"
        << num(exponent) << "</Exponent>\n    </" << brdf_name(brdf) << ">\n";
    }
    x << "  </BRDFs>\n";
  }
  x << "  <Materials>\n";
  for (size_t i = 0; i < materials.size(); ++i) {
    const Material& m = materials[i];
    x << "    <Material id=\"" << i + 1 << "\"";
    if (*material_type_name(m.type)) x << " type=\"" << material_type_name(m.type) << "\"";
    if (m.brdf != 0 || m.brdf_flags != 0)
      x << " BRDF=\"" << ids[std::make_tuple(m.brdf, m.brdf_flags, m.phong_exponent)] << "\"";
    x << ">\n"
      << "      <AmbientReflectance>" << vec(m.ambient) << "</AmbientReflectance>\n"
      << "      <DiffuseReflectance>" << vec(m.diffuse) << "</DiffuseReflectance>\n"
      << "      <SpecularReflectance>" << vec(m.specular) << "</SpecularReflectance>\n"
      << "      <MirrorReflectance>" << vec(m.mirror) << "</MirrorReflectance>\n"
      << "      <AbsorptionCoefficient>" << vec(m.absorption) << "</AbsorptionCoefficient>\n"
      << "      <PhongExponent>" << num(m.phong_exponent) << "</PhongExponent>\n"
      << "      <RefractionIndex>" << num(m.refraction_index) << "</RefractionIndex>\n"
      << "      <AbsorptionIndex>" << num(m.absorption_index) << "</AbsorptionIndex>\n"
      << "      <Roughness>" << num(m.roughness) << "</Roughness>\n"
      << "    </Material>\n";
  }
  x << "  </Materials>\n";
}

void write_camera(std::ostream& x, const rt::CameraDesc& c, size_t id) {
  x << "    <Camera id=\"" << id << "\"" << (c.left_handed ? " handedness=\"left\"" : "") << ">\n"
    << "      <Position>" << vec(c.position) << "</Position>\n"
    << "      <Gaze>" << vec(c.gaze) << "</Gaze>\n"
    << "      <Up>" << vec(c.up) << "</Up>\n"
    << "      <NearPlane>" << num(c.left) << " " << num(c.right) << " " << num(c.bottom) << " "
    << num(c.top) << "</NearPlane>\n"
    << "      <NearDistance>" << num(c.near_distance) << "</NearDistance>\n"
    << "      <ImageResolution>" << c.width << " " << c.height << "</ImageResolution>\n"
    << "      <NumSamples>" << c.samples << "</NumSamples>\n";
  if (c.aperture > 0)
    x << "      <ApertureSize>" << num(c.aperture) << "</ApertureSize>\n"
      << "      <FocusDistance>" << num(c.focus_distance) << "</FocusDistance>\n";
  if (c.tonemap) {
    const rt::PhotographicParams& p = c.tonemap_params;
    x << "      <Tonemap>\n        <TMO>Photographic</TMO>\n        <TMOOptions>" << num(p.key)
      << " " << num(p.burn_percent) << "</TMOOptions>\n        <Saturation>" << num(p.saturation)
      << "</Saturation>\n        <Gamma>" << num(p.gamma) << "</Gamma>\n      </Tonemap>\n";
  }
  if (c.path_tracing) {
    x << "      <Renderer>PathTracing</Renderer>\n      <RendererParams>";
    const char* sep = "";
    for (auto [flag, name] : {std::pair{RT_FLAG_NEXT_EVENT, "NextEventEstimation"},
                              std::pair{RT_FLAG_IMPORTANCE_SAMPLING, "ImportanceSampling"},
                              std::pair{RT_FLAG_RUSSIAN_ROULETTE, "RussianRoulette"}})
      if (c.path_flags & flag) {
        x << sep << name;
        sep = " ";
      }
    x << "</RendererParams>\n";
  }
  x << "      <ImageName>" << text(c.image_name) << "</ImageName>\n    </Camera>\n";
}

void write_lights(std::ostream& x, const rt::SceneDesc& s) {
  x << "  <Lights>\n    <AmbientLight>" << vec(s.ambient) << "</AmbientLight>\n";
  for (size_t i = 0; i < s.point_lights.size(); ++i)
    x << "    <PointLight id=\"" << i + 1 << "\">\n      <Position>"
      << vec(s.point_lights[i].position) << "</Position>\n      <Intensity>"
      << vec(s.point_lights[i].intensity) << "</Intensity>\n    </PointLight>\n";
  // The parallelogram dialect keeps any area light exactly: corner and two edges.
  for (size_t i = 0; i < s.area_lights.size(); ++i) {
    const AreaLight& a = s.area_lights[i];
    x << "    <AreaLight id=\"" << i + 1 << "\">\n      <Position>" << vec(a.corner)
      << "</Position>\n      <EdgeVector1>" << vec(a.edge1) << "</EdgeVector1>\n"
      << "      <EdgeVector2>" << vec(a.edge2) << "</EdgeVector2>\n      <Intensity>"
      << vec(a.radiance) << "</Intensity>\n    </AreaLight>\n";
  }
  // Directional and spot lights in the device form the loader made: the direction is
  // already unit length, the cone angles come back from their cosines.
  size_t id = s.point_lights.size() + s.area_lights.size();
  for (const Light& l : s.lights) {
    if (l.type == RT_LIGHT_DIRECTIONAL)
      x << "    <DirectionalLight id=\"" << ++id << "\">\n      <Direction>" << vec(l.normal)
        << "</Direction>\n      <Radiance>" << vec(l.emission)
        << "</Radiance>\n    </DirectionalLight>\n";
    if (l.type == RT_LIGHT_SPOT)
      x << "    <SpotLight id=\"" << ++id << "\">\n      <Position>" << vec(l.position)
        << "</Position>\n      <Direction>" << vec(l.normal) << "</Direction>\n      <Intensity>"
        << vec(l.emission) << "</Intensity>\n      <CoverageAngle>"
        << num(std::acos(static_cast<double>(RT_SPOT_COS_COVERAGE(&l))) * 360 / M_PI)
        << "</CoverageAngle>\n      <FalloffAngle>"
        << num(std::acos(static_cast<double>(RT_SPOT_COS_FALLOFF(&l))) * 360 / M_PI)
        << "</FalloffAngle>\n    </SpotLight>\n";
  }
  x << "  </Lights>\n";
}

void write_textures(std::ostream& x, const ImportedScene& in,
                    const std::vector<std::string>& image_names) {
  const rt::SceneDesc& s = in.scene;
  if (s.textures.empty()) return;
  x << "  <Textures>\n    <Images>\n";
  for (size_t i = 0; i < image_names.size(); ++i)
    x << "      <Image id=\"" << i + 1 << "\">" << text(image_names[i]) << "</Image>\n";
  x << "    </Images>\n";
  static const char* kTypes[] = {"image", "perlin", "checkerboard"};
  static const char* kDecals[] = {"replace_kd",         "blend_kd",       "replace_ks",
                                  "replace_background", "replace_normal", "bump_normal",
                                  "replace_all"};
  for (size_t i = 0; i < s.textures.size(); ++i) {
    const TextureDesc& d = s.textures[i].desc;
    const bool image = d.type == RT_TEXTURE_IMAGE;
    x << "    <TextureMap id=\"" << i + 1 << "\" type=\"" << kTypes[d.type] << "\""
      << (image && in.images[s.textures[i].image].degamma ? " degamma=\"true\"" : "") << ">\n";
    if (image) x << "      <ImageId>" << s.textures[i].image + 1 << "</ImageId>\n";
    x << "      <DecalMode>" << kDecals[d.decal] << "</DecalMode>\n"
      << "      <Interpolation>" << (d.interpolation == RT_INTERP_BILINEAR ? "bilinear" : "nearest")
      << "</Interpolation>\n      <Normalizer>" << num(d.normalizer) << "</Normalizer>\n"
      << "      <BumpFactor>" << num(d.bump_factor) << "</BumpFactor>\n"
      << "      <NoiseScale>" << num(d.noise_scale) << "</NoiseScale>\n"
      << "      <NoiseConversion>" << (d.noise_conversion == RT_NOISE_ABSVAL ? "absval" : "linear")
      << "</NoiseConversion>\n      <Scale>" << num(d.checker_scale) << "</Scale>\n"
      << "      <Offset>" << num(d.checker_offset) << "</Offset>\n"
      << "      <BlackColor>" << vec(d.black) << "</BlackColor>\n"
      << "      <WhiteColor>" << vec(d.white) << "</WhiteColor>\n    </TextureMap>\n";
  }
  x << "  </Textures>\n";
}

}  // namespace xml
}  // namespace rtconvert
