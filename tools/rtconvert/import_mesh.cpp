#include "import_mesh.h"

#include <array>
#include <map>
#include <string>
#include <vector>

namespace rtconvert {

rt::Mat4 from_ai(const aiMatrix4x4& a) {
  rt::Mat4 m;
  for (int r = 0; r < 4; ++r)
    for (int c = 0; c < 4; ++c) m(r, c) = a[r][c];
  return m;
}

bool has_smooth_normals(const aiMesh& m) {
  if (!m.HasNormals()) return false;
  for (unsigned f = 0; f < m.mNumFaces; ++f) {
    const aiFace& face = m.mFaces[f];
    aiVector3D a = m.mVertices[face.mIndices[0]], b = m.mVertices[face.mIndices[1]],
               c = m.mVertices[face.mIndices[2]];
    aiVector3D n = (b - a) ^ (c - a);
    if (n.Length() == 0) continue;
    n.Normalize();
    for (int k = 0; k < 3; ++k) {
      aiVector3D v = m.mNormals[face.mIndices[k]];
      if (v.Length() > 0 && (v.Normalize() * n) < 0.999f) return true;
    }
  }
  return false;
}

rt::MeshDesc mesh_of(const aiMesh& m, bool uvs, bool weld) {
  rt::MeshDesc d;
  d.element = std::string("mesh '") + m.mName.C_Str() + "'";
  std::vector<int> index(m.mNumVertices);
  std::map<std::array<float, 6>, int> seen;
  for (unsigned i = 0; i < m.mNumVertices; ++i) {
    const aiVector3D p = m.mVertices[i], n = m.HasNormals() ? m.mNormals[i] : aiVector3D();
    if (weld) {
      auto [it, added] = seen.emplace(std::array<float, 6>{p.x, p.y, p.z, n.x, n.y, n.z},
                                      static_cast<int>(d.positions.size()));
      index[i] = it->second;
      if (!added) continue;
    } else {
      index[i] = static_cast<int>(d.positions.size());
    }
    d.positions.push_back({p.x, p.y, p.z});
    if (uvs) d.uvs.push_back({m.mTextureCoords[0][i].x, 1.0 - m.mTextureCoords[0][i].y});
  }
  for (unsigned f = 0; f < m.mNumFaces; ++f)
    if (m.mFaces[f].mNumIndices == 3)
      d.triangles.push_back({index[m.mFaces[f].mIndices[0]], index[m.mFaces[f].mIndices[1]],
                             index[m.mFaces[f].mIndices[2]]});
  return d;
}

bool same_geometry(const rt::MeshDesc& a, const rt::MeshDesc& b) {
  if (a.triangles != b.triangles || a.positions.size() != b.positions.size() || a.uvs != b.uvs)
    return false;
  for (size_t i = 0; i < a.positions.size(); ++i)
    if (a.positions[i].x != b.positions[i].x || a.positions[i].y != b.positions[i].y ||
        a.positions[i].z != b.positions[i].z)
      return false;
  return true;
}

}  // namespace rtconvert
