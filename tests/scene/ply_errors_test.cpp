// The PLY reader on bad input: every error is one line naming the file and the offending
// value, and a deterministic mutation fuzz must end in a valid mesh or rt::InputError.
#include <gtest/gtest.h>

#include <cctype>
#include <cmath>
#include <fstream>
#include <random>
#include <stdexcept>
#include <string>

#include "util/errors.h"
#include "scene/ply.h"
#include "support/ply_writer.h"

namespace rt {
namespace {

using namespace test;

const std::string kTriHeader =
    "ply\nformat ascii 1.0\nelement vertex 3\nproperty float x\nproperty float y\n"
    "property float z\nelement face 1\nproperty list uchar int vertex_indices\nend_header\n";

TEST(PlyTest, ErrorMissingFile) {
  expect_ply_error((temp_dir() / "does_not_exist.ply").string(), {"cannot open"});
  expect_ply_error(temp_dir().string(), {"cannot open"});  // a directory
}

TEST(PlyTest, ErrorTruncatedBinary) {
  const std::string full = rich_ply(Enc::kLittle);
  // Cut inside the vertex data, then inside the face list.
  const size_t data = full.find("end_header\n") + 11;
  // Too short for the declared count: caught before reading (each vertex takes >= 36 bytes).
  expect_ply_error(write_file("trunc_v.ply", full.substr(0, data + 50)),
                   {"element vertex", "count 4", "truncated"});
  // Long enough for the minimum (list items excluded) but the last vertex is cut.
  expect_ply_error(write_file("trunc_v3.ply", full.substr(0, data + 150)),
                   {"element vertex", "vertex 3", "end of file"});
  expect_ply_error(write_file("trunc_f.ply", full.substr(0, full.size() - 14)),
                   {"element face", "face 1", "end of file"});
}

TEST(PlyTest, ErrorTruncatedAscii) {
  expect_ply_error(write_file("trunc_ascii_v.ply", kTriHeader + "0 0 0\n1 0 0\n1 1\n"),
                   {"element vertex", "vertex 2", "end of file"});
  expect_ply_error(write_file("trunc_ascii_f.ply", kTriHeader + "0 0 0\n1 0 0\n1 1 0\n3 0 1\n"),
                   {"element face", "face 0", "end of file"});
}

TEST(PlyTest, ErrorIndexOutOfRange) {
  expect_ply_error(write_file("range.ply", kTriHeader + "0 0 0\n1 0 0\n1 1 0\n3 0 1 12\n"),
                   {"element face", "face 0", "index 12 out of range [0, 3)"});
  // uint32 indices above INT32_MAX must not wrap to valid ones.
  Body b(Enc::kLittle);
  for (int i = 0; i < 9; ++i) b.f32(0);
  b.u8(3).u32(0).u32(1).u32(4294967295u);
  std::string h = kTriHeader;
  h.replace(h.find("ascii"), 5, "binary_little_endian");
  h.replace(h.find("uchar int"), 9, "uchar uint");
  expect_ply_error(write_file("range_u32.ply", h + b.str()), {"index 4294967295 out of range"});
}

TEST(PlyTest, ErrorNegativeIndex) {
  expect_ply_error(write_file("negative.ply", kTriHeader + "0 0 0\n1 0 0\n1 1 0\n3 0 -1 2\n"),
                   {"element face", "face 0", "index -1 out of range"});
}

TEST(PlyTest, ErrorNonFiniteCoordinate) {
  expect_ply_error(write_file("nan.ply", kTriHeader + "0 0 0\n1 nan 0\n1 1 0\n3 0 1 2\n"),
                   {"element vertex", "vertex 1", "property y", "nan"});
  expect_ply_error(write_file("inf.ply", kTriHeader + "0 0 0\n1 0 0\n1 1 -inf\n3 0 1 2\n"),
                   {"vertex 2", "property z", "inf"});
  expect_ply_error(write_file("overflow.ply", kTriHeader + "1e39 0 0\n1 0 0\n1 1 0\n3 0 1 2\n"),
                   {"vertex 0", "property x", "1e+39"});
  Body b(Enc::kBig);
  b.f32(0).f32(0).f32(0).f32(std::nanf("")).f32(0).f32(0).f32(0).f32(1).f32(0);
  std::string h = kTriHeader;
  h.replace(h.find("ascii"), 5, "binary_big_endian");
  expect_ply_error(write_file("nan_be.ply", h + b.u8(3).i32(0).i32(1).i32(2).str()),
                   {"vertex 1", "property x", "nan"});
}

TEST(PlyTest, ErrorFaceWithTwoIndices) {
  expect_ply_error(write_file("two.ply", kTriHeader + "0 0 0\n1 0 0\n1 1 0\n2 0 1\n"),
                   {"element face", "face 0", "2 indices"});
}

TEST(PlyTest, ErrorUnknownFormatOrType) {
  std::string h = kTriHeader;
  h.replace(h.find("ascii"), 5, "binary_middle_endian");
  expect_ply_error(write_file("format.ply", h), {"header", "binary_middle_endian"});
  h = kTriHeader;
  h.replace(h.find("float x"), 5, "half");
  expect_ply_error(write_file("type.ply", h + "0 0 0\n"), {"header", "half x"});
  expect_ply_error(write_file("nofmt.ply", "ply\nelement vertex 0\nend_header\n"), {"format"});
  expect_ply_error(write_file("noend.ply", "ply\nformat ascii 1.0\nelement vertex 0\n"),
                   {"end_header"});
}

TEST(PlyTest, ErrorBadMagic) {
  // Nothing of a file that is not a PLY is quoted (a scene may name /etc/passwd).
  expect_ply_error(write_file("magic.ply", "OFF-secret\n3 1 0\n"), {"not a PLY file"});
  try {
    read_ply(write_file("magic.ply", "OFF-secret\n3 1 0\n"));
  } catch (const InputError& e) {
    EXPECT_EQ(std::string(e.what()).find("secret"), std::string::npos) << e.what();
  }
  expect_ply_error(write_file("empty.ply", ""), {"end_header"});
}

TEST(PlyTest, ErrorAbsurdCounts) {
  std::string list = kTriHeader;
  list.replace(list.find("uchar int"), 9, "int int");
  expect_ply_error(write_file("list.ply", list + "0 0 0\n1 0 0\n1 1 0\n200000 0 1 2\n"),
                   {"element face", "face 0", "list count 200000"});
  list.replace(list.find("ascii"), 5, "binary_big_endian");
  Body lb(Enc::kBig);
  for (int i = 0; i < 9; ++i) lb.f32(1);
  lb.i32(-5).i32(0).i32(1).i32(2);
  expect_ply_error(write_file("list_be.ply", list + lb.str()), {"face 0", "list count -5"});
  // A skipped list (not the indices) is guarded the same way.
  std::string skip = kTriHeader;
  skip.replace(skip.find("end_header"), 0, "element edge 1\nproperty list int int pts\n");
  expect_ply_error(write_file("list_skip.ply", skip + "0 0 0\n1 0 0\n1 1 0\n3 0 1 2\n1001 0\n"),
                   {"element edge", "edge 0", "property pts", "list count 1001"});
  // Binary: 2 billion vertices cannot fit in a tiny file; must fail before allocating.
  std::string h = kTriHeader;
  h.replace(h.find("ascii"), 5, "binary_little_endian");
  h.replace(h.find("vertex 3"), 8, "vertex 2000000000");
  expect_ply_error(write_file("count.ply", h + std::string(100, '\0')),
                   {"element vertex", "count 2000000000"});
  h.replace(h.find("vertex 2000000000"), 17, "vertex 99999999999");
  expect_ply_error(write_file("count64.ply", h), {"header", "99999999999"});
  // ASCII gets the same guard (each value needs at least one byte).
  std::string a = kTriHeader;
  a.replace(a.find("face 1"), 6, "face 1000000000");
  expect_ply_error(write_file("count_ascii.ply", a + "0 0 0\n1 0 0\n1 1 0\n3 0 1 2\n"),
                   {"element face", "count 1000000000"});
}

// Mutated valid files must yield either a consistent mesh or InputError, never anything else.
TEST(PlyTest, FuzzMutationsNeverCrash) {
  const std::string bases[] = {rich_ply(Enc::kLittle), rich_ply(Enc::kAscii), rich_ply(Enc::kBig)};
  std::mt19937 rng(12345);
  const std::string path = (temp_dir() / "fuzz.ply").string();
  int meshes = 0, errors = 0;
  for (int iter = 0; iter < 2000; ++iter) {
    std::string s = bases[iter % 3];
    const size_t header_end = s.find("end_header") + 10;
    auto pick = [&](size_t n) { return std::uniform_int_distribution<size_t>(0, n - 1)(rng); };
    switch (pick(5)) {
      case 0:  // flip random bytes anywhere
        for (size_t k = 0, n = 1 + pick(4); k < n; ++k) s[pick(s.size())] ^= 1 << pick(8);
        break;
      case 1:  // truncate
        s.resize(pick(s.size()));
        break;
      case 2:  // insert random bytes in the header
        s.insert(pick(header_end), std::string(1 + pick(3), static_cast<char>(pick(256))));
        break;
      case 3:  // change a digit in the header, so counts grow or shrink
        for (size_t k = 0; k < 20; ++k) {
          const size_t i = pick(header_end);
          if (std::isdigit(static_cast<unsigned char>(s[i]))) {
            s[i] = static_cast<char>('0' + pick(10));
            break;
          }
        }
        break;
      default:  // overwrite a byte in the data with an extreme value
        s[header_end + 1 + pick(s.size() - header_end - 1)] =
            static_cast<char>(pick(2) ? 0xff : 0x7f);
        break;
    }
    std::ofstream(path, std::ios::binary | std::ios::trunc) << s;
    try {
      const PlyMesh m = read_ply(path);
      ++meshes;
      const int n = static_cast<int>(m.positions.size());
      ASSERT_TRUE(m.normals.empty() || m.normals.size() == m.positions.size()) << iter;
      for (const Tri& t : m.triangles) {
        for (int i : t) ASSERT_TRUE(i >= 0 && i < n) << "iteration " << iter;
      }
      for (const Vec& p : m.positions) {
        for (float c : p) ASSERT_TRUE(std::isfinite(c)) << "iteration " << iter;
      }
    } catch (const InputError& e) {
      ++errors;
      ASSERT_NE(std::string(e.what()).find(path), std::string::npos) << e.what();
    } catch (const std::exception& e) {
      FAIL() << "iteration " << iter << ": unexpected exception " << e.what();
    }
  }
  // Both outcomes must actually be exercised, or the fuzz is not testing much.
  EXPECT_GT(meshes, 100);
  EXPECT_GT(errors, 100);
}

}  // namespace
}  // namespace rt
