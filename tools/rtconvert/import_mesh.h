// Assimp's meshes and transforms as the course's: the pieces of the importer
// (import_assimp.cpp) that read one aiMesh or aiMatrix4x4 and nothing else.
#pragma once

#include <assimp/mesh.h>
#include <assimp/matrix4x4.h>

#include "scene/scene.h"
#include "util/mat4.h"

namespace rtconvert {

rt::Mat4 from_ai(const aiMatrix4x4& a);

// True when some vertex normal leans away from its face: the file means smooth shading.
bool has_smooth_normals(const aiMesh& m);

// `uvs`: the mesh's first texture coordinates are kept, with v flipped (Assimp's origin is
// the bottom left, the course's the top left). `weld`: vertices that differ only in the
// attributes dropped here (texture seams of an untextured mesh) are merged again, so that
// smooth shading does not split along them.
rt::MeshDesc mesh_of(const aiMesh& m, bool uvs, bool weld);

// Whether two meshes hold the same triangles over the same positions and coordinates.
bool same_geometry(const rt::MeshDesc& a, const rt::MeshDesc& b);

}  // namespace rtconvert
