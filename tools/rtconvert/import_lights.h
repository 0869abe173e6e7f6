// Cameras and lights of an imported file, and the defaults that let a file without them
// render at once.
#pragma once

#include <assimp/scene.h>

#include "convert.h"

namespace rtconvert {

// An emissive mesh of two triangles over four corners that form a parallelogram (in world
// space) becomes an area light emitting `radiance`; false when the mesh is anything else.
bool parallelogram_light(const aiMesh& m, const rt::Mat4& world, float3 radiance, AreaLight& out);

// `gltf`: the file is glTF 2.0, whose field of view Assimp stores its own way.
void import_cameras(const aiScene& ai, const std::string& file, bool gltf, int width,
                    rt::SceneDesc& s, Report& report);
// `photometric`: glTF's KHR_lights_punctual units (candela, lux); other formats' light
// colours are read as the irradiance they give at the scene's centre.
void import_lights(const aiScene& ai, const std::string& file, bool photometric, rt::SceneDesc& s,
                   Report& report);
// A camera framing the scene and a light beside it, when the file has none.
void add_defaults(const std::string& file, int width, rt::SceneDesc& s, Report& report);

}  // namespace rtconvert
