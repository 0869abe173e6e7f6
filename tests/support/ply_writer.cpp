#include "support/ply_writer.h"

#include <gtest/gtest.h>

#include <fstream>
#include <random>

#include "util/errors.h"

namespace rt::test {

namespace fs = std::filesystem;

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

void expect_ply_error(const std::string& path, const std::vector<std::string>& needles) {
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

}  // namespace rt::test
