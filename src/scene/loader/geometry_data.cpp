// Where the numbers of VertexData, TexCoordData and Faces come from (inline text or a
// binaryFile) and the base their indices count from (ZeroBasedIndexing).
#include <tinyxml2.h>

#include <cmath>
#include <cstring>
#include <filesystem>

#include "scene/loader/binary_data.h"
#include "scene/loader/loader.h"
#include "scene/xml_text.h"
#include "util/errors.h"

namespace rt {
namespace loader {

// hw6/sponza.xml writes <ZeroBasedIndexing>true</ZeroBasedIndexing>: every index into
// VertexData and TexCoordData (Faces, inline or binary, Triangle Indices, Sphere Center)
// then counts from 0. PLY files are unaffected: their indices are always 0-based and
// address the PLY's own vertices, never VertexData.
void Loader::read_index_base(const XMLElement* scene) {
  const XMLElement* z = child(scene, "ZeroBasedIndexing", false);
  if (!z) return;
  std::string v = text_of(z);
  v.erase(0, v.find_first_not_of(" \t\r\n"));
  v.erase(v.find_last_not_of(" \t\r\n") + 1);
  if (v == "true" || v == "1")
    zero_based_ = true;
  else if (v != "false" && v != "0")
    fail_value(z, "is neither true nor false");
}

std::vector<double> Loader::binary_numbers(const XMLElement* e, int per_record, const char* record,
                                           bool ints) {
  const char* name = e->Attribute("binaryFile");
  std::filesystem::path p(name);
  if (p.is_relative()) p = std::filesystem::path(file_).parent_path() / p;
  scene_.inputs.push_back(p.string());
  std::vector<uint32_t> words;
  try {
    words = read_binary_records(p.string(), per_record);
  } catch (const InputError& err) {
    fail_file(e, "binaryFile", p.string(), err);
  }
  std::vector<double> out;
  out.reserve(words.size());
  if (ints) {
    for (int32_t v : words_as_ints(words)) out.push_back(v);
    return out;
  }
  std::vector<float> floats = words_as_floats(words);
  for (size_t i = 0; i < floats.size(); ++i) {
    if (!std::isfinite(floats[i]))
      fail(e, "binaryFile '" + shorten(name) + "': " + record + " " +
                  std::to_string(i / per_record) + " holds " + fmt(floats[i]) +
                  " (not a finite number)");
    out.push_back(floats[i]);
  }
  return out;
}

std::vector<double> Loader::data_numbers(const XMLElement* e, int per_record, const char* record,
                                         bool ints, size_t min_count) {
  if (!e->Attribute("binaryFile")) return numbers(e, min_count, SIZE_MAX);
  if (text_of(e).find_first_not_of(" \t\r\n") != std::string::npos)
    fail(e, "has both a binaryFile and inline numbers: only one source is allowed");
  std::vector<double> v = binary_numbers(e, per_record, record, ints);
  if (v.size() < min_count)
    fail(e, "binaryFile '" + shorten(e->Attribute("binaryFile")) + "' holds no " + record);
  return v;
}

}  // namespace loader
}  // namespace rt
