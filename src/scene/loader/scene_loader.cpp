// Reads the METU CENG795 scene format (assignments 1-6 and the older dialects seen in
// the course's files) with tinyxml2: the document, the scene-wide values and the helpers
// every element family uses. The families live beside this file.
#include <tinyxml2.h>

#include <cctype>
#include <cerrno>
#include <cfloat>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <filesystem>
#include <map>
#include <memory>
#include <sstream>

#include "cl/material/brdf.h"
#include "image/read_ldr.h"
#include "scene/loader/loader.h"
#include "scene/ply.h"
#include "scene/scene.h"
#include "scene/scene_schema.h"
#include "scene/xml_diagnosis.h"
#include "scene/xml_text.h"
#include "util/errors.h"

namespace rt {
namespace loader {

// A number as the file would write it: 3, -1.5, 1e+30.
std::string fmt(double v) {
  char buf[32];
  std::snprintf(buf, sizeof buf, "%.10g", v);
  return buf;
}

std::vector<double> Loader::numbers(const XMLElement* e, size_t min_count, size_t max_count) const {
  const std::string text = text_of(e);
  std::vector<double> out;
  const char* p = text.c_str();
  for (;;) {
    while (*p && std::isspace(static_cast<unsigned char>(*p))) ++p;
    if (!*p) break;
    const char* start = p;
    while (*p && !std::isspace(static_cast<unsigned char>(*p))) ++p;
    std::string token(start, p);
    char* end = nullptr;
    errno = 0;
    double v = std::strtod(token.c_str(), &end);
    if (end != token.c_str() + token.size() || token.empty())
      fail(e, "not a number: '" + shorten(token) + "'");
    // Overflow gives inf; underflow (1e-400) is a representable tiny value, not an error.
    if (!std::isfinite(v)) fail(e, "not a finite number: '" + shorten(token) + "'");
    // The devices work in float. Positions reach them relative to the camera (src/
    // world_frame.h), so a position beyond float range could in principle be rendered, but
    // there even double resolves only 1e22 units (2^-52 of the value): no detail the file
    // could mean survives the parse. Every other number (radii, scales, colours) goes to
    // float as it is. So one limit for all: the float range.
    if (std::fabs(v) > FLT_MAX)
      fail(e, "'" + shorten(token) + "' is too large (beyond float range)");
    out.push_back(v);
  }
  if (out.size() < min_count || out.size() > max_count) {
    std::ostringstream s;
    s << "expected " << min_count;
    if (max_count != min_count)
      s << (max_count == SIZE_MAX ? " or more" : " to " + std::to_string(max_count));
    s << (max_count == 1 ? " number" : " numbers") << ", got " << out.size() << " ('"
      << shorten(text) << "')";
    fail(e, s.str());
  }
  return out;
}

const XMLElement* Loader::child(const XMLElement* e, const char* name, bool required) const {
  const XMLElement* c = e->FirstChildElement(name);
  if (!c && required) fail(e, std::string("missing <") + name + ">" + misspelling_hint(e, name));
  return c;
}

double Loader::child_number(const XMLElement* e, const char* name, double fallback) const {
  const XMLElement* c = child(e, name, false);
  return c ? number(c) : fallback;
}

Vec3d Loader::child_vec3(const XMLElement* e, const char* name, Vec3d fallback) const {
  const XMLElement* c = child(e, name, false);
  return c ? vec3(c) : fallback;
}

SceneDesc Loader::load() {
  if (file_.empty())
    throw InputError("scene file '': the name is empty (give the path of an XML scene file)");
  // A directory opens but cannot be read; tinyxml2 would call either "malformed at line 0".
  std::error_code ec;
  if (std::filesystem::is_directory(file_, ec))
    throw input_error(file_, "file", "is a directory, not a scene file");
  errno = 0;
  std::unique_ptr<std::FILE, int (*)(std::FILE*)> f(std::fopen(file_.c_str(), "rb"), &std::fclose);
  if (!f)
    throw input_error(
        file_, "file",
        std::string("cannot open") + (errno ? std::string(": ") + std::strerror(errno) : ""));
  std::string text;
  char buf[1 << 16];
  for (size_t n; (n = std::fread(buf, 1, sizeof buf, f.get())) > 0;) text.append(buf, n);
  if (std::ferror(f.get())) throw input_error(file_, "file", "cannot read");
  scene_.inputs.push_back(file_);
  return load_text(text);
}

SceneDesc Loader::load_text(const std::string& xml) {
  // A mesh or an image given as the scene: say so rather than what the XML parser makes of it.
  const std::string kind = non_xml_kind(xml);
  if (!kind.empty())
    throw InputError(file_ + ": not an XML scene file (it starts like a " + kind + " file)");
  tinyxml2::XMLDocument doc;
  const tinyxml2::XMLError err = doc.Parse(xml.data(), xml.size());
  if (err == tinyxml2::XML_ERROR_EMPTY_DOCUMENT)
    throw input_error(file_, "XML", "empty document: no <Scene> element");
  if (err != tinyxml2::XML_SUCCESS) {
    XmlProblem p = find_xml_problem(xml);
    if (p.what.empty()) {
      // Something the scan does not know; the parser's line and element, in words.
      std::string detail = doc.ErrorStr() ? doc.ErrorStr() : "";
      size_t at = detail.find("XMLElement name=");
      p = {doc.ErrorLineNum(), at == std::string::npos ? std::string("the XML parser stops here")
                                                       : "the XML parser stops in <" +
                                                             shorten(detail.substr(at + 16)) + ">"};
    }
    throw InputError(file_ + ":" + std::to_string(p.line) + ": malformed XML: " + p.what);
  }
  return read_document(doc);
}

SceneDesc Loader::read_document(const tinyxml2::XMLDocument& doc) {
  const XMLElement* scene = doc.FirstChildElement("Scene");
  if (!scene) throw input_error(file_, "XML", "no <Scene> root element");
  scene_.file = file_;
  // Structure first (unsupported features, repeats, unknown elements), then the values.
  for (const std::string& w : check_scene_structure(doc, file_)) warn(w);
  scene_.background = child_vec3(scene, "BackgroundColor", {});
  scene_.shadow_epsilon = child_number(scene, "ShadowRayEpsilon", 1e-3);
  if (scene_.shadow_epsilon < 0)
    fail_value(child(scene, "ShadowRayEpsilon", true), "must not be negative");
  scene_.intersection_epsilon = child_number(scene, "IntersectionTestEpsilon", 1e-6);
  if (scene_.intersection_epsilon < 0)
    fail_value(child(scene, "IntersectionTestEpsilon", true), "must not be negative");
  if (const XMLElement* d = child(scene, "MaxRecursionDepth", false)) {
    double v = number(d);
    if (v < 0 || v != std::floor(v) || v > RT_MAX_DEPTH)
      fail_value(d, "is not a whole number in [0, " + std::to_string(RT_MAX_DEPTH) + "]");
    scene_.max_depth = static_cast<int>(v);
  }
  read_cameras(scene);
  if (options_.outline) {
    list_named_files(scene);
    return std::move(scene_);
  }
  read_lights(scene);
  read_brdfs(scene);
  read_materials(scene);
  read_transformations(scene);
  read_index_base(scene);
  read_vertices(scene);
  read_textures(scene);
  read_texcoords(scene);
  read_objects(scene);
  check_texture_coordinates();
  if (scene_.degenerate_triangles > 0)
    warn(file_ + ": Objects: skipped " + std::to_string(scene_.degenerate_triangles) +
         " degenerate triangles");
  return std::move(scene_);
}

// Every element's plyFile and binaryFile, and every Textures > Images > Image, whether used
// or not, resolved as the readers resolve them: beside the scene file.
void Loader::list_named_files(const XMLElement* scene) {
  const std::filesystem::path folder = std::filesystem::path(file_).parent_path();
  auto add = [&](std::string name) {
    name.erase(0, name.find_first_not_of(" \t\r\n"));
    name.erase(name.find_last_not_of(" \t\r\n") + 1);
    std::filesystem::path p(name);
    if (p.empty()) return;
    scene_.inputs.push_back((p.is_relative() ? folder / p : p).string());
  };
  std::vector<const XMLElement*> open{scene};
  while (!open.empty()) {
    const XMLElement* e = open.back();
    open.pop_back();
    for (const char* a : {"plyFile", "binaryFile"})
      if (const char* v = e->Attribute(a)) add(v);
    for (const XMLElement* c = e->FirstChildElement(); c; c = c->NextSiblingElement())
      open.push_back(c);
  }
  const XMLElement* ts = scene->FirstChildElement("Textures");
  const XMLElement* images = ts ? ts->FirstChildElement("Images") : nullptr;
  for (const XMLElement* im = images ? images->FirstChildElement("Image") : nullptr; im;
       im = im->NextSiblingElement("Image"))
    add(text_of(im));
}

}  // namespace loader

SceneDesc load_scene(const std::string& path, const LoadOptions& options) {
  return loader::Loader(path, options).load();
}

SceneDesc load_scene_text(const std::string& xml, const std::string& name,
                          const LoadOptions& options) {
  return loader::Loader(name, options).load_text(xml);
}

}  // namespace rt
