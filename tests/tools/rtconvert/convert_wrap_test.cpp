// rtconvert's texture-coordinate wrapping on import (texture_import.h): the other formats
// repeat a texture outside [0, 1]^2, the course clamps, so triangles are moved by whole
// repeats, with their vertices copied where neighbours move differently.
#include <gtest/gtest.h>

#include "texture_import.h"

namespace rtconvert {
namespace {

TEST(WrapTextureCoordinates, TrianglesMoveByWholeRepeatsIntoTheUnitSquare) {
  rt::MeshDesc m;
  m.positions = {{0, 0, 0}, {1, 0, 0}, {1, 1, 0}, {2, 0, 0}, {2, 1, 0}};
  m.uvs = {{0, 0}, {1, 0}, {1, 1}, {2, 0}, {2, 1}};
  // A lies in the first repeat and stays; B in the second, so it moves by one and its
  // vertices, shared with A and C, are copied; C spans two repeats and cannot move.
  m.triangles = {{0, 1, 2}, {1, 3, 4}, {0, 3, 4}};
  const rt::MeshDesc in = m;
  EXPECT_EQ(wrap_texture_coordinates(m), 1);
  ASSERT_EQ(m.triangles.size(), 3u);
  EXPECT_EQ(m.positions.size(), 8u);  // A's 3, B's 3 moved copies, C's 2 not yet used.
  const std::array<double, 2> b[3] = {{0, 0}, {1, 0}, {1, 1}};
  for (int t = 0; t < 3; ++t)
    for (int k = 0; k < 3; ++k) {
      // Positions go with their coordinates.
      EXPECT_EQ(m.positions[m.triangles[t][k]].x, in.positions[in.triangles[t][k]].x);
      EXPECT_EQ(m.uvs[m.triangles[t][k]], t == 1 ? b[k] : in.uvs[in.triangles[t][k]]);
    }
}

TEST(WrapTextureCoordinates, CoordinatesInsideTheUnitSquareStay) {
  rt::MeshDesc m;
  m.positions = {{0, 0, 0}, {1, 0, 0}, {1, 1, 0}};
  m.uvs = {{0, 0}, {1, 0}, {1, 1}};  // 1 is the right edge, not the next repeat's start.
  m.triangles = {{0, 1, 2}};
  rt::MeshDesc in = m;
  EXPECT_EQ(wrap_texture_coordinates(m), 0);
  EXPECT_EQ(m.uvs, in.uvs);
  EXPECT_EQ(m.triangles, in.triangles);
}

}  // namespace
}  // namespace rtconvert
