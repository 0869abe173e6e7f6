// rtconvert's import as fuzz targets (declared in fuzz/targets.h): the bytes are written to
// a file of the scratch folder (fuzz/scratch.h), since Assimp picks its importer by the
// extension, then imported (the course's glTF extras included) and written as a course scene
// as `rtconvert in.gltf out.xml` would. Assimp is a Debian library, not built with the
// sanitizers: the fuzzers see its crashes but not its silent memory errors, and its code
// adds no coverage feedback, so these targets mostly explore rtconvert's own code on top.
#include <stdexcept>
#include <string>

#include "convert.h"
#include "fuzz/scratch.h"
#include "fuzz/targets.h"
#include "util/errors.h"

namespace rt {
namespace {

void import_model(const std::string& name, const uint8_t* data, size_t size) {
  const std::string path = fuzz_scratch_file(name, data, size);
  rtconvert::Report report;
  try {
    rtconvert::ImportedScene scene = rtconvert::import_with_assimp(path, 64, true, report);
    rtconvert::write_course_xml(scene, fuzz_scratch_dir() + "/out.xml", report);
  } catch (const std::runtime_error& e) {  // rtconvert::ConvertError or rt::InputError.
    const std::string what = e.what();
    if (what.find(fuzz_scratch_dir()) == std::string::npos || what.find('\n') != std::string::npos)
      throw std::logic_error("a refusal not in one line naming the file: " + what);
  }
}

}  // namespace

void fuzz_obj(const uint8_t* data, size_t size) { import_model("in.obj", data, size); }
// Assimp takes a .glb for binary glTF and a .gltf for JSON by the name alone: the magic picks.
void fuzz_gltf(const uint8_t* data, size_t size) {
  const bool binary =
      size >= 4 && data[0] == 'g' && data[1] == 'l' && data[2] == 'T' && data[3] == 'F';
  import_model(binary ? "in.glb" : "in.gltf", data, size);
}

}  // namespace rt
