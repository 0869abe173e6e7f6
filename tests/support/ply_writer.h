// Writing PLY test files (tests/scene/ply_test.cpp, tests/scene/ply_errors_test.cpp): one
// description of a body in any of the three encodings, a rich mesh that exercises skipped
// data, and the check of a rejected file.
#pragma once

#include <algorithm>
#include <array>
#include <cstdint>
#include <cstdio>
#include <cstring>
#include <filesystem>
#include <string>
#include <type_traits>
#include <vector>

#include "scene/ply.h"

namespace rt::test {

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

// The "format ..." header line of an encoding.
std::string format_line(Enc enc);

// A fresh directory per test process, removed at exit.
const std::filesystem::path& temp_dir();

// Writes `content` to `name` in temp_dir(); returns its path.
std::string write_file(const std::string& name, const std::string& content);

// Reads `path` expecting InputError; checks it is one line naming the file and each needle.
void expect_ply_error(const std::string& path, const std::vector<std::string>& needles);

// Four vertices with normals and unused u v / colour; an 'edge' element in between; a triangle and
// a quad with a skipped list before the indices and a skipped int after them.
std::string rich_ply(Enc enc);

// The mesh rich_ply() describes, exactly.
void expect_rich_mesh(const PlyMesh& m);

}  // namespace rt::test
