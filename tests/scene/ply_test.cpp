// The PLY reader on valid input: exact values in all three encodings, list count and item
// types, both names of the index list, fan triangulation, optional normals, CRLF line endings,
// and the course's PLY files.
#include <gtest/gtest.h>

#include <filesystem>
#include <string>
#include <utility>
#include <vector>

#include "util/errors.h"
#include "scene/ply.h"
#include "support/ply_writer.h"

namespace rt {
namespace {

using namespace test;
namespace fs = std::filesystem;

TEST(PlyTest, AllEncodingsGiveTheSameExactMesh) {
  const PlyMesh a = read_ply(write_file("rich_ascii.ply", rich_ply(Enc::kAscii)));
  const PlyMesh le = read_ply(write_file("rich_le.ply", rich_ply(Enc::kLittle)));
  const PlyMesh be = read_ply(write_file("rich_be.ply", rich_ply(Enc::kBig)));
  expect_rich_mesh(a);
  expect_rich_mesh(le);
  expect_rich_mesh(be);
}

// One triangle whose face list uses the given count and item types.
std::string list_types_ply(Enc enc, const std::string& count_t, const std::string& item_t,
                           const std::string& name = "vertex_indices") {
  std::string h = "ply\n" + format_line(enc) +
                  "element vertex 3\nproperty double x\nproperty double y\nproperty double z\n"
                  "element face 1\nproperty list " +
                  count_t + " " + item_t + " " + name + "\nend_header\n";
  Body b(enc);
  for (int i = 0; i < 3; ++i) b.f64(i).f64(2 * i).f64(-i).eol();
  if (count_t == "uchar" || count_t == "uint8") b.u8(3);
  if (count_t == "int" || count_t == "int32") b.i32(3);
  if (count_t == "ushort") b.u16(3);
  for (int i : {2, 0, 1}) {
    if (item_t == "int") b.i32(i);
    if (item_t == "uint") b.u32(i);
    if (item_t == "short") b.i16(i);
    if (item_t == "uchar") b.u8(i);
    if (item_t == "char") b.i8(i);
  }
  return h + b.eol().str();
}

TEST(PlyTest, ListCountAndItemTypes) {
  const std::vector<std::pair<std::string, std::string>> types = {
      {"uchar", "int"},    {"uint8", "int"},   {"int", "int"}, {"int32", "uint"},
      {"ushort", "short"}, {"uchar", "uchar"}, {"int", "char"}};
  int n = 0;
  for (Enc enc : {Enc::kAscii, Enc::kLittle, Enc::kBig}) {
    for (const auto& [c, i] : types) {
      const PlyMesh m =
          read_ply(write_file("types" + std::to_string(n++) + ".ply", list_types_ply(enc, c, i)));
      ASSERT_EQ(m.positions.size(), 3u) << c << " " << i;
      EXPECT_EQ(m.positions[2], (Vec{2, 4, -2}));
      EXPECT_EQ(m.triangles, (std::vector<Tri>{{2, 0, 1}})) << c << " " << i;
      EXPECT_TRUE(m.normals.empty());
    }
  }
}

TEST(PlyTest, VertexIndexAndVertexIndicesNames) {
  for (const char* name : {"vertex_index", "vertex_indices"}) {
    const PlyMesh m = read_ply(
        write_file(std::string(name) + ".ply", list_types_ply(Enc::kAscii, "uchar", "int", name)));
    EXPECT_EQ(m.triangles, (std::vector<Tri>{{2, 0, 1}})) << name;
  }
  expect_ply_error(write_file("other_name.ply", list_types_ply(Enc::kAscii, "uchar", "int", "idx")),
                   {"element face", "vertex_indices"});
}

TEST(PlyTest, QuadAndPentagonAreFanTriangulated) {
  const std::string ply =
      "ply\nformat ascii 1.0\nelement vertex 6\n"
      "property float x\nproperty float y\nproperty float z\n"
      "element face 2\nproperty list uchar int vertex_indices\nend_header\n"
      "0 0 0\n1 0 0\n1 1 0\n0 1 0\n0 2 0\n2 2 0\n"
      "4 0 1 2 3\n"
      "5 5 4 3 2 1\n";
  const PlyMesh m = read_ply(write_file("ngon.ply", ply));
  const std::vector<Tri> expected = {{0, 1, 2}, {0, 2, 3}, {5, 4, 3}, {5, 3, 2}, {5, 2, 1}};
  EXPECT_EQ(m.triangles, expected);
}

TEST(PlyTest, NormalsOnlyWhenPresent) {
  const std::string with =
      "ply\nformat ascii 1.0\nelement vertex 1\nproperty float nx\nproperty float x\n"
      "property float ny\nproperty float y\nproperty float z\nproperty float nz\nend_header\n"
      "0.25 1 0.5 2 3 -0.75\n";
  const PlyMesh m = read_ply(write_file("normals.ply", with));
  EXPECT_EQ(m.positions, (std::vector<Vec>{{1, 2, 3}}));
  EXPECT_EQ(m.normals, (std::vector<Vec>{{0.25f, 0.5f, -0.75f}}));
  EXPECT_TRUE(m.triangles.empty());
  const std::string partial =
      "ply\nformat ascii 1.0\nelement vertex 1\nproperty float x\nproperty float y\n"
      "property float z\nproperty float nx\nend_header\n1 2 3 4\n";
  expect_ply_error(write_file("partial_normals.ply", partial), {"element vertex", "nx"});
}

TEST(PlyTest, CrlfLineEndings) {
  std::string ascii = rich_ply(Enc::kAscii);
  std::string crlf;
  for (char c : ascii) crlf += c == '\n' ? std::string("\r\n") : std::string(1, c);
  expect_rich_mesh(read_ply(write_file("crlf_ascii.ply", crlf)));
  // Binary: CRLF only in the header; the data starts right after "end_header\r\n".
  std::string bin = rich_ply(Enc::kLittle);
  const size_t end = bin.find("end_header\n") + 11;
  std::string header;
  for (char c : bin.substr(0, end)) header += c == '\n' ? std::string("\r\n") : std::string(1, c);
  expect_rich_mesh(read_ply(write_file("crlf_le.ply", header + bin.substr(end))));
}

#ifdef RT_SHARED_SCENES_DIR
const fs::path kScenes = RT_SHARED_SCENES_DIR;
#define RT_REQUIRE_SCENES()                            \
  if (!fs::exists(kScenes / "hw2/ply/cube.ply")) {     \
    GTEST_SKIP() << "no course scenes at " << kScenes; \
  }
#else
const fs::path kScenes;
#define RT_REQUIRE_SCENES() GTEST_SKIP() << "RT_SHARED_SCENES_DIR not defined"
#endif

TEST(PlyTest, CourseCube) {
  RT_REQUIRE_SCENES();
  // ASCII, uchar/int 'vertex_index', six quads -> twelve triangles.
  const PlyMesh m = read_ply((kScenes / "hw2/ply/cube.ply").string());
  ASSERT_EQ(m.positions.size(), 8u);
  EXPECT_EQ(m.positions[6], (Vec{1, 1, 1}));
  EXPECT_TRUE(m.normals.empty());
  ASSERT_EQ(m.triangles.size(), 12u);
  EXPECT_EQ(m.triangles[0], (Tri{0, 1, 2}));
  EXPECT_EQ(m.triangles[1], (Tri{0, 2, 3}));
  EXPECT_EQ(m.triangles[11], (Tri{3, 4, 0}));
}

TEST(PlyTest, CourseTapWater) {
  RT_REQUIRE_SCENES();
  // binary_little_endian, uchar/int 'vertex_indices', triangles only.
  const PlyMesh m = read_ply((kScenes / "hw3/tap_water/ply/tap_water_200_fixed.ply").string());
  EXPECT_EQ(m.positions.size(), 20055u);
  EXPECT_EQ(m.triangles.size(), 39816u);
  for (const Tri& t : m.triangles) {
    for (int i : t) ASSERT_TRUE(i >= 0 && i < 20055);
  }
}

TEST(PlyTest, AllCoursePlyFilesLoad) {
  RT_REQUIRE_SCENES();
  int files = 0;
  for (const auto& entry : fs::recursive_directory_iterator(kScenes)) {
    if (entry.path().extension() != ".ply") continue;
    ++files;
    const PlyMesh m = read_ply(entry.path().string());
    EXPECT_FALSE(m.triangles.empty()) << entry.path();
    const int n = static_cast<int>(m.positions.size());
    for (const Tri& t : m.triangles) {
      for (int i : t) ASSERT_TRUE(i >= 0 && i < n) << entry.path();
    }
  }
  EXPECT_GT(files, 0);
}

}  // namespace
}  // namespace rt
