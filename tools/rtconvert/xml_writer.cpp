// Writes a SceneDesc as course XML that rt::load_scene reads back into the same values:
// doubles are printed with 17 significant digits and floats with 9, both of which round
// trip exactly, and every object's composed transform becomes one <Composite> matrix.
// Large meshes and images taken out of the input go to the folder OUT_files beside it.
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <set>
#include <sstream>

#include "io/file_util.h"
#include "xml_format.h"

namespace rtconvert {
namespace {

using rt::Vec3d;
using xml::num;
using xml::vec;

// Meshes up to this many triangles are written inline; larger ones as binary PLY.
constexpr size_t kInlineTriangles = 100;

// Binary PLY, with u v per vertex when the mesh has texture coordinates.
std::string ply_bytes(const rt::MeshDesc& mesh) {
  std::ostringstream out;
  const bool uvs = !mesh.uvs.empty();
  out << "ply\nformat binary_little_endian 1.0\ncomment written by rtconvert\nelement vertex "
      << mesh.positions.size() << "\nproperty float x\nproperty float y\nproperty float z\n"
      << (uvs ? "property float u\nproperty float v\n" : "") << "element face "
      << mesh.triangles.size() << "\nproperty list uchar int vertex_indices\nend_header\n";
  for (size_t i = 0; i < mesh.positions.size(); ++i) {
    const Vec3d& p = mesh.positions[i];
    float v[5] = {static_cast<float>(p.x), static_cast<float>(p.y), static_cast<float>(p.z), 0, 0};
    if (uvs) {
      v[3] = static_cast<float>(mesh.uvs[i][0]);
      v[4] = static_cast<float>(mesh.uvs[i][1]);
    }
    out.write(reinterpret_cast<const char*>(v), (uvs ? 5 : 3) * sizeof(float));
  }
  for (const auto& t : mesh.triangles) {
    const unsigned char n = 3;
    out.write(reinterpret_cast<const char*>(&n), 1);
    out.write(reinterpret_cast<const char*>(t.data()), 3 * sizeof(int));
  }
  return out.str();
}

// The files that go beside the XML, gathered while the XML is written and written only
// once the whole conversion's files are checked against its inputs (check_conversion_files),
// so that a refused conversion writes nothing; removed again when a later write fails.
class SideFiles {
 public:
  explicit SideFiles(const std::string& xml_path)
      : folder_(side_folder(xml_path)), name_(std::filesystem::path(folder_).filename().string()) {}
  ~SideFiles() {
    if (done_) return;
    for (const auto& f : written_) std::remove(f.c_str());
    std::error_code ec;
    if (created_) std::filesystem::remove(folder_, ec);  // Only when empty.
  }
  // Plans `bytes` as `file` in the folder; returns the name the XML uses.
  std::string add(const std::string& file, std::string bytes, const char* what) {
    planned_.push_back({(std::filesystem::path(folder_) / file).string(), what});
    bytes_.push_back(std::move(bytes));
    return name_ + "/" + file;
  }
  const std::vector<PlannedFile>& planned() const { return planned_; }
  void write_all() {
    std::error_code ec;
    if (!planned_.empty() && !std::filesystem::is_directory(folder_, ec)) {
      if (!std::filesystem::create_directory(folder_, ec))
        throw ConvertError(folder_ + ": cannot create the folder for the meshes and images");
      created_ = true;
    }
    for (size_t i = 0; i < planned_.size(); ++i) {
      write_file_atomically(planned_[i].path, bytes_[i]);
      written_.push_back(planned_[i].path);
      std::string().swap(bytes_[i]);
    }
  }
  void keep() { done_ = true; }

 private:
  std::string folder_, name_;
  std::vector<PlannedFile> planned_;
  std::vector<std::string> bytes_;
  std::vector<std::string> written_;
  bool created_ = false, done_ = false;
};

// The Image file names as the XML names them: files of the input relative to the XML's
// folder where possible, embedded images written into the side folder.
std::vector<std::string> image_names(const std::vector<ImageFile>& images,
                                     const std::string& xml_path, SideFiles& side) {
  namespace fs = std::filesystem;
  std::vector<std::string> out;
  std::set<std::string> taken;
  const fs::path dir = fs::absolute(fs::path(xml_path)).parent_path();
  for (const ImageFile& f : images) {
    if (f.bytes.empty()) {
      std::error_code ec;
      fs::path rel = fs::relative(fs::absolute(f.path), dir, ec);
      out.push_back(ec || rel.empty() ? fs::absolute(f.path).string() : rel.generic_string());
      continue;
    }
    // Names are told apart with letter case folded: one file where the file system folds it.
    std::string name = f.name;
    for (int k = 2; !taken.insert(rt::same_file_key(name)).second; ++k)
      name = fs::path(f.name).stem().string() + "_" + std::to_string(k) +
             fs::path(f.name).extension().string();
    out.push_back(side.add(name, f.bytes, "image"));
  }
  return out;
}

// PLY stores floats: a mesh whose positions are not all floats goes inline instead.
bool float_exact(const rt::MeshDesc& mesh) {
  for (const Vec3d& p : mesh.positions)
    if (static_cast<float>(p.x) != p.x || static_cast<float>(p.y) != p.y ||
        static_cast<float>(p.z) != p.z)
      return false;
  return true;
}

}  // namespace

void write_course_xml(const ImportedScene& in, const std::string& xml_path, Report& report,
                      const std::vector<std::string>& inputs) {
  const rt::SceneDesc& s = in.scene;
  SideFiles side(xml_path);
  std::ostringstream x;
  x << "<Scene>\n  <!-- written by rtconvert -->\n"
    << "  <BackgroundColor>" << vec(s.background) << "</BackgroundColor>\n"
    << "  <ShadowRayEpsilon>" << num(s.shadow_epsilon) << "</ShadowRayEpsilon>\n"
    << "  <IntersectionTestEpsilon>" << num(s.intersection_epsilon)
    << "</IntersectionTestEpsilon>\n"
    << "  <MaxRecursionDepth>" << s.max_depth << "</MaxRecursionDepth>\n  <Cameras>\n";
  for (size_t i = 0; i < s.cameras.size(); ++i) xml::write_camera(x, s.cameras[i], i + 1);
  x << "  </Cameras>\n";
  xml::write_lights(x, s);
  xml::write_brdfs_and_materials(x, s.materials);
  xml::write_textures(x, in, image_names(in.images, xml_path, side));
  x << "  <Transformations>\n";
  for (size_t i = 0; i < s.objects.size(); ++i) {
    if (s.objects[i].transform.is_identity()) continue;
    x << "    <Composite id=\"" << i + 1 << "\">";
    for (int k = 0; k < 16; ++k) x << (k ? " " : "") << num(s.objects[i].transform.m[k]);
    x << "</Composite>\n";
  }
  // Vertex 1 is the centre of every sphere (the transform carries centre and radius);
  // inline meshes follow. TexCoordData pairs with VertexData entry for entry.
  std::vector<long> inline_offset(s.meshes.size(), -1);
  std::ostringstream vertices, uvs;
  vertices << "    0 0 0\n";
  uvs << "    0 0\n";
  bool any_uvs = false;
  long next_vertex = 1;  // The spheres' centre.
  for (size_t m = 0; m < s.meshes.size(); ++m) {
    const rt::MeshDesc& mesh = s.meshes[m];
    if (mesh.triangles.size() > kInlineTriangles && float_exact(mesh)) continue;
    inline_offset[m] = next_vertex;  // Vertices before the mesh's first; indices are 1-based.
    for (size_t i = 0; i < mesh.positions.size(); ++i) {
      vertices << "    " << vec(mesh.positions[i]) << "\n";
      any_uvs = any_uvs || !mesh.uvs.empty();
      uvs << "    " << (mesh.uvs.empty() ? "0 0" : num(mesh.uvs[i][0]) + " " + num(mesh.uvs[i][1]))
          << "\n";
    }
    next_vertex += static_cast<long>(mesh.positions.size());
  }
  x << "  </Transformations>\n  <VertexData>\n" << vertices.str() << "  </VertexData>\n";
  if (any_uvs) x << "  <TexCoordData>\n" << uvs.str() << "  </TexCoordData>\n";
  x << "  <Objects>\n";
  std::vector<int> first_user(s.meshes.size(), -1);
  std::vector<std::string> ply_of(s.meshes.size());
  for (size_t i = 0; i < s.objects.size(); ++i) {
    const rt::ObjectDesc& o = s.objects[i];
    std::string common = "      <Material>" + std::to_string(o.material + 1) + "</Material>\n";
    if (!o.transform.is_identity())
      common += "      <Transformations>c" + std::to_string(i + 1) + "</Transformations>\n";
    if (o.motion.x != 0 || o.motion.y != 0 || o.motion.z != 0)
      common += "      <MotionBlur>" + vec(o.motion) + "</MotionBlur>\n";
    std::string textures;
    for (int t : o.textures) textures += (textures.empty() ? "" : " ") + std::to_string(t + 1);
    const std::string textures_element = "      <Textures>" + textures + "</Textures>\n";
    if (!o.textures.empty()) common += textures_element;
    if (o.emits) common += "      <Radiance>" + vec(o.radiance) + "</Radiance>\n";
    if (o.kind == rt::ObjectDesc::kSphere) {
      const char* tag = o.emits ? "LightSphere" : "Sphere";
      x << "    <" << tag << " id=\"" << i + 1 << "\">\n"
        << common << "      <Center>1</Center>\n      <Radius>1</Radius>\n    </" << tag << ">\n";
      continue;
    }
    // Instances take the base's emission: object lights are written out in full (their
    // geometry shared through vertexOffset or the same PLY file).
    const int base = first_user[o.mesh];
    if (base >= 0 && !o.emits && !s.objects[base].emits) {
      // The base's transform is replaced, not composed: the matrix is already complete.
      x << "    <MeshInstance id=\"" << i + 1 << "\" baseMeshId=\"" << base + 1
        << "\" resetTransform=\"true\">\n"
        << common
        << (o.textures.empty() && !s.objects[base].textures.empty() ? textures_element : "")
        << "    </MeshInstance>\n";
      continue;
    }
    if (base < 0 && !o.emits) first_user[o.mesh] = static_cast<int>(i);
    const rt::MeshDesc& mesh = s.meshes[o.mesh];
    const char* tag = o.emits ? "LightMesh" : "Mesh";
    x << "    <" << tag << " id=\"" << i + 1 << "\""
      << (mesh.smooth ? " shadingMode=\"smooth\"" : "") << ">\n"
      << common;
    if (inline_offset[o.mesh] >= 0) {
      // TexCoordData is indexed by the face indices plus textureOffset, not vertexOffset.
      x << "      <Faces vertexOffset=\"" << inline_offset[o.mesh] << "\""
        << (any_uvs ? " textureOffset=\"" + std::to_string(inline_offset[o.mesh]) + "\"" : "")
        << ">\n";
      for (const auto& t : mesh.triangles)
        x << "        " << t[0] + 1 << " " << t[1] + 1 << " " << t[2] + 1 << "\n";
      x << "      </Faces>\n";
    } else {
      if (ply_of[o.mesh].empty()) {
        // The index keeps the names unique: files may give several meshes one name.
        std::string name = "mesh" + std::to_string(o.mesh + 1);
        if (in.mesh_names.size() == s.meshes.size() && !in.mesh_names[o.mesh].empty())
          name += "_" + in.mesh_names[o.mesh];
        ply_of[o.mesh] = side.add(name + ".ply", ply_bytes(mesh), "mesh");
      }
      x << "      <Faces plyFile=\"" << xml::text(ply_of[o.mesh]) << "\"/>\n";
    }
    x << "    </" << tag << ">\n";
  }
  x << "  </Objects>\n</Scene>\n";
  std::vector<PlannedFile> files{{xml_path, "output"}};
  files.insert(files.end(), side.planned().begin(), side.planned().end());
  check_conversion_files(files, inputs);
  side.write_all();
  write_file_atomically(xml_path, x.str());
  side.keep();
  (void)report;
}

void write_file_atomically(const std::string& path, const std::string& content) {
  // The project's atomic write: a temporary of a fresh name, so no file of the user's is
  // ever truncated on the way.
  if (const int err = rt::write_file_atomic(path, content.data(), content.size()))
    throw ConvertError(path + ": cannot write: " + rt::errno_text(err));
}

}  // namespace rtconvert
