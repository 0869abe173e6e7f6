// Names shared by the glTF exporter and importer, and the step that adds what Assimp's
// glTF exporter leaves out (cameras, KHR_lights_punctual, the course's extras).
#pragma once

#include <string>
#include <vector>

#include "convert.h"

namespace rtconvert {

inline std::string object_name(size_t i) { return "object" + std::to_string(i); }
inline std::string material_name(size_t i) { return "material" + std::to_string(i); }
// The node, mesh and material of area light i's emissive quad.
inline std::string area_light_name(size_t i) { return "arealight" + std::to_string(i); }

// A course material with the texture maps of the objects that wear it: glTF and OBJ bind
// textures to materials, the course binds them to objects. Variant i < materials.size()
// is material i untextured; textured combinations follow, in the order objects use them.
struct MaterialVariant {
  int material = 0;
  std::vector<int> textures;
};
std::vector<MaterialVariant> material_variants(const rt::SceneDesc& s);
int variant_of(const std::vector<MaterialVariant>& variants, const rt::ObjectDesc& o);
// material<m> for the untextured ones, material<m>_textured<i> for the others (the importer
// reads the number after "material" as the course material).
std::string variant_name(const std::vector<MaterialVariant>& variants, size_t i);

// The replace_kd (decal) image map among `textures`, -1 when none.
int image_map(const rt::SceneDesc& s, const std::vector<int>& textures, int decal);

void add_course_data_to_glb(const rt::SceneDesc& s, const std::string& path,
                            const std::vector<ImageFile>& images, Report& report);

}  // namespace rtconvert
