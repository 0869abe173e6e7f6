// Reader of the course's binary geometry files; the layout is described in binary_data.h.
#include "scene/loader/binary_data.h"

#include <cerrno>
#include <cstring>
#include <fstream>
#include <iterator>

#include "util/errors.h"

namespace rt {
namespace loader {

namespace {

// Assembles the word from bytes explicitly, so a big-endian host reads the same values.
uint32_t little_endian_word(const unsigned char* b) {
  return static_cast<uint32_t>(b[0]) | static_cast<uint32_t>(b[1]) << 8 |
         static_cast<uint32_t>(b[2]) << 16 | static_cast<uint32_t>(b[3]) << 24;
}

}  // namespace

std::vector<uint32_t> read_binary_records(const std::string& path, int per_record) {
  std::ifstream in(path, std::ios::binary);
  if (!in) throw input_error(path, "file", std::string("cannot open: ") + std::strerror(errno));
  std::vector<unsigned char> bytes((std::istreambuf_iterator<char>(in)),
                                   std::istreambuf_iterator<char>());
  if (in.bad()) throw input_error(path, "file", "cannot read");
  if (bytes.size() < 4)
    throw input_error(path, "header",
                      "truncated: " + std::to_string(bytes.size()) +
                          " bytes, fewer than the 4 of the record count");
  const int32_t count = static_cast<int32_t>(little_endian_word(bytes.data()));
  if (count < 0)
    throw input_error(path, "header", "record count " + std::to_string(count) + " is negative");
  const uint64_t record_bytes = 4ull * static_cast<uint64_t>(per_record);
  const uint64_t expected = 4 + record_bytes * static_cast<uint64_t>(count);
  const std::string declared = "the count says " + std::to_string(count) + " record" +
                               (count == 1 ? "" : "s") + " of " + std::to_string(per_record) +
                               " values (" + std::to_string(expected) + " bytes)";
  if (bytes.size() < expected)
    throw input_error(
        path, "data",
        "truncated: " + declared + " but the file has " + std::to_string(bytes.size()) + " bytes");
  if (bytes.size() > expected)
    throw input_error(path, "data",
                      "count mismatch: " + declared + " but the file has " +
                          std::to_string(bytes.size()) + " bytes");
  std::vector<uint32_t> words(static_cast<size_t>(count) * per_record);
  for (size_t i = 0; i < words.size(); ++i) words[i] = little_endian_word(&bytes[4 + 4 * i]);
  return words;
}

std::vector<float> words_as_floats(const std::vector<uint32_t>& words) {
  std::vector<float> out(words.size());
  for (size_t i = 0; i < words.size(); ++i) std::memcpy(&out[i], &words[i], sizeof(float));
  return out;
}

std::vector<int32_t> words_as_ints(const std::vector<uint32_t>& words) {
  std::vector<int32_t> out(words.size());
  for (size_t i = 0; i < words.size(); ++i) std::memcpy(&out[i], &words[i], sizeof(int32_t));
  return out;
}

}  // namespace loader
}  // namespace rt
