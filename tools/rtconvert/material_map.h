// The mapping of other formats' materials (as Assimp presents them) to the course's model;
// the table is in README.md ("Importing and exporting").
#pragma once

#include <assimp/material.h>

#include <string>

#include "convert.h"

namespace rtconvert {

struct MappedMaterial {
  Material material{};
  float3 emission{};  // Radiance of an emissive surface (0 when none), for area lights.
  std::string name;
};

MappedMaterial map_material(const aiMaterial& m, const std::string& file, Report& report);

}  // namespace rtconvert
