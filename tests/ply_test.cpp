// Tests for the PLY reader: exact values in all three encodings, skipping of unused data, error
// messages, and a deterministic mutation fuzz that must end in a valid mesh or rt::InputError.
#include "ply.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <array>
#include <cctype>
#include <cmath>
#include <cstdint>
#include <cstdio>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <random>
#include <string>
#include <type_traits>
#include <vector>

#include "errors.h"

namespace rt {
namespace {

namespace fs = std::filesystem;
using Tri = std::array<int, 3>;
using Vec = std::array<float, 3>;

enum class Enc { kAscii, kLittle, kBig };

// Builds a PLY body in any encoding from the same calls, so one description yields three files.
class Body {
 public:
  explicit Body(Enc enc) : enc_(enc) {}
  Body& f32(float v) { return put(v); }
  Body& f64(double v) { return put(v); }
  Body& u8(uint8_t v) { return put(v); }
  Body& i8(int8_t v) { return put(v); }
  Body& i16(int16_t v) { return put(v); }
  Body& u16(uint16_t v) { return put(v); }
  Body& i32(int32_t v) { return put(v); }
  Body& u32(uint32_t v) { return put(v); }
  Body& eol() {
    if (enc_ == Enc::kAscii) data_ += "\n";
    return *this;
  }
  const std::string& str() const { return data_; }

 private:
  template <class T>
  Body& put(T v) {
    if (enc_ == Enc::kAscii) {
      if constexpr (std::is_floating_point_v<T>) {
        char buf[64];
        std::snprintf(buf, sizeof buf, "%.9g ", static_cast<double>(v));
        data_ += buf;
      } else {
        data_ += std::to_string(static_cast<long long>(v)) + " ";
      }
      return *this;
    }
    char b[sizeof(T)];
    std::memcpy(b, &v, sizeof(T));
    const uint16_t one = 1;
    const bool host_little = *reinterpret_cast<const char*>(&one) == 1;
    if (host_little != (enc_ == Enc::kLittle)) std::reverse(b, b + sizeof(T));
    data_.append(b, sizeof(T));
    return *this;
  }

  Enc enc_;
  std::string data_;
};

std::string format_line(Enc enc) {
  switch (enc) {
    case Enc::kAscii:
      return "format ascii 1.0\n";
    case Enc::kLittle:
      return "format binary_little_endian 1.0\n";
    case Enc::kBig:
      return "format binary_big_endian 1.0\n";
  }
  return "";
}

// A fresh directory per test process, removed at exit.
const fs::path& temp_dir() {
  static const struct Dir {
    fs::path path;
    Dir() {
      std::random_device rd;
      path = fs::temp_directory_path() / ("rt_ply_test_" + std::to_string(rd()));
      fs::create_directories(path);
    }
    ~Dir() {
      std::error_code ec;
      fs::remove_all(path, ec);
    }
  } dir;
  return dir.path;
}

std::string write_file(const std::string& name, const std::string& content) {
  const std::string path = (temp_dir() / name).string();
  std::ofstream(path, std::ios::binary) << content;
  return path;
}

// Reads `path` expecting InputError; checks it is one line naming the file and each needle.
void expect_error(const std::string& path, const std::vector<std::string>& needles) {
  try {
    read_ply(path);
    ADD_FAILURE() << "no error for " << path;
  } catch (const InputError& e) {
    const std::string msg = e.what();
    EXPECT_NE(msg.find(path), std::string::npos) << msg;
    EXPECT_EQ(msg.find('\n'), std::string::npos) << msg;
    for (const std::string& n : needles) {
      EXPECT_NE(msg.find(n), std::string::npos) << n << " in: " << msg;
    }
  }
}

// Four vertices with normals and unused u v / colour; an 'edge' element in between; a triangle and
// a quad with a skipped list before the indices and a skipped int after them.
std::string rich_ply(Enc enc) {
  std::string h = "ply\n" + format_line(enc) +
                  "comment rich test mesh\nobj_info generated\n"
                  "element vertex 4\n"
                  "property float x\nproperty float y\nproperty float z\n"
                  "property float u\nproperty float v\n"
                  "property float nx\nproperty float ny\nproperty float nz\n"
                  "property uchar red\nproperty uchar green\nproperty uchar blue\n"
                  "property list uchar short vlist\n"
                  "element edge 2\nproperty int vertex1\nproperty int vertex2\n"
                  "element face 2\n"
                  "property list uchar float texcoord\n"
                  "property list uchar int vertex_indices\n"
                  "property int flags\n"
                  "element material 1\nproperty double shininess\n"
                  "end_header\n";
  Body b(enc);
  const float p[4][3] = {{0, 0, 0}, {1.5f, 0, 0}, {1.5f, 2.25f, 0}, {-0.125f, 2.25f, 3e-5f}};
  for (int i = 0; i < 4; ++i) {
    b.f32(p[i][0]).f32(p[i][1]).f32(p[i][2]).f32(0.5f).f32(0.75f);
    b.f32(0).f32(0).f32(i == 3 ? -1.0f : 1.0f).u8(255).u8(static_cast<uint8_t>(i)).u8(7);
    b.u8(2).i16(-3).i16(4).eol();
  }
  b.i32(0).i32(1).eol().i32(2).i32(3).eol();
  b.u8(2).f32(0.1f).f32(0.2f).u8(3).i32(0).i32(1).i32(2).i32(-7).eol();
  b.u8(0).u8(4).i32(0).i32(1).i32(2).i32(3).i32(99).eol();
  b.f64(12.5).eol();
  return h + b.str();
}

void expect_rich_mesh(const PlyMesh& m) {
  const std::vector<Vec> pos = {{0, 0, 0}, {1.5f, 0, 0}, {1.5f, 2.25f, 0}, {-0.125f, 2.25f, 3e-5f}};
  const std::vector<Vec> nrm = {{0, 0, 1}, {0, 0, 1}, {0, 0, 1}, {0, 0, -1}};
  const std::vector<Tri> tris = {{0, 1, 2}, {0, 1, 2}, {0, 2, 3}};
  EXPECT_EQ(m.positions, pos);
  EXPECT_EQ(m.normals, nrm);
  EXPECT_EQ(m.triangles, tris);
}

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
  expect_error(write_file("other_name.ply", list_types_ply(Enc::kAscii, "uchar", "int", "idx")),
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
  expect_error(write_file("partial_normals.ply", partial), {"element vertex", "nx"});
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

const std::string kTriHeader =
    "ply\nformat ascii 1.0\nelement vertex 3\nproperty float x\nproperty float y\n"
    "property float z\nelement face 1\nproperty list uchar int vertex_indices\nend_header\n";

TEST(PlyTest, ErrorMissingFile) {
  expect_error((temp_dir() / "does_not_exist.ply").string(), {"cannot open"});
  expect_error(temp_dir().string(), {"cannot open"});  // a directory
}

TEST(PlyTest, ErrorTruncatedBinary) {
  const std::string full = rich_ply(Enc::kLittle);
  // Cut inside the vertex data, then inside the face list.
  const size_t data = full.find("end_header\n") + 11;
  // Too short for the declared count: caught before reading (each vertex takes >= 36 bytes).
  expect_error(write_file("trunc_v.ply", full.substr(0, data + 50)),
               {"element vertex", "count 4", "truncated"});
  // Long enough for the minimum (list items excluded) but the last vertex is cut.
  expect_error(write_file("trunc_v3.ply", full.substr(0, data + 150)),
               {"element vertex", "vertex 3", "end of file"});
  expect_error(write_file("trunc_f.ply", full.substr(0, full.size() - 14)),
               {"element face", "face 1", "end of file"});
}

TEST(PlyTest, ErrorTruncatedAscii) {
  expect_error(write_file("trunc_ascii_v.ply", kTriHeader + "0 0 0\n1 0 0\n1 1\n"),
               {"element vertex", "vertex 2", "end of file"});
  expect_error(write_file("trunc_ascii_f.ply", kTriHeader + "0 0 0\n1 0 0\n1 1 0\n3 0 1\n"),
               {"element face", "face 0", "end of file"});
}

TEST(PlyTest, ErrorIndexOutOfRange) {
  expect_error(write_file("range.ply", kTriHeader + "0 0 0\n1 0 0\n1 1 0\n3 0 1 12\n"),
               {"element face", "face 0", "index 12 out of range [0, 3)"});
  // uint32 indices above INT32_MAX must not wrap to valid ones.
  Body b(Enc::kLittle);
  for (int i = 0; i < 9; ++i) b.f32(0);
  b.u8(3).u32(0).u32(1).u32(4294967295u);
  std::string h = kTriHeader;
  h.replace(h.find("ascii"), 5, "binary_little_endian");
  h.replace(h.find("uchar int"), 9, "uchar uint");
  expect_error(write_file("range_u32.ply", h + b.str()), {"index 4294967295 out of range"});
}

TEST(PlyTest, ErrorNegativeIndex) {
  expect_error(write_file("negative.ply", kTriHeader + "0 0 0\n1 0 0\n1 1 0\n3 0 -1 2\n"),
               {"element face", "face 0", "index -1 out of range"});
}

TEST(PlyTest, ErrorNonFiniteCoordinate) {
  expect_error(write_file("nan.ply", kTriHeader + "0 0 0\n1 nan 0\n1 1 0\n3 0 1 2\n"),
               {"element vertex", "vertex 1", "property y", "nan"});
  expect_error(write_file("inf.ply", kTriHeader + "0 0 0\n1 0 0\n1 1 -inf\n3 0 1 2\n"),
               {"vertex 2", "property z", "inf"});
  expect_error(write_file("overflow.ply", kTriHeader + "1e39 0 0\n1 0 0\n1 1 0\n3 0 1 2\n"),
               {"vertex 0", "property x", "1e+39"});
  Body b(Enc::kBig);
  b.f32(0).f32(0).f32(0).f32(std::nanf("")).f32(0).f32(0).f32(0).f32(1).f32(0);
  std::string h = kTriHeader;
  h.replace(h.find("ascii"), 5, "binary_big_endian");
  expect_error(write_file("nan_be.ply", h + b.u8(3).i32(0).i32(1).i32(2).str()),
               {"vertex 1", "property x", "nan"});
}

TEST(PlyTest, ErrorFaceWithTwoIndices) {
  expect_error(write_file("two.ply", kTriHeader + "0 0 0\n1 0 0\n1 1 0\n2 0 1\n"),
               {"element face", "face 0", "2 indices"});
}

TEST(PlyTest, ErrorUnknownFormatOrType) {
  std::string h = kTriHeader;
  h.replace(h.find("ascii"), 5, "binary_middle_endian");
  expect_error(write_file("format.ply", h), {"header", "binary_middle_endian"});
  h = kTriHeader;
  h.replace(h.find("float x"), 5, "half");
  expect_error(write_file("type.ply", h + "0 0 0\n"), {"header", "half x"});
  expect_error(write_file("nofmt.ply", "ply\nelement vertex 0\nend_header\n"), {"format"});
  expect_error(write_file("noend.ply", "ply\nformat ascii 1.0\nelement vertex 0\n"),
               {"end_header"});
}

TEST(PlyTest, ErrorBadMagic) {
  // Nothing of a file that is not a PLY is quoted (a scene may name /etc/passwd).
  expect_error(write_file("magic.ply", "OFF-secret\n3 1 0\n"), {"not a PLY file"});
  try {
    read_ply(write_file("magic.ply", "OFF-secret\n3 1 0\n"));
  } catch (const InputError& e) {
    EXPECT_EQ(std::string(e.what()).find("secret"), std::string::npos) << e.what();
  }
  expect_error(write_file("empty.ply", ""), {"end_header"});
}

TEST(PlyTest, ErrorAbsurdCounts) {
  std::string list = kTriHeader;
  list.replace(list.find("uchar int"), 9, "int int");
  expect_error(write_file("list.ply", list + "0 0 0\n1 0 0\n1 1 0\n200000 0 1 2\n"),
               {"element face", "face 0", "list count 200000"});
  list.replace(list.find("ascii"), 5, "binary_big_endian");
  Body lb(Enc::kBig);
  for (int i = 0; i < 9; ++i) lb.f32(1);
  lb.i32(-5).i32(0).i32(1).i32(2);
  expect_error(write_file("list_be.ply", list + lb.str()), {"face 0", "list count -5"});
  // A skipped list (not the indices) is guarded the same way.
  std::string skip = kTriHeader;
  skip.replace(skip.find("end_header"), 0, "element edge 1\nproperty list int int pts\n");
  expect_error(write_file("list_skip.ply", skip + "0 0 0\n1 0 0\n1 1 0\n3 0 1 2\n1001 0\n"),
               {"element edge", "edge 0", "property pts", "list count 1001"});
  // Binary: 2 billion vertices cannot fit in a tiny file; must fail before allocating.
  std::string h = kTriHeader;
  h.replace(h.find("ascii"), 5, "binary_little_endian");
  h.replace(h.find("vertex 3"), 8, "vertex 2000000000");
  expect_error(write_file("count.ply", h + std::string(100, '\0')),
               {"element vertex", "count 2000000000"});
  h.replace(h.find("vertex 2000000000"), 17, "vertex 99999999999");
  expect_error(write_file("count64.ply", h), {"header", "99999999999"});
  // ASCII gets the same guard (each value needs at least one byte).
  std::string a = kTriHeader;
  a.replace(a.find("face 1"), 6, "face 1000000000");
  expect_error(write_file("count_ascii.ply", a + "0 0 0\n1 0 0\n1 1 0\n3 0 1 2\n"),
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
