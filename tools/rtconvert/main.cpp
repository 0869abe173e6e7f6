// rtconvert: course XML <-> glTF 2.0 / OBJ / anything Assimp reads, and XML -> pbrt-v4.
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <exception>
#include <string>

#include "convert.h"
#include "errors.h"

namespace {

const char* kUsage =
    "usage: rtconvert INPUT OUTPUT [--width N] [--quiet]\n"
    "  INPUT.xml -> OUTPUT.glb | OUTPUT.obj | OUTPUT.pbrt | OUTPUT.xml   export\n"
    "  INPUT.(any format Assimp reads: obj gltf glb fbx ply dae 3ds ...) -> OUTPUT.xml   import\n"
    "  --width N   image width of cameras the importer makes (default 640)\n"
    "  --quiet     no warnings on stderr\n"
    "  --no-extras import glTF without rtconvert's extras.ceng795 (as another tool's file)\n"
    "Exit status: 0 done, 1 input that cannot be converted (one line says why), 2 usage.\n";

struct Options {
  std::string input, output;
  int width = 640;
  bool quiet = false;
  bool use_extras = true;
};

[[noreturn]] void usage_error(const std::string& what) {
  std::fprintf(stderr, "rtconvert: %s\n%s", what.c_str(), kUsage);
  std::exit(2);
}

// All of the command line in one place.
Options parse_args(int argc, char** argv) {
  Options o;
  for (int i = 1; i < argc; ++i) {
    std::string a = argv[i];
    if (a == "--help" || a == "-h") {
      std::fputs(kUsage, stdout);
      std::exit(0);
    } else if (a == "--quiet") {
      o.quiet = true;
    } else if (a == "--no-extras") {
      o.use_extras = false;
    } else if (a == "--width") {
      if (i + 1 >= argc) usage_error("--width needs a value");
      char* end = nullptr;
      long w = std::strtol(argv[++i], &end, 10);
      if (*end || w < 1 || w > 32768)
        usage_error(std::string("--width: '") + argv[i] + "' is not in [1, 32768]");
      o.width = static_cast<int>(w);
    } else if (a.size() > 1 && a[0] == '-') {
      usage_error("unknown option '" + a + "'");
    } else if (o.input.empty()) {
      o.input = a;
    } else if (o.output.empty()) {
      o.output = a;
    } else {
      usage_error("one input and one output, got a third file '" + a + "'");
    }
  }
  if (o.output.empty()) usage_error("needs an input and an output file");
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
    if (in == "xml") {
      rt::SceneDesc scene = rt::load_scene(o.input);
      for (const auto& w : scene.warnings) report.warn(w);
      // Light types beyond the course's point and area lights have no mapping yet.
      if (!scene.lights.empty())
        report.warn(o.input + ": " + std::to_string(scene.lights.size()) +
                    " lights of types other than point and area are not converted");
      if (!scene.textures.empty())
        report.warn(o.input + ": " + std::to_string(scene.textures.size()) +
                    " texture maps and the texture coordinates are not converted");
      if (out == "glb") {
        rtconvert::export_with_assimp(scene, o.output, "glb2", report);
      } else if (out == "obj") {
        rtconvert::export_with_assimp(scene, o.output, "obj", report);
      } else if (out == "pbrt") {
        rtconvert::export_pbrt(scene, o.output, report);
      } else if (out == "xml") {
        rtconvert::write_course_xml({scene, {}}, o.output, report);
      } else {
        throw rtconvert::ConvertError(o.output + ": cannot export to '." + out +
                                      "' (use .glb, .obj, .pbrt or .xml)");
      }
    } else {
      if (out != "xml")
        throw rtconvert::ConvertError(o.output + ": an import writes course XML (.xml), not '." +
                                      out + "'");
      rtconvert::ImportedScene scene =
          rtconvert::import_with_assimp(o.input, o.width, o.use_extras, report);
      rtconvert::write_course_xml(scene, o.output, report);
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
