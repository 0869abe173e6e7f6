// Number and text formatting of the course XML writer (xml_writer.cpp, xml_parts.cpp):
// doubles with 17 significant digits and floats with 9, both of which read back exactly.
#pragma once

#include <cstdio>
#include <ostream>
#include <string>
#include <vector>

#include "convert.h"

namespace rtconvert {
namespace xml {

inline std::string num(double v) {
  char buf[40];
  std::snprintf(buf, sizeof buf, "%.17g", v);
  return buf;
}

inline std::string num(float v) {
  char buf[40];
  std::snprintf(buf, sizeof buf, "%.9g", static_cast<double>(v));
  return buf;
}

inline std::string vec(rt::Vec3d v) { return num(v.x) + " " + num(v.y) + " " + num(v.z); }
inline std::string vec(float3 v) { return num(v.x) + " " + num(v.y) + " " + num(v.z); }

// The five characters XML reserves, escaped (an image name may hold '&').
std::string text(const std::string& s);

// The parts of a scene file (xml_parts.cpp). Materials with a BRDF model refer to the
// <BRDFs> written before them.
void write_brdfs_and_materials(std::ostream& x, const std::vector<Material>& materials);
void write_camera(std::ostream& x, const rt::CameraDesc& c, size_t id);
void write_lights(std::ostream& x, const rt::SceneDesc& s);
// `image_names`: the Image elements' file names, relative to the XML file.
void write_textures(std::ostream& x, const ImportedScene& in,
                    const std::vector<std::string>& image_names);

}  // namespace xml
}  // namespace rtconvert
