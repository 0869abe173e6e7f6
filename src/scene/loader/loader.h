// The scene loader's internal class, shared by the files of src/loader/: one file per
// family of elements (cameras, lights, materials, objects, textures), this class holding
// what they read into and the number/child helpers they share.
#pragma once

#include <tinyxml2.h>

#include <array>
#include <map>
#include <string>
#include <vector>

#include "scene/scene.h"
#include "scene/xml_text.h"
#include "util/errors.h"

namespace rt {
namespace loader {

using tinyxml2::XMLElement;

// A number as the file would write it: 3, -1.5, 1e+30.
std::string fmt(double v);

class Loader {
 public:
  Loader(std::string file, const LoadOptions& options)
      : file_(std::move(file)), options_(options) {}
  SceneDesc load();
  // Reads the scene from XML text already in memory; `file_` only names it and locates
  // the PLY files it refers to (the fuzzer feeds scenes this way).
  SceneDesc load_text(const std::string& xml);

 private:
  [[noreturn]] void fail(const XMLElement* e, const std::string& what) const {
    throw input_error(file_, e ? path_of(e) : std::string("Scene"), what);
  }
  // Quotes the element's text before `what`: "Radius: '-1' must be positive".
  [[noreturn]] void fail_value(const XMLElement* e, const std::string& what) const {
    fail(e, "'" + shorten(text_of(e)) + "' " + what);
  }

  // A file the scene names (plyFile="m.ply") failed to read: the attribute with the path it
  // resolved to (where the file was looked for), then the reader's message without the
  // path it starts with, so that the file is named once.
  [[noreturn]] void fail_file(const XMLElement* e, const char* attribute, const std::string& path,
                              const InputError& err) const {
    std::string why = err.what();
    if (why.rfind(path + ": ", 0) == 0) why.erase(0, path.size() + 2);
    if (why.rfind("file: ", 0) == 0) why.erase(0, 6);
    fail(e, std::string(attribute) + " '" + shorten(path, 200) + "': " + why);
  }

  std::vector<double> numbers(const XMLElement* e, size_t min_count, size_t max_count) const;
  double number(const XMLElement* e) const { return numbers(e, 1, 1)[0]; }
  Vec3d vec3(const XMLElement* e) const {
    auto v = numbers(e, 3, 3);
    return {v[0], v[1], v[2]};
  }
  const XMLElement* child(const XMLElement* e, const char* name, bool required) const;
  double child_number(const XMLElement* e, const char* name, double fallback) const;
  Vec3d child_vec3(const XMLElement* e, const char* name, Vec3d fallback) const;
  Vec3d nonzero(const XMLElement* e, Vec3d v, const char* what = "is a zero-length vector") const {
    if (length(v) == 0) fail_value(e, what);
    return v;
  }

  // A camera's Gaze or Up: non-zero, and with a squared length inside float's normal range,
  // because the camera is normalized in float as the course's renderer does
  // (src/prepare/course_camera.cpp); outside it the basis is 0 or Inf and the image blank.
  Vec3d camera_direction(const XMLElement* e, Vec3d v, const char* what) const;

  void read_cameras(const XMLElement* scene);
  void read_tonemap(const XMLElement* tm, CameraDesc* cam) const;
  void read_renderer(const XMLElement* camera, CameraDesc* cam) const;
  void read_lights(const XMLElement* scene);
  void read_environment_light(const XMLElement* light, const XMLElement* scene);
  void read_brdfs(const XMLElement* scene);
  void read_materials(const XMLElement* scene);
  void read_transformations(const XMLElement* scene);
  void read_vertices(const XMLElement* scene);
  void read_objects(const XMLElement* scene);
  void read_textures(const XMLElement* scene);
  TextureMapDesc read_texture_map(const XMLElement* e,
                                  const std::map<std::string, std::string>& images,
                                  std::map<std::pair<std::string, bool>, int>& loaded);
  void read_texcoords(const XMLElement* scene);
  std::vector<int> textures_of(const XMLElement* e) const;
  void check_texture_coordinates() const;
  int material_of(const XMLElement* e) const;
  Mat4 transform_of(const XMLElement* e) const;
  Vec3d motion_of(const XMLElement* e) const;
  Vec3d radiance_of(const XMLElement* e) const;
  int vertex_index(const XMLElement* e, double index, long offset = 0) const;
  // The first index of VertexData and TexCoordData: 1, or 0 with <ZeroBasedIndexing>.
  int index_base() const { return zero_based_ ? 0 : 1; }
  void read_index_base(const XMLElement* scene);
  // The numbers of e's binaryFile (see binary_data.h), `per_record` per record, as doubles.
  std::vector<double> binary_numbers(const XMLElement* e, int per_record, const char* record,
                                     bool ints);
  // e's numbers: inline text, or its binaryFile's records.
  std::vector<double> data_numbers(const XMLElement* e, int per_record, const char* record,
                                   bool ints, size_t min_count = 0);
  int add_mesh_from_faces(const XMLElement* obj, const XMLElement* faces, bool smooth, bool uvs);
  void warn(const XMLElement* e, const std::string& what) {
    warn(file_ + ": " + path_of(e) + ": " + what);
  }
  // With --strict, the first warning ends the load as an error.
  void warn(const std::string& line) {
    if (options_.strict) throw InputError(line + " [--strict: warnings are errors]");
    scene_.warnings.push_back(line);
  }
  SceneDesc read_document(const tinyxml2::XMLDocument& doc);
  void list_named_files(const XMLElement* scene);  // LoadOptions::outline

  std::string file_;
  LoadOptions options_;
  bool zero_based_ = false;  // <ZeroBasedIndexing>true</ZeroBasedIndexing> (hw6/sponza).
  SceneDesc scene_;
  std::map<std::string, int> material_ids_;
  std::map<std::string, Material> brdfs_;   // BRDF id -> the members a BRDF sets.
  std::map<std::string, Mat4> transforms_;  // Keyed "t1", "s2", "r3", "c4".
  std::vector<Vec3d> vertices_;
  std::vector<std::array<double, 2>> texcoords_;   // TexCoordData, one pair per vertex.
  std::map<std::string, int> texture_ids_;         // TextureMap id -> index.
  std::map<std::string, int> mesh_objects_;        // Mesh id -> object index.
  std::map<std::string, int> instance_objects_;    // MeshInstance id -> object index.
  std::map<std::string, int> light_mesh_objects_;  // LightMesh id -> object index.
};

}  // namespace loader
}  // namespace rt
