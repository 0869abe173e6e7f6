// Writes a SceneDesc as course XML that rt::load_scene reads back into the same values:
// doubles are printed with 17 significant digits and floats with 9, both of which round
// trip exactly, and every object's composed transform becomes one <Composite> matrix.
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <sstream>

#include "convert.h"

namespace rtconvert {
namespace {

using rt::Vec3d;

// Meshes up to this many triangles are written inline; larger ones as binary PLY.
constexpr size_t kInlineTriangles = 100;

std::string num(double v) {
  char buf[40];
  std::snprintf(buf, sizeof buf, "%.17g", v);
  return buf;
}

std::string num(float v) {
  char buf[40];
  std::snprintf(buf, sizeof buf, "%.9g", static_cast<double>(v));
  return buf;
}

// The five characters XML reserves, escaped (an image name may hold '&').
std::string xml_text(const std::string& s) {
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

std::string vec(Vec3d v) { return num(v.x) + " " + num(v.y) + " " + num(v.z); }
std::string vec(float3 v) { return num(v.x) + " " + num(v.y) + " " + num(v.z); }

void write_ply(const rt::MeshDesc& mesh, const std::string& path) {
  std::ofstream out(path, std::ios::binary);
  if (!out) throw ConvertError(path + ": cannot write the PLY file");
  out << "ply\nformat binary_little_endian 1.0\ncomment written by rtconvert\nelement vertex "
      << mesh.positions.size() << "\nproperty float x\nproperty float y\nproperty float z\n"
      << "element face " << mesh.triangles.size()
      << "\nproperty list uchar int vertex_indices\nend_header\n";
  for (const Vec3d& p : mesh.positions) {
    float xyz[3] = {static_cast<float>(p.x), static_cast<float>(p.y), static_cast<float>(p.z)};
    out.write(reinterpret_cast<const char*>(xyz), sizeof xyz);
  }
  for (const auto& t : mesh.triangles) {
    const unsigned char n = 3;
    out.write(reinterpret_cast<const char*>(&n), 1);
    out.write(reinterpret_cast<const char*>(t.data()), 3 * sizeof(int));
  }
  if (!out) throw ConvertError(path + ": write failed");
}

// PLY stores floats: a mesh whose positions are not all floats goes inline instead.
bool float_exact(const rt::MeshDesc& mesh) {
  for (const Vec3d& p : mesh.positions)
    if (static_cast<float>(p.x) != p.x || static_cast<float>(p.y) != p.y ||
        static_cast<float>(p.z) != p.z)
      return false;
  return true;
}

void write_material(std::ostream& x, const Material& m, size_t id) {
  x << "    <Material id=\"" << id << "\"";
  if (*material_type_name(m.type)) x << " type=\"" << material_type_name(m.type) << "\"";
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
  x << "      <ImageName>" << xml_text(c.image_name) << "</ImageName>\n    </Camera>\n";
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
  x << "  </Lights>\n";
}

}  // namespace

void write_course_xml(const ImportedScene& in, const std::string& xml_path, Report& report) {
  const rt::SceneDesc& s = in.scene;
  namespace fs = std::filesystem;
  const fs::path dir = fs::path(xml_path).parent_path();
  const std::string stem = fs::path(xml_path).stem().string();
  std::ostringstream x;
  x << "<Scene>\n  <!-- written by rtconvert -->\n"
    << "  <BackgroundColor>" << vec(s.background) << "</BackgroundColor>\n"
    << "  <ShadowRayEpsilon>" << num(s.shadow_epsilon) << "</ShadowRayEpsilon>\n"
    << "  <IntersectionTestEpsilon>" << num(s.intersection_epsilon)
    << "</IntersectionTestEpsilon>\n"
    << "  <MaxRecursionDepth>" << s.max_depth << "</MaxRecursionDepth>\n  <Cameras>\n";
  for (size_t i = 0; i < s.cameras.size(); ++i) write_camera(x, s.cameras[i], i + 1);
  x << "  </Cameras>\n";
  write_lights(x, s);
  x << "  <Materials>\n";
  for (size_t i = 0; i < s.materials.size(); ++i) write_material(x, s.materials[i], i + 1);
  x << "  </Materials>\n  <Transformations>\n";
  for (size_t i = 0; i < s.objects.size(); ++i) {
    if (s.objects[i].transform.is_identity()) continue;
    x << "    <Composite id=\"" << i + 1 << "\">";
    for (int k = 0; k < 16; ++k) x << (k ? " " : "") << num(s.objects[i].transform.m[k]);
    x << "</Composite>\n";
  }
  // Vertex 1 is the centre of every sphere (the transform carries centre and radius);
  // inline meshes follow.
  x << "  </Transformations>\n  <VertexData>\n    0 0 0\n";
  std::vector<long> inline_offset(s.meshes.size(), -1);
  long next_vertex = 1;  // The spheres' centre.
  for (size_t m = 0; m < s.meshes.size(); ++m) {
    const rt::MeshDesc& mesh = s.meshes[m];
    if (mesh.triangles.size() > kInlineTriangles && float_exact(mesh)) continue;
    inline_offset[m] = next_vertex;  // Vertices before the mesh's first; indices are 1-based.
    for (const Vec3d& p : mesh.positions) x << "    " << vec(p) << "\n";
    next_vertex += static_cast<long>(mesh.positions.size());
  }
  x << "  </VertexData>\n  <Objects>\n";
  std::vector<int> first_user(s.meshes.size(), -1);
  for (size_t i = 0; i < s.objects.size(); ++i) {
    const rt::ObjectDesc& o = s.objects[i];
    std::string common = "      <Material>" + std::to_string(o.material + 1) + "</Material>\n";
    if (!o.transform.is_identity())
      common += "      <Transformations>c" + std::to_string(i + 1) + "</Transformations>\n";
    if (o.motion.x != 0 || o.motion.y != 0 || o.motion.z != 0)
      common += "      <MotionBlur>" + vec(o.motion) + "</MotionBlur>\n";
    if (o.kind == rt::ObjectDesc::kSphere) {
      x << "    <Sphere id=\"" << i + 1 << "\">\n"
        << common << "      <Center>1</Center>\n      <Radius>1</Radius>\n    </Sphere>\n";
      continue;
    }
    if (first_user[o.mesh] >= 0) {
      // The base's transform is replaced, not composed: the matrix is already complete.
      x << "    <MeshInstance id=\"" << i + 1 << "\" baseMeshId=\"" << first_user[o.mesh] + 1
        << "\" resetTransform=\"true\">\n"
        << common << "    </MeshInstance>\n";
      continue;
    }
    first_user[o.mesh] = static_cast<int>(i);
    const rt::MeshDesc& mesh = s.meshes[o.mesh];
    x << "    <Mesh id=\"" << i + 1 << "\"" << (mesh.smooth ? " shadingMode=\"smooth\"" : "")
      << ">\n"
      << common;
    if (inline_offset[o.mesh] >= 0) {
      x << "      <Faces vertexOffset=\"" << inline_offset[o.mesh] << "\">\n";
      for (const auto& t : mesh.triangles)
        x << "        " << t[0] + 1 << " " << t[1] + 1 << " " << t[2] + 1 << "\n";
      x << "      </Faces>\n";
    } else {
      // The index keeps the names unique: files may give several meshes one name.
      std::string name = "mesh" + std::to_string(o.mesh + 1);
      if (in.mesh_names.size() == s.meshes.size() && !in.mesh_names[o.mesh].empty())
        name += "_" + in.mesh_names[o.mesh];
      std::string file = stem + "_" + name + ".ply";
      write_ply(mesh, (dir / file).string());
      x << "      <Faces plyFile=\"" << xml_text(file) << "\"/>\n";
    }
    x << "    </Mesh>\n";
  }
  x << "  </Objects>\n</Scene>\n";
  write_file_atomically(xml_path, x.str());
  (void)report;
}

void write_file_atomically(const std::string& path, const std::string& content) {
  const std::string temporary = path + ".partial";
  {
    std::ofstream out(temporary, std::ios::binary | std::ios::trunc);
    out.write(content.data(), static_cast<std::streamsize>(content.size()));
    if (!out) {
      std::remove(temporary.c_str());
      throw ConvertError(path + ": cannot write");
    }
  }
  if (std::rename(temporary.c_str(), path.c_str()) != 0) {
    std::remove(temporary.c_str());
    throw ConvertError(path + ": cannot write (rename failed)");
  }
}

}  // namespace rtconvert
