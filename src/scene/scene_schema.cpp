#include "scene_schema.h"

#include <cstring>
#include <map>
#include <utility>

#include "scene/loader/shared_ids.h"
#include "util/errors.h"
#include "util/spelling.h"
#include "xml_text.h"

namespace rt {
namespace {

using tinyxml2::XMLElement;

enum class Support { kRead, kUnsupported };

// One row per element (or "@attribute") that may appear inside a context. A context names
// what an element's children are: "Camera" is the inside of a <Camera>.
struct Rule {
  const char* context;
  const char* name;   // Element name, or "@name" for an attribute.
  const char* value;  // Attributes only: the row applies to this value (nullptr: any value).
  Support support;
  bool many;          // May repeat (a list); otherwise a second one is an error.
  bool ids_repeat;    // Two of them may share an id (a course scene relies on it): a warning.
  const char* inner;  // Context of its own children and attributes; "" for a plain value.
  bool group;         // Holds elements (text inside it is stray); otherwise holds a value.
  const char* wrong;  // Unsupported only: how the image would silently be wrong.
};

Rule value(const char* ctx, const char* name, const char* inner = "") {
  return {ctx, name, nullptr, Support::kRead, false, false, inner, false, nullptr};
}
Rule group(const char* ctx, const char* name, const char* inner) {
  return {ctx, name, nullptr, Support::kRead, false, false, inner, true, nullptr};
}
Rule list(const char* ctx, const char* name, const char* inner, bool holds_elements = true,
          bool ids_repeat = false) {
  return {ctx, name, nullptr, Support::kRead, true, ids_repeat, inner, holds_elements, nullptr};
}
Rule attribute(const char* ctx, const char* name, const char* only_value = nullptr) {
  return {ctx, name, only_value, Support::kRead, false, false, "", false, nullptr};
}
Rule unsupported(const char* ctx, const char* name, const char* wrong) {
  return {ctx, name, nullptr, Support::kUnsupported, true, true, "", false, wrong};
}

// Every element and attribute the loader knows. Rows are matched in order; the first row
// whose context, name (and value, for attributes) match decides. "id" is allowed anywhere.
const std::vector<Rule>& rules() {
  static const std::vector<Rule> kRules = {
      value("Scene", "BackgroundColor"),
      value("Scene", "ShadowRayEpsilon"),
      value("Scene", "IntersectionTestEpsilon"),
      value("Scene", "MaxRecursionDepth"),
      list("Scene", "Camera", "Camera"),  // Files of 2017 have no <Cameras>.
      group("Scene", "Cameras", "Cameras"),
      group("Scene", "Lights", "Lights"),
      group("Scene", "Materials", "Materials"),
      group("Scene", "Transformations", "TransformationList"),
      value("Scene", "VertexData", "VertexData"),
      group("Scene", "Objects", "Objects"),
      value("Scene", "TexCoordData", "TexCoordData"),
      group("Scene", "Textures", "Textures"),
      group("Scene", "BRDFs", "BRDFs"),
      value("Scene", "ZeroBasedIndexing"),
      attribute("VertexData", "@binaryFile"),
      attribute("TexCoordData", "@binaryFile"),

      group("Textures", "Images", "Images"),
      list("Textures", "TextureMap", "TextureMap"),
      list("Images", "Image", "", false),
      attribute("TextureMap", "@type"),
      attribute("TextureMap", "@degamma"),
      value("TextureMap", "DecalMode"),
      value("TextureMap", "ImageId"),
      value("TextureMap", "Interpolation"),
      value("TextureMap", "Normalizer"),
      value("TextureMap", "BumpFactor"),
      value("TextureMap", "NoiseScale"),
      value("TextureMap", "NoiseConversion"),
      value("TextureMap", "Scale"),
      value("TextureMap", "Offset"),
      value("TextureMap", "BlackColor"),
      value("TextureMap", "WhiteColor"),

      list("BRDFs", "OriginalBlinnPhong", "BRDF"),
      list("BRDFs", "OriginalPhong", "BRDF"),
      list("BRDFs", "ModifiedBlinnPhong", "BRDF"),
      list("BRDFs", "ModifiedPhong", "BRDF"),
      list("BRDFs", "TorranceSparrow", "BRDF"),
      attribute("BRDF", "@normalized"),
      attribute("BRDF", "@kdfresnel"),
      value("BRDF", "Exponent"),

      list("Cameras", "Camera", "Camera"),
      attribute("Camera", "@type"),
      attribute("Camera", "@handedness"),
      value("Camera", "Position"),
      value("Camera", "Gaze"),
      value("Camera", "GazePoint"),
      value("Camera", "Up"),
      value("Camera", "NearPlane"),
      value("Camera", "NearDistance"),
      value("Camera", "FovY"),
      value("Camera", "ImageResolution"),
      value("Camera", "ImageName"),
      value("Camera", "NumSamples"),
      value("Camera", "ApertureSize"),
      value("Camera", "FocusDistance"),
      group("Camera", "Tonemap", "Tonemap"),
      value("Tonemap", "TMO"),
      value("Tonemap", "TMOOptions"),
      value("Tonemap", "Saturation"),
      value("Tonemap", "Gamma"),
      value("Camera", "Renderer"),
      value("Camera", "RendererParams"),

      value("Lights", "AmbientLight"),
      // hw4's sphere_perlin*.xml define two point lights with id 3; both shine.
      list("Lights", "PointLight", "PointLight", true, true),
      list("Lights", "AreaLight", "AreaLight"),
      list("Lights", "DirectionalLight", "DirectionalLight"),
      list("Lights", "SpotLight", "SpotLight"),
      list("Lights", "SphericalDirectionalLight", "SphericalDirectionalLight"),
      attribute("SphericalDirectionalLight", "@type"),
      value("SphericalDirectionalLight", "ImageId"),
      value("SphericalDirectionalLight", "Sampler"),
      value("DirectionalLight", "Direction"),
      value("DirectionalLight", "Radiance"),
      value("SpotLight", "Position"),
      value("SpotLight", "Direction"),
      value("SpotLight", "Intensity"),
      value("SpotLight", "CoverageAngle"),
      value("SpotLight", "FalloffAngle"),
      value("PointLight", "Position"),
      value("PointLight", "Intensity"),
      value("AreaLight", "Position"),
      value("AreaLight", "Normal"),
      value("AreaLight", "Size"),
      value("AreaLight", "Radiance"),
      value("AreaLight", "EdgeVector1"),
      value("AreaLight", "EdgeVector2"),
      value("AreaLight", "Intensity"),

      list("Materials", "Material", "Material"),
      attribute("Material", "@type"),
      attribute("Material", "@BRDF"),
      attribute("Material", "@degamma"),
      value("Material", "AmbientReflectance"),
      value("Material", "DiffuseReflectance"),
      value("Material", "SpecularReflectance"),
      value("Material", "MirrorReflectance"),
      value("Material", "PhongExponent"),
      value("Material", "RefractionIndex"),
      value("Material", "AbsorptionIndex"),
      value("Material", "AbsorptionCoefficient"),
      value("Material", "Roughness"),
      value("Material", "Transparency"),

      list("TransformationList", "Translation", "", false),
      list("TransformationList", "Scaling", "", false),
      list("TransformationList", "Rotation", "", false),
      list("TransformationList", "Composite", "", false),

      list("Objects", "Mesh", "Mesh"),
      list("Objects", "Triangle", "Triangle"),
      // hw1/two_spheres.xml gives both of its spheres id 1.
      list("Objects", "Sphere", "Sphere", true, true),
      list("Objects", "MeshInstance", "MeshInstance"),
      list("Objects", "LightMesh", "LightMesh"),
      list("Objects", "LightSphere", "LightSphere"),
      value("LightMesh", "Radiance"),
      value("LightMesh", "Faces", "Faces"),
      attribute("LightMesh", "@shadingMode"),
      value("LightSphere", "Radiance"),
      value("LightSphere", "Center"),
      value("LightSphere", "Radius"),
      // The lights are sampled where they are at time 0.
      unsupported("LightMesh", "MotionBlur", "the light would not move"),
      unsupported("LightSphere", "MotionBlur", "the light would not move"),
      attribute("Mesh", "@shadingMode"),
      value("Mesh", "Faces", "Faces"),
      attribute("Faces", "@plyFile"),
      attribute("Faces", "@vertexOffset"),
      attribute("Faces", "@binaryFile"),
      attribute("Faces", "@textureOffset"),
      attribute("Triangle", "@shadingMode"),
      value("Triangle", "Indices"),
      value("Sphere", "Center"),
      value("Sphere", "Radius"),
      attribute("MeshInstance", "@baseMeshId"),
      attribute("MeshInstance", "@resetTransform"),
  };
  // What every object may carry.
  static const std::vector<Rule> kAll = [] {
    std::vector<Rule> all = kRules;
    for (const char* object :
         {"Mesh", "Triangle", "Sphere", "MeshInstance", "LightMesh", "LightSphere"}) {
      all.push_back(value(object, "Material"));
      all.push_back(value(object, "Transformations"));
      all.push_back(value(object, "MotionBlur"));
      all.push_back(value(object, "Textures"));
    }
    return all;
  }();
  return kAll;
}

const Rule* find_rule(const std::string& context, const char* name, const char* attr_value) {
  for (const Rule& r : rules()) {
    if (context != r.context || std::strcmp(name, r.name) != 0) continue;
    if (r.value && (!attr_value || std::strcmp(r.value, attr_value) != 0)) continue;
    return &r;
  }
  return nullptr;
}

// "; did you mean <Radius>?" for an unknown element (or "; did you mean plyFile?" for an
// attribute, `name` then starting with '@') near one the context knows; "" otherwise.
std::string suggestion(const std::string& context, const std::string& name) {
  const bool attr = !name.empty() && name[0] == '@';
  std::vector<std::string> known;
  for (const Rule& r : rules())
    if (context == r.context && (r.name[0] == '@') == attr) known.push_back(r.name);
  const std::string near = closest_name(name, known);
  if (near.empty()) return "";
  return attr ? "; did you mean " + near.substr(1) + "?" : "; did you mean <" + near + ">?";
}

bool is_blank(const char* s) {
  for (; s && *s; ++s)
    if (!std::strchr(" \t\r\n", *s)) return false;
  return true;
}

// Nothing inside and no attribute but an id: ignoring it changes nothing.
bool is_empty(const XMLElement* e) {
  for (auto* a = e->FirstAttribute(); a; a = a->Next())
    if (std::strcmp(a->Name(), "id") != 0) return false;
  return !e->FirstChildElement() && is_blank(text_of(e).c_str());
}

std::string line(const XMLElement* e) { return std::to_string(e->GetLineNum()); }

class StructureCheck {
 public:
  explicit StructureCheck(const std::string& file) : file_(file) {}

  std::vector<std::string> run(const tinyxml2::XMLDocument& doc) {
    const XMLElement* scene = nullptr;
    for (auto* n = doc.FirstChild(); n; n = n->NextSibling()) {
      if (const auto* t = n->ToText()) {
        if (!is_blank(t->Value())) warn_once("#roottext", "XML", "text outside <Scene>, ignored");
      } else if (const XMLElement* e = n->ToElement()) {
        if (std::strcmp(e->Name(), "Scene") != 0) {
          warn_once(std::string("#root/") + e->Name(), "XML",
                    "root element <" + shorten(e->Name()) + "> (line " + line(e) + "), ignored");
        } else if (scene) {
          warn_once("#scene2", "XML",
                    "a second <Scene> (line " + line(e) + "), ignored: only the first (line " +
                        line(scene) + ") is read");
        } else {
          scene = e;
        }
      }
    }
    if (scene) walk(scene, "Scene", true);
    std::vector<std::string> out;
    for (auto& [text, count] : warnings_)
      out.push_back(count > 1 ? text + " (" + std::to_string(count) + " times)" : text);
    return out;
  }

 private:
  [[noreturn]] void fail(const XMLElement* e, const std::string& what) const {
    throw input_error(file_, path_of(e), what);
  }

  // One warning per kind, however often the kind occurs; the count is added at the end.
  void warn_once(const std::string& kind, const std::string& where, const std::string& what) {
    auto [it, inserted] = kinds_.emplace(kind, warnings_.size());
    if (inserted)
      warnings_.push_back({file_ + ": " + where + ": " + what, 1});
    else
      ++warnings_[it->second].second;
  }

  void check_attributes(const XMLElement* e, const std::string& context) {
    for (auto* a = e->FirstAttribute(); a; a = a->Next()) {
      if (std::strcmp(a->Name(), "id") == 0) continue;
      const std::string name = std::string("@") + a->Name();
      const Rule* r = find_rule(context, name.c_str(), a->Value());
      const std::string shown = shorten(a->Name()) + "=\"" + shorten(a->Value()) + "\"";
      if (!r)
        warn_once(context + "/" + e->Name() + name, path_of(e),
                  "unknown attribute " + shown + " (line " + line(e) + "), ignored" +
                      suggestion(context, name));
      else if (r->support == Support::kUnsupported)
        fail(e, "attribute " + shown + " (line " + line(e) + ") is not supported: " + r->wrong);
    }
  }

  void walk(const XMLElement* e, const std::string& context, bool holds_elements) {
    check_attributes(e, context);
    if (!holds_elements) {
      if (const XMLElement* c = e->FirstChildElement())
        warn_once(context + "/" + e->Name() + "/*", path_of(c),
                  "element inside a value (line " + line(c) + "), ignored");
      return;
    }
    std::map<std::string, const XMLElement*> single;
    std::map<std::pair<std::string, std::string>, const XMLElement*> ids;
    for (auto* n = e->FirstChild(); n; n = n->NextSibling()) {
      if (const auto* t = n->ToText(); t && !is_blank(t->Value()))
        warn_once(context + "#text", path_of(e),
                  "text '" + shorten(t->Value(), 12) + "' between elements, ignored");
      const XMLElement* c = n->ToElement();
      if (!c) continue;
      const Rule* r = find_rule(context, c->Name(), nullptr);
      if (!r) {
        warn_once(
            context + "/" + c->Name(), path_of(c),
            "unknown element (line " + line(c) + "), ignored" + suggestion(context, c->Name()));
        continue;
      }
      if (r->support == Support::kUnsupported) {
        if (is_empty(c)) continue;
        fail(c, "not supported (line " + line(c) + "): " + r->wrong);
      }
      if (!r->many) {
        auto [it, first] = single.emplace(c->Name(), c);
        if (!first)
          fail(c, "repeated at lines " + line(it->second) + " and " + line(c) +
                      " (only one is allowed)");
      }
      if (const char* id = c->Attribute("id")) {
        // Kinds whose shared ids are refused are one namespace; the others keep their own.
        const SharedIds* group = shared_ids_of(context, c->Name());
        const bool shared = group && group->refused;
        const std::string space = shared ? std::string("#") + group->kinds[0] : c->Name();
        auto [it, first] = ids.emplace(std::make_pair(space, std::string(id)), c);
        if (!first && shared && std::strcmp(it->second->Name(), c->Name()) != 0)
          fail(c, "id '" + shorten(id) + "' is also the id of the <" + it->second->Name() +
                      "> at line " + line(it->second) + ": " + group->reference +
                      " could mean either");
        if (!first && !r->ids_repeat)
          fail(c, "id '" + shorten(id) + "' is defined twice, at lines " + line(it->second) +
                      " and " + line(c));
        if (!first)
          warn_once(context + "/" + c->Name() + "#id", path_of(c),
                    "id '" + shorten(id) + "' is used at lines " + line(it->second) + " and " +
                        line(c) + "; both are kept");
      }
      walk(c, r->inner, r->group);
    }
  }

  const std::string& file_;
  std::vector<std::pair<std::string, int>> warnings_;  // Text and how many of its kind.
  std::map<std::string, size_t> kinds_;                // Kind -> index in warnings_.
};

}  // namespace

std::vector<std::string> check_scene_structure(const tinyxml2::XMLDocument& doc,
                                               const std::string& file) {
  return StructureCheck(file).run(doc);
}

std::string misspelling_hint(const tinyxml2::XMLElement* parent, const char* missing) {
  for (auto* c = parent->FirstChildElement(); c; c = c->NextSiblingElement()) {
    bool known = false;
    for (const Rule& r : rules()) known = known || std::strcmp(r.name, c->Name()) == 0;
    if (!known && closest_name(c->Name(), {missing}) == missing)
      return "; <" + shorten(c->Name()) + "> at line " + line(c) +
             " is not a known element: did you mean <" + missing + ">?";
  }
  return "";
}

}  // namespace rt
