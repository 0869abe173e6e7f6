// The files around a conversion: the folder beside an XML output, the image files behind a
// course scene's textures, and the check of what a conversion writes against what it reads.
#include <sys/stat.h>
#include <tinyxml2.h>

#include <filesystem>
#include <fstream>
#include <map>
#include <set>
#include <sstream>

#include "convert.h"
#include "io/file_util.h"

namespace rtconvert {
namespace fs = std::filesystem;

std::string side_folder(const std::string& xml_path) {
  fs::path p(xml_path);
  return (p.parent_path() / (p.stem().string() + "_files")).string();
}

namespace {

std::string trimmed(const char* text) {
  std::string s = text ? text : "";
  size_t a = s.find_first_not_of(" \t\r\n"), b = s.find_last_not_of(" \t\r\n");
  return a == std::string::npos ? std::string() : s.substr(a, b - a + 1);
}

}  // namespace

// The loader numbers images by first use: TextureMaps in file order, one image per
// (ImageId, degamma) pair. The same walk gives the same numbers.
std::vector<ImageFile> course_image_files(const std::string& xml_path, const rt::SceneDesc& s) {
  std::vector<ImageFile> out;
  if (s.images.empty()) return out;
  tinyxml2::XMLDocument doc;
  if (doc.LoadFile(xml_path.c_str()) != tinyxml2::XML_SUCCESS)
    throw ConvertError(xml_path + ": cannot read the scene again for its image files");
  const tinyxml2::XMLElement* scene = doc.FirstChildElement("Scene");
  const tinyxml2::XMLElement* ts = scene ? scene->FirstChildElement("Textures") : nullptr;
  std::map<std::string, std::string> files;
  const tinyxml2::XMLElement* list = ts ? ts->FirstChildElement("Images") : nullptr;
  for (auto* im = list ? list->FirstChildElement("Image") : nullptr; im;
       im = im->NextSiblingElement("Image"))
    if (im->Attribute("id")) files[im->Attribute("id")] = trimmed(im->GetText());
  std::set<std::pair<std::string, bool>> seen;
  for (auto* e = ts ? ts->FirstChildElement("TextureMap") : nullptr; e;
       e = e->NextSiblingElement("TextureMap")) {
    if (trimmed(e->Attribute("type")) != "image") continue;
    const tinyxml2::XMLElement* id = e->FirstChildElement("ImageId");
    const std::string key = trimmed(id ? id->GetText() : nullptr);
    const bool degamma = trimmed(e->Attribute("degamma")) == "true";
    if (!seen.insert({key, degamma}).second) continue;
    fs::path p(files[key]);
    if (p.is_relative()) p = fs::path(xml_path).parent_path() / p;
    ImageFile f;
    f.path = p.lexically_normal().string();
    f.degamma = degamma;
    out.push_back(f);
  }
  if (out.size() != s.images.size())
    throw ConvertError(xml_path + ": Textures: found " + std::to_string(out.size()) +
                       " image files for the loader's " + std::to_string(s.images.size()));
  return out;
}

void warn_missing_material_libraries(const std::string& obj, Report& report) {
  std::ifstream in(obj);
  std::string line;
  while (std::getline(in, line)) {
    std::istringstream words(line);
    std::string word;
    if (!(words >> word) || word != "mtllib") continue;
    // OBJ names the library relative to itself; a name may hold spaces.
    std::string name;
    std::getline(words >> std::ws, name);
    while (!name.empty() && (name.back() == '\r' || name.back() == ' ')) name.pop_back();
    fs::path p(name);
    if (p.is_relative()) p = fs::path(obj).parent_path() / p;
    std::error_code ec;
    if (!fs::exists(p, ec))
      report.warn(obj + ": material library '" + name +
                  "' (mtllib) not found: " + "every material is a default grey");
  }
}

void check_conversion_files(const std::vector<PlannedFile>& outputs,
                            const std::vector<std::string>& inputs) {
  std::error_code ec;
  // Inputs by path key and, where they exist, by the file itself (a hard link).
  std::map<std::string, std::string> read;
  std::map<std::pair<dev_t, ino_t>, std::string> read_ids;
  for (const std::string& in : inputs) {
    if (!read.emplace(rt::same_file_key(in), in).second) continue;
    struct stat st;
    if (::stat(in.c_str(), &st) == 0) read_ids.emplace(std::make_pair(st.st_dev, st.st_ino), in);
  }
  std::map<std::string, const PlannedFile*> written;
  for (const PlannedFile& o : outputs) {
    const fs::path folder = fs::path(o.path).parent_path();
    // The side folder (OUT_files) is made by the conversion; the output's own must exist.
    if (&o == &outputs.front() && !folder.empty() && !fs::is_directory(folder, ec))
      throw ConvertError(o.path + ": the folder '" + folder.string() + "' does not exist");
    const std::string key = rt::same_file_key(o.path);
    auto in = read.find(key);
    std::string input = in == read.end() ? "" : in->second;
    struct stat st;
    if (input.empty() && ::stat(o.path.c_str(), &st) == 0) {
      auto id = read_ids.find({st.st_dev, st.st_ino});
      if (id != read_ids.end()) input = id->second;
    }
    if (!input.empty())
      throw ConvertError(o.path + ": the " + o.what + " is the input file " + input +
                         "; refusing to overwrite it (choose another output name)");
    const auto [it, first] = written.emplace(key, &o);
    if (!first)
      throw ConvertError(o.path + ": the " + o.what + " and the " + it->second->what + " " +
                         it->second->path +
                         " are one file where the file system folds letter case (choose "
                         "another output name)");
  }
}

}  // namespace rtconvert
