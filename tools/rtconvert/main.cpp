// rtconvert: course XML <-> glTF 2.0 / OBJ / anything Assimp reads, and XML -> pbrt-v4.
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <exception>
#include <string>
#include <vector>

#include "convert.h"
#include "util/args.h"
#include "util/errors.h"

namespace {

struct Options {
  std::string input, output;
  int width = 640;
  bool quiet = false;
  bool use_extras = true;
};

// All of the command line in one place: the project's options table (src/util/args.h)
// gives the parser, --help and the one-line usage errors (exit status 2).
Options parse_args(int argc, char** argv) {
  rt::OptionTable<Options> t(
      "rtconvert", "rtconvert INPUT OUTPUT [options]",
      "Converts between the course's XML scenes and other formats:\n"
      "  INPUT.xml -> OUTPUT.glb | OUTPUT.obj | OUTPUT.pbrt | OUTPUT.xml   export\n"
      "  INPUT.(any format Assimp reads: obj gltf glb fbx ply dae 3ds ...) -> OUTPUT.xml   import\n"
      "Exit status: 0 done, 1 input that cannot be converted (one line says why), 2 usage.");
  t.section("Conversion")
      .integer("--width", "N", rt::Range::closed(1, 32768), RT_FIELD(width),
               "image width of the cameras the importer makes")
      .flag("--no-extras", RT_FIELD(use_extras),
            "import glTF without rtconvert's extras.ceng795, as another tool's file", false)
      .flag("--quiet", RT_FIELD(quiet), "no warnings on stderr");
  Options o;
  std::vector<std::string> files = t.parse_or_exit(argc, argv, &o);
  if (files.size() != 2) t.usage_error("needs an input and an output file");
  o.input = files[0];
  o.output = files[1];
  return o;
}

std::string extension(const std::string& path) {
  size_t dot = path.find_last_of('.'), slash = path.find_last_of('/');
  if (dot == std::string::npos || (slash != std::string::npos && dot < slash)) return "";
  std::string e = path.substr(dot + 1);
  for (char& c : e) c = static_cast<char>(std::tolower(static_cast<unsigned char>(c)));
  return e;
}

}  // namespace

int main(int argc, char** argv) {
  const Options o = parse_args(argc, argv);
  rtconvert::Report report;
  const std::string in = extension(o.input), out = extension(o.output);
  try {
    // Before anything is read or written: an output that is the input would replace the
    // scene by a lossy rewrite of itself. An OBJ export writes its MTL file too (Assimp
    // names it after the OBJ, with ".mtl" in lower case). Once the input is read, every
    // file it names is checked too, and an XML output's files beside it (write_course_xml).
    std::vector<rtconvert::PlannedFile> outputs{{o.output, "output"}};
    if (out == "obj")
      outputs.push_back({o.output.substr(0, o.output.size() - 3) + "mtl", "material library"});
    rtconvert::check_conversion_files(outputs, {o.input});
    if (in == "xml") {
      if (out != "glb" && out != "obj" && out != "pbrt" && out != "xml")
        throw rtconvert::ConvertError(o.output + ": cannot export to '." + out +
                                      "' (use .glb, .obj, .pbrt or .xml)");
      rtconvert::ImportedScene scene{rt::load_scene(o.input), {}, {}};
      for (const auto& w : scene.scene.warnings) report.warn(w);
      scene.images = rtconvert::course_image_files(o.input, scene.scene);
      rtconvert::warn_dropped(scene.scene, o.output, out, report);
      const std::vector<std::string>& inputs = scene.scene.inputs;  // The XML, PLYs, images.
      if (out != "xml") rtconvert::check_conversion_files(outputs, inputs);
      if (out == "glb") {
        rtconvert::export_with_assimp(scene.scene, o.output, "glb2", report, scene.images);
      } else if (out == "obj") {
        rtconvert::export_with_assimp(scene.scene, o.output, "obj", report, scene.images);
      } else if (out == "pbrt") {
        rtconvert::export_pbrt(scene.scene, o.output, report);
      } else {
        rtconvert::write_course_xml(scene, o.output, report, inputs);
      }
    } else {
      if (out != "xml")
        throw rtconvert::ConvertError(o.output + ": an import writes course XML (.xml), not '." +
                                      out + "'");
      rtconvert::ImportedScene scene =
          rtconvert::import_with_assimp(o.input, o.width, o.use_extras, report);
      std::vector<std::string> inputs{o.input};  // The model and the image files it names.
      for (const rtconvert::ImageFile& f : scene.images)
        if (f.bytes.empty()) inputs.push_back(f.path);
      rtconvert::write_course_xml(scene, o.output, report, inputs);
    }
  } catch (const std::exception& e) {
    // Loader, Assimp and conversion errors alike: one line naming the file and the feature.
    std::fprintf(stderr, "rtconvert: %s\n", e.what());
    return 1;
  }
  if (!o.quiet)
    for (const auto& w : report.warnings) std::fprintf(stderr, "warning: %s\n", w.c_str());
  return 0;
}
