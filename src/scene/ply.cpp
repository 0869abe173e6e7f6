// PLY reader. The whole file is read into memory and parsed from the buffer: per-token iostream
// parsing is far too slow for million-triangle meshes. Every count and length taken from the
// file is checked against the bytes actually present before it drives a loop or an allocation,
// so malformed input ends in rt::InputError rather than a crash, a hang or a huge allocation.
#include "ply.h"

#include <algorithm>
#include <cfloat>
#include <charconv>
#include <cmath>
#include <cstdint>
#include <cstdio>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <iterator>
#include <sstream>

#include "util/errors.h"

namespace rt {
namespace {

enum class Type { kInt8, kUint8, kInt16, kUint16, kInt32, kUint32, kFloat32, kFloat64 };
constexpr const char* kTypeNames[] = {"int8",  "uint8",  "int16",   "uint16",
                                      "int32", "uint32", "float32", "float64"};
constexpr size_t kTypeSizes[] = {1, 1, 2, 2, 4, 4, 4, 8};
constexpr double kTypeMin[] = {-128, 0, -32768, 0, -2147483648.0, 0};
constexpr double kTypeMax[] = {127, 255, 32767, 65535, 2147483647.0, 4294967295.0};
// The original PLY type names, in the same order.
constexpr const char* kOldTypeNames[] = {"char", "uchar", "short", "ushort",
                                         "int",  "uint",  "float", "double"};
constexpr int kMaxListCount = 1000;  // no sane mesh has faces this large; guards the fuzzers

bool parse_type(const std::string& s, Type* t) {
  for (int i = 0; i < 8; ++i) {
    if (s != kTypeNames[i] && s != kOldTypeNames[i]) continue;
    *t = static_cast<Type>(i);
    return true;
  }
  return false;
}

bool is_float(Type t) { return t == Type::kFloat32 || t == Type::kFloat64; }
bool is_space(char c) {
  return c == ' ' || c == '\t' || c == '\r' || c == '\n' || c == '\v' || c == '\f';
}

// Makes untrusted bytes safe to embed in a one-line message: a short excerpt, printable ASCII.
std::string printable(const char* b, const char* e) {
  std::string s;
  for (; b != e && s.size() < 40; ++b) s += (*b >= 32 && *b < 127) ? *b : '?';
  if (b != e) s += "...";
  return s;
}

std::string num(double v) {
  if (v == std::floor(v) && std::fabs(v) < 1e18) return std::to_string(static_cast<long long>(v));
  char buf[32];
  std::snprintf(buf, sizeof buf, "%g", v);
  return buf;
}

template <class T>
double as(const unsigned char* b) {
  T v;
  std::memcpy(&v, b, sizeof v);
  return static_cast<double>(v);
}
constexpr double (*kDecode[])(const unsigned char*) = {as<int8_t>,   as<uint8_t>, as<int16_t>,
                                                       as<uint16_t>, as<int32_t>, as<uint32_t>,
                                                       as<float>,    as<double>};

bool host_is_little_endian() {
  const uint16_t one = 1;
  unsigned char c;
  std::memcpy(&c, &one, 1);
  return c == 1;
}

// Roles of the properties the mesh needs; everything else is read and dropped.
enum Role { kX, kY, kZ, kNx, kNy, kNz, kIndices, kU, kV, kSkip };

struct Property {
  std::string name;
  Type type = Type::kFloat32;  // item type for lists
  bool is_list = false;
  Type count_type = Type::kUint8;
  Role role = kSkip;
};

struct Element {
  std::string name;
  size_t count = 0;
  std::vector<Property> props;
};

class Parser {
 public:
  Parser(const std::string& path, const std::string& data)
      : path_(path), pos_(data.data()), end_(data.data() + data.size()) {}

  PlyMesh parse() {
    parse_header();
    assign_roles();
    PlyMesh mesh;
    for (const Element& el : elements_) read_element(el, &mesh);
    return mesh;
  }

 private:
  static constexpr size_t kNoItem = static_cast<size_t>(-1);

  [[noreturn]] void header_fail(const std::string& what) const {
    throw input_error(path_, "header", what);
  }

  // Names the element, and the item and property being read when there is one.
  [[noreturn]] void fail(const std::string& what) const {
    std::string where;
    if (item_ != kNoItem) where = el_->name + " " + std::to_string(item_) + ": ";
    if (prop_) where += "property " + prop_->name + ": ";
    throw input_error(path_, "element " + el_->name, where + what);
  }

  void parse_header() {
    for (bool first = true;; first = false) {
      if (pos_ == end_) header_fail("missing end_header");
      const char* b = pos_;
      const char* e = std::find(pos_, end_, '\n');
      pos_ = e == end_ ? end_ : e + 1;
      if (e != b && e[-1] == '\r') --e;  // CRLF files
      if (first) {
        // Nothing of the file is quoted: a scene may name any file (/etc/passwd) as its PLY,
        // and its first line is none of the message's business.
        if (std::string(b, e) != "ply") header_fail("not a PLY file (the first line is not 'ply')");
        continue;
      }
      std::istringstream line(std::string(b, e));  // the header is small: iostreams are fine
      const std::vector<std::string> w{std::istream_iterator<std::string>(line), {}};
      if (w.empty() || w[0] == "comment" || w[0] == "obj_info") continue;
      if (w[0] == "end_header" && w.size() == 1) break;
      if (w[0] == "format" && w.size() == 3 && w[2] == "1.0") {
        if (w[1] == "ascii") {
          ascii_ = true;
        } else if (w[1] == "binary_little_endian" || w[1] == "binary_big_endian") {
          swap_ = (w[1] == "binary_little_endian") != host_is_little_endian();
        } else {
          header_fail("unknown format '" + printable(b, e) + "'");
        }
        have_format_ = true;
      } else if (w[0] == "element" && w.size() == 3) {
        unsigned long long count = 0;
        const char* s = w[2].data();
        auto r = std::from_chars(s, s + w[2].size(), count);
        // Indices are int, so no element may have more than INT32_MAX items.
        if (r.ec != std::errc() || r.ptr != s + w[2].size() || count > 2147483647ull) {
          header_fail("element " + w[1] + ": bad count '" + printable(s, s + w[2].size()) + "'");
        }
        elements_.push_back({w[1], static_cast<size_t>(count), {}});
      } else if (w[0] == "property" && !elements_.empty() && (w.size() == 3 || w.size() == 5)) {
        Property p;
        p.is_list = w.size() == 5;
        p.name = w.back();
        if (p.is_list && w[1] != "list") header_fail("bad property line '" + printable(b, e) + "'");
        if (!parse_type(w[w.size() - 2], &p.type) ||
            (p.is_list && !parse_type(w[2], &p.count_type))) {
          header_fail("unknown type in '" + printable(b, e) + "'");
        }
        if (p.is_list && is_float(p.count_type)) {
          header_fail("list count type must be an integer in '" + printable(b, e) + "'");
        }
        elements_.back().props.push_back(p);
      } else {
        header_fail("bad header line '" + printable(b, e) + "'");
      }
    }
    if (!have_format_) header_fail("missing format line");
  }

  // Marks the properties the mesh needs and checks the vertex and face elements are usable.
  void assign_roles() {
    static const char* kVertexNames[] = {"x", "y", "z", "nx", "ny", "nz"};
    const Element* vertex = nullptr;
    for (Element& el : elements_) {
      el_ = &el;
      const bool is_vertex = el.name == "vertex", is_face = el.name == "face";
      if (is_vertex && vertex) fail("declared twice");
      if (is_vertex) vertex = &el;
      int found = 0;
      for (Property& p : el.props) {
        for (int r = 0; r < 6 && is_vertex; ++r) {
          if (p.name == kVertexNames[r]) p.role = static_cast<Role>(r);
        }
        // Texture coordinates go by several names: u v, s t, texture_u texture_v.
        if (is_vertex && (p.name == "u" || p.name == "s" || p.name == "texture_u")) p.role = kU;
        if (is_vertex && (p.name == "v" || p.name == "t" || p.name == "texture_v")) p.role = kV;
        if (is_face && (p.name == "vertex_indices" || p.name == "vertex_index")) p.role = kIndices;
        if (p.role == kIndices && (!p.is_list || is_float(p.type))) {
          fail(p.name + " must be a list of integers");
        }
        if (p.role < kIndices && p.is_list) fail("property " + p.name + " must not be a list");
        if (p.role != kSkip) found |= 1 << p.role;
      }
      if (is_face && !(found & (1 << kIndices))) fail("no vertex_indices property");
      if (!is_vertex) continue;
      if ((found & 7) != 7) fail("missing x, y or z property");
      if ((found & 56) != 0 && (found & 56) != 56) fail("normals need all of nx, ny and nz");
      has_normals_ = (found & 56) != 0;
      const int uv_bits = (1 << kU) | (1 << kV);
      if ((found & uv_bits) != 0 && (found & uv_bits) != uv_bits)
        fail("texture coordinates need both u and v (or s and t)");
      has_uvs_ = (found & uv_bits) != 0;
    }
    if (!vertex) header_fail("no vertex element");
    vertex_count_ = vertex->count;
  }

  double ascii_scalar(Type t) {
    while (pos_ != end_ && is_space(*pos_)) ++pos_;
    const char* b = pos_;
    while (pos_ != end_ && !is_space(*pos_)) ++pos_;
    if (b == pos_) fail("unexpected end of file");
    // from_chars rejects a leading '+', which some writers emit.
    const char* s = (*b == '+' && pos_ - b > 1 && b[1] != '-') ? b + 1 : b;
    if (is_float(t)) {
      double v;
      auto r = std::from_chars(s, pos_, v);
      if (r.ec == std::errc() && r.ptr == pos_) return v;
    } else {
      long long v;
      auto r = std::from_chars(s, pos_, v);
      int i = static_cast<int>(t);
      if (r.ec == std::errc() && r.ptr == pos_ && v >= kTypeMin[i] && v <= kTypeMax[i]) return v;
    }
    fail(std::string("bad ") + kTypeNames[static_cast<int>(t)] + " value '" + printable(b, pos_) +
         "'");
  }

  double binary_scalar(Type t) {
    const size_t n = kTypeSizes[static_cast<int>(t)];
    if (static_cast<size_t>(end_ - pos_) < n) fail("unexpected end of file");
    unsigned char b[8];
    std::memcpy(b, pos_, n);
    pos_ += n;
    if (swap_) std::reverse(b, b + n);
    return kDecode[static_cast<int>(t)](b);
  }

  double scalar(Type t) { return ascii_ ? ascii_scalar(t) : binary_scalar(t); }

  void read_element(const Element& el, PlyMesh* mesh) {
    el_ = &el;
    prop_ = nullptr;
    item_ = kNoItem;
    if (el.props.empty()) return;  // nothing to read, however large the count
    // Every item takes at least this many bytes, which bounds the count by the file size.
    size_t min_bytes = 0;
    for (const Property& p : el.props) {
      min_bytes += ascii_ ? 1 : kTypeSizes[static_cast<int>(p.is_list ? p.count_type : p.type)];
    }
    const size_t left = static_cast<size_t>(end_ - pos_);
    if (el.count > left / min_bytes) {
      fail("count " + std::to_string(el.count) + " needs at least " +
           std::to_string(el.count * min_bytes) + " bytes but only " + std::to_string(left) +
           " remain (truncated file?)");
    }
    const bool vertex = el.name == "vertex";
    if (vertex) mesh->positions.reserve(el.count);
    if (vertex && has_normals_) mesh->normals.reserve(el.count);
    if (el.name == "face") mesh->triangles.reserve(el.count);
    double v[kSkip] = {};
    std::vector<int> idx;
    for (item_ = 0; item_ < el.count; ++item_) {
      for (const Property& p : el.props) {
        prop_ = &p;
        if (!p.is_list) {
          const double x = scalar(p.type);
          if (p.role == kSkip) continue;
          // Also rejects values that would overflow float, before the conversion.
          if (!(std::fabs(x) <= FLT_MAX)) fail("value " + num(x) + " is not a finite float");
          v[p.role] = x;
          continue;
        }
        const double n = scalar(p.count_type);
        if (n < 0 || n > kMaxListCount) fail("list count " + num(n) + " out of range [0, 1000]");
        const int count = static_cast<int>(n);
        if (p.role != kIndices) {
          for (int i = 0; i < count; ++i) scalar(p.type);
          continue;
        }
        if (count < 3) fail("face has " + std::to_string(count) + " indices, needs at least 3");
        idx.clear();
        for (int i = 0; i < count; ++i) {
          const double x = scalar(p.type);
          if (x < 0 || x >= vertex_count_) {
            fail("index " + num(x) + " out of range [0, " + std::to_string(vertex_count_) + ")");
          }
          idx.push_back(static_cast<int>(x));
        }
        for (int i = 1; i + 1 < count; ++i) mesh->triangles.push_back({idx[0], idx[i], idx[i + 1]});
      }
      if (!vertex) continue;
      mesh->positions.push_back({float(v[kX]), float(v[kY]), float(v[kZ])});
      if (has_normals_) mesh->normals.push_back({float(v[kNx]), float(v[kNy]), float(v[kNz])});
      if (has_uvs_) mesh->uvs.push_back({float(v[kU]), float(v[kV])});
    }
  }

  const std::string& path_;
  const char* pos_;
  const char* end_;
  bool ascii_ = false;
  bool swap_ = false;
  bool have_format_ = false;
  bool has_normals_ = false;
  bool has_uvs_ = false;
  size_t vertex_count_ = 0;
  std::vector<Element> elements_;
  // What is being read, for error messages.
  const Element* el_ = nullptr;
  size_t item_ = kNoItem;
  const Property* prop_ = nullptr;
};

// file_size also rejects directories, which an ifstream would happily open.
std::string read_file(const std::string& path) {
  std::error_code ec;
  const auto size = std::filesystem::file_size(path, ec);
  if (ec) throw input_error(path, "file", "cannot open: " + ec.message());
  std::string data(size, '\0');
  std::ifstream in(path, std::ios::binary);
  if (!in.read(data.data(), static_cast<std::streamsize>(size))) {
    throw input_error(path, "file", "cannot read");
  }
  return data;
}

}  // namespace

PlyMesh read_ply(const std::string& path) { return parse_ply(read_file(path), path); }

PlyMesh parse_ply(const std::string& data, const std::string& name) {
  return Parser(name, data).parse();
}

}  // namespace rt
