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

// The file behind one image a TextureMapDesc::image indexes. rtconvert copies or
// references image files and never decodes them for the output, so scene.images may be
// empty; this list is what the writers use.
struct ImageFile {
  std::string path;      // Absolute, or relative to the current folder; empty with `bytes`.
  std::string bytes;     // An image embedded in the input (glTF, FBX): written beside the output.
  std::string name;      // File name for `bytes` ("albedo.png").
  bool degamma = false;  // The TextureMap's degamma="true".
};

// Per-mesh names for the files written beside the XML ("<stem>_files/mesh3_body.ply").
struct ImportedScene {
  rt::SceneDesc scene;
  std::vector<std::string> mesh_names;  // Parallel to scene.meshes; may be empty.
  std::vector<ImageFile> images;        // Indexed by TextureMapDesc::image.
};

// The folder beside OUT.xml that holds its PLY meshes and extracted images: OUT_files.
std::string side_folder(const std::string& xml_path);

// The image files of a course scene, indexed as its TextureMapDesc::image (the loader keeps
// the decoded images only): read again from the <Textures> of `xml_path`.
std::vector<ImageFile> course_image_files(const std::string& xml_path, const rt::SceneDesc& s);

// One warning per material library (mtllib) an OBJ file names that does not exist: Assimp
// then gives every material its default grey without a word.
void warn_missing_material_libraries(const std::string& obj, Report& report);

// A file a conversion writes, and what it is in messages ("output", "mesh", "image",
// "material library").
struct PlannedFile {
  std::string path;
  const char* what;
};

// Refuses (ConvertError, one line), before anything is written: a first output (the
// conversion's own file) in a folder that does not exist; an output that is one of `inputs`
// (the same path after normalizing, links and letter case, rt::same_file_key, or the same
// file through a hard link); two outputs that are one file.
void check_conversion_files(const std::vector<PlannedFile>& outputs,
                            const std::vector<std::string>& inputs);

// Warnings for what the target format cannot carry (format "glb", "obj", "pbrt", "xml"),
// one line per feature, naming it.
void warn_dropped(const rt::SceneDesc& s, const std::string& path, const std::string& format,
                  Report& report);

// Import: any file Assimp reads. glTF files written by export_with_assimp carry the
// course's exact values in `extras` (see course_extras.h) and come back bit for bit, unless
// `use_extras` is false (then they are read as any other tool's file would be).
ImportedScene import_with_assimp(const std::string& path, int default_width, bool use_extras,
                                 Report& report);

// Writes the scene as course XML; meshes above a few triangles go to binary PLY files
// beside it. Nothing is written when one of its files (the XML, the PLY files and images
// beside it) would replace one of `inputs` or another of them (check_conversion_files).
void write_course_xml(const ImportedScene& in, const std::string& xml_path, Report& report,
                      const std::vector<std::string>& inputs = {});

// Export through Assimp: format "glb2" (binary glTF 2.0, with cameras, lights and extras
// added to its JSON) or "obj" (OBJ + MTL).
// `images`: the files of the scene's image textures (course_image_files).
void export_with_assimp(const rt::SceneDesc& scene, const std::string& path,
                        const std::string& format, Report& report,
                        const std::vector<ImageFile>& images = {});

// Writes `content` to a temporary file beside `path` and renames it: an interrupted or
// failed conversion never leaves a half-written file under the output's name.
void write_file_atomically(const std::string& path, const std::string& content);

// Export to pbrt-v4's text format; what does not map is listed in a comment at the top.
void export_pbrt(const rt::SceneDesc& scene, const std::string& path, Report& report);

}  // namespace rtconvert
