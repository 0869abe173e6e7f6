// Names shared by the glTF exporter and importer, and the step that adds what Assimp's
// glTF exporter leaves out (cameras, KHR_lights_punctual, the course's extras).
#pragma once

#include <string>

#include "convert.h"

namespace rtconvert {

inline std::string object_name(size_t i) { return "object" + std::to_string(i); }
inline std::string material_name(size_t i) { return "material" + std::to_string(i); }
// The node, mesh and material of area light i's emissive quad.
inline std::string area_light_name(size_t i) { return "arealight" + std::to_string(i); }

void add_course_data_to_glb(const rt::SceneDesc& s, const std::string& path, Report& report);

}  // namespace rtconvert
