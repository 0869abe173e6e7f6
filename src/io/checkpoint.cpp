#include "io/checkpoint.h"

#include <algorithm>
#include <cstdio>
#include <cstring>
#include <fstream>
#include <stdexcept>

#include "io/file_util.h"

namespace rt {
namespace {

constexpr const char* kMagic = "rtcheckpoint 1\n";

template <typename T>
void append_raw(std::string* out, const std::vector<T>& v) {
  out->append(reinterpret_cast<const char*>(v.data()), v.size() * sizeof(T));
}

// The next "<name> <value>" line from `at`; false at the blank line that ends the header.
bool next_field(const std::vector<uint8_t>& d, size_t* at, std::string* name, std::string* value) {
  const char* begin = reinterpret_cast<const char*>(d.data());
  const void* nl = std::memchr(begin + *at, '\n', d.size() - *at);
  if (!nl) throw std::runtime_error("header not terminated");
  const std::string line(begin + *at, static_cast<const char*>(nl));
  *at += line.size() + 1;
  if (line.empty()) return false;
  const size_t space = line.find(' ');
  if (space == std::string::npos) throw std::runtime_error("bad header line '" + line + "'");
  *name = line.substr(0, space);
  *value = line.substr(space + 1);
  return true;
}

}  // namespace

std::string checkpoint_path_for(const std::string& image) { return image + ".rtcheckpoint"; }

void write_checkpoint(const std::string& path, const Checkpoint& c) {
  std::string bytes = kMagic;
  for (const auto& [name, value] : c.key) bytes += name + " " + value + "\n";
  bytes += "spp " + std::to_string(c.spp) + "\n";
  if (!c.row_spp.empty()) {
    std::string runs;
    for (size_t y = 0, end; y < c.row_spp.size(); y = end) {
      for (end = y + 1; end < c.row_spp.size() && c.row_spp[end] == c.row_spp[y];) ++end;
      runs +=
          (runs.empty() ? "" : ",") + std::to_string(end - y) + "x" + std::to_string(c.row_spp[y]);
    }
    bytes += "rows " + runs + "\n";
  }
  bytes += "pixels " + std::to_string(c.accum.size()) + "\n\n";
  append_raw(&bytes, c.accum);
  append_raw(&bytes, c.primary);
  if (c.primary.size() != c.accum.size())
    throw std::runtime_error(path + ": cannot write checkpoint: inconsistent film");
  if (const int err = write_file_atomic(path, bytes.data(), bytes.size()))
    throw std::runtime_error(path + ": cannot write checkpoint: " + errno_text(err));
}

namespace {

// The header of checkpoint bytes `d`: the key, the counts; *at is left at the film.
Checkpoint parse_header(const std::vector<uint8_t>& d, size_t* at, long long* pixels) {
  const size_t magic = std::strlen(kMagic);
  if (d.size() < magic || std::memcmp(d.data(), kMagic, magic) != 0)
    throw std::runtime_error("not a version 1 checkpoint");
  Checkpoint c;
  *at = magic;
  *pixels = -1;
  c.spp = -1;
  for (std::string name, value; next_field(d, at, &name, &value);) {
    if (name == "spp") {
      c.spp = std::stoi(value);
    } else if (name == "pixels") {
      *pixels = std::stoll(value);
    } else if (name == "rows") {
      for (size_t run = 0; run < value.size();) {
        size_t used = 0;
        const int n = std::stoi(value.substr(run), &used);
        if (n <= 0 || value.compare(run + used, 1, "x") != 0)
          throw std::runtime_error("bad rows '" + value + "'");
        run += used + 1;
        const int s = std::stoi(value.substr(run), &used);
        if (s < 0) throw std::runtime_error("bad rows '" + value + "'");
        c.row_spp.insert(c.row_spp.end(), n, s);
        run += used + (run + used < value.size() ? 1 : 0);
      }
    } else {
      c.key.emplace_back(name, value);
    }
  }
  if (!c.row_spp.empty() && (*pixels % static_cast<long long>(c.row_spp.size()) != 0 ||
                             *std::min_element(c.row_spp.begin(), c.row_spp.end()) != c.spp))
    throw std::runtime_error("its rows do not match its pixels and samples");
  if (c.spp < 0 || *pixels < 0) throw std::runtime_error("damaged header");
  return c;
}

template <typename F>
Checkpoint reading(const std::string& path, F read) {
  try {
    return read();
  } catch (const std::logic_error&) {  // std::stoi on a damaged number.
    throw std::runtime_error(path + ": cannot read checkpoint: damaged header");
  } catch (const std::runtime_error& e) {
    throw std::runtime_error(path + ": cannot read checkpoint: " + e.what());
  }
}

}  // namespace

Checkpoint read_checkpoint(const std::string& path) {
  return reading(path, [&] {
    std::vector<uint8_t> d;
    if (const int err = read_file(path, &d)) throw std::runtime_error(errno_text(err));
    size_t at = 0;
    long long pixels = -1;
    Checkpoint c = parse_header(d, &at, &pixels);
    const uint64_t film =
        static_cast<uint64_t>(pixels) * (sizeof(PixelAccum) + sizeof(PrimaryInfo));
    if (d.size() - at != film)
      throw std::runtime_error("the film is " + std::to_string(d.size() - at) + " bytes, not " +
                               std::to_string(film));
    c.accum.resize(pixels);
    c.primary.resize(pixels);
    std::memcpy(c.accum.data(), d.data() + at, pixels * sizeof(PixelAccum));
    std::memcpy(c.primary.data(), d.data() + at + pixels * sizeof(PixelAccum),
                pixels * sizeof(PrimaryInfo));
    return c;
  });
}

Checkpoint read_checkpoint_header(const std::string& path) {
  return reading(path, [&] {
    std::ifstream in(path, std::ios::binary);
    if (!in) throw std::runtime_error("cannot open");
    // The header is text before the film; its longest line, the rows, stays far below this.
    std::vector<uint8_t> d(1 << 20);
    in.read(reinterpret_cast<char*>(d.data()), static_cast<std::streamsize>(d.size()));
    d.resize(static_cast<size_t>(in.gcount()));
    size_t at = 0;
    long long pixels = -1;
    return parse_header(d, &at, &pixels);
  });
}

std::string key_difference(const CheckpointKey& saved, const CheckpointKey& now) {
  for (const auto& [name, value] : now) {
    std::string old = "absent";
    for (const auto& [n, v] : saved)
      if (n == name) old = v;
    if (old != value) return name + " is " + old + " in the checkpoint, " + value + " in this run";
  }
  return saved.size() == now.size() ? "" : "its key has fields this run does not know";
}

std::string files_hash(const std::vector<std::string>& paths) {
  uint64_t h = 1469598103934665603ull;
  for (const std::string& p : paths) {
    std::vector<uint8_t> d;
    if (const int err = read_file(p, &d))
      throw std::runtime_error(p + ": cannot read: " + errno_text(err));
    for (uint8_t b : d) h = (h ^ b) * 1099511628211ull;
    h = (h ^ 0xff) * 1099511628211ull;  // Separates the files.
  }
  char text[17];
  std::snprintf(text, sizeof text, "%016llx", static_cast<unsigned long long>(h));
  return text;
}

}  // namespace rt
