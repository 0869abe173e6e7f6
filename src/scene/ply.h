// Minimal PLY mesh reader: positions, optional normals and texture coordinates, and
// triangulated faces.
#pragma once

#include <array>
#include <string>
#include <vector>

namespace rt {

struct PlyMesh {
  std::vector<std::array<float, 3>> positions;
  std::vector<std::array<float, 3>> normals;  // empty when the file has no nx/ny/nz
  std::vector<std::array<float, 2>> uvs;      // empty when the file has no u/v (or s/t)
  std::vector<std::array<int, 3>> triangles;  // 0-based; quads and n-gons fan-triangulated
};

// Reads an ASCII, binary_little_endian or binary_big_endian PLY file.
// Throws rt::InputError with a one-line message naming the file, the element/property and the
// bad value.
PlyMesh read_ply(const std::string& path);

// The same from the file's bytes in memory; `name` stands for the file in messages.
PlyMesh parse_ply(const std::string& data, const std::string& name);

}  // namespace rt
