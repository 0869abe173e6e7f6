// rtconvert: the course's XML scenes to and from the formats of other tools (through
// Assimp) and pbrt-v4. Lives outside src/ so that Assimp never becomes a dependency of
// the renderer; it reuses the core's loader (rt::load_scene) and PLY reader.
#pragma once

#include <stdexcept>
#include <string>
#include <vector>

#include "cl/features.h"
#include "scene/scene.h"

namespace rtconvert {

// Radiance 1 (white, glTF's emission 1, OBJ's Ke 1) on the course's 0-255 scale.
inline constexpr float kRadianceScale = 255.0f;

// The course's material type attribute ("" for plain Blinn-Phong) and back; the tags are
// feature bits (cl/features.h), not small integers.
inline const char* material_type_name(int type) {
  switch (type) {
    case RT_MATERIAL_MIRROR:
      return "mirror";
    case RT_MATERIAL_CONDUCTOR:
      return "conductor";
    case RT_MATERIAL_DIELECTRIC:
      return "dielectric";
    default:
      return "";
  }
}
inline int material_type_from_name(const std::string& name) {
  for (int type : {RT_MATERIAL_MIRROR, RT_MATERIAL_CONDUCTOR, RT_MATERIAL_DIELECTRIC})
    if (name == material_type_name(type)) return type;
  return RT_MATERIAL_PLAIN;
}

// Collects the warnings of one conversion (approximate mappings, dropped features); main
// prints each on its own line, so nothing approximate happens silently.
struct Report {
  std::vector<std::string> warnings;
  void warn(const std::string& what) {
    // Materials of the same name in one file would repeat their warning word for word.
    for (const auto& w : warnings)
      if (w == what) return;
    warnings.push_back(what);
  }
};

// Thrown for input that cannot be converted: one line naming the file and the feature.
struct ConvertError : std::runtime_error {
  using std::runtime_error::runtime_error;
};

// Per-mesh names for the files written beside the XML ("<stem>_mesh3.ply").
struct ImportedScene {
  rt::SceneDesc scene;
  std::vector<std::string> mesh_names;  // Parallel to scene.meshes; may be empty.
};

// Import: any file Assimp reads. glTF files written by export_with_assimp carry the
// course's exact values in `extras` (see course_extras.h) and come back bit for bit, unless
// `use_extras` is false (then they are read as any other tool's file would be).
ImportedScene import_with_assimp(const std::string& path, int default_width, bool use_extras,
                                 Report& report);

// Writes the scene as course XML; meshes above a few triangles go to binary PLY files
// beside it.
void write_course_xml(const ImportedScene& in, const std::string& xml_path, Report& report);

// Export through Assimp: format "glb2" (binary glTF 2.0, with cameras, lights and extras
// added to its JSON) or "obj" (OBJ + MTL).
void export_with_assimp(const rt::SceneDesc& scene, const std::string& path,
                        const std::string& format, Report& report);

// Writes `content` to a temporary file beside `path` and renames it: an interrupted or
// failed conversion never leaves a half-written file under the output's name.
void write_file_atomically(const std::string& path, const std::string& content);

// Export to pbrt-v4's text format; what does not map is listed in a comment at the top.
void export_pbrt(const rt::SceneDesc& scene, const std::string& path, Report& report);

}  // namespace rtconvert
