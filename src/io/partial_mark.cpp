#include "io/partial_mark.h"

#include <OpenEXR/ImfHeader.h>
#include <OpenEXR/ImfInputFile.h>
#include <OpenEXR/ImfStringAttribute.h>

#include <cstring>
#include <filesystem>
#include <vector>

#include "io/file_util.h"
#include "io/image_output.h"

namespace rt {
namespace {

uint32_t be32(const uint8_t* p) {
  return uint32_t{p[0]} << 24 | uint32_t{p[1]} << 16 | uint32_t{p[2]} << 8 | p[3];
}

// The PNG's tEXt chunks come before its image data (png_write_info writes them).
bool png_mark(const std::vector<uint8_t>& d, std::string* mark) {
  static const uint8_t kSig[8] = {137, 80, 78, 71, 13, 10, 26, 10};
  if (d.size() < 8 || std::memcmp(d.data(), kSig, 8) != 0) return false;
  const std::string key = kSamplesMarkKey;
  for (size_t at = 8; at + 8 <= d.size();) {
    const uint32_t len = be32(&d[at]);
    const std::string type(reinterpret_cast<const char*>(&d[at + 4]), 4);
    if (at + 12 + uint64_t{len} > d.size()) return false;
    const char* body = reinterpret_cast<const char*>(&d[at + 8]);
    if (type == "tEXt" && len > key.size() && std::memcmp(body, key.c_str(), key.size() + 1) == 0)
      *mark = std::string(body + key.size() + 1, len - key.size() - 1);
    if (type == "IEND") return true;
    at += 12 + len;
  }
  return false;
}

// The comment markers before the JPEG's first scan.
bool jpeg_mark(const std::vector<uint8_t>& d, std::string* mark) {
  if (d.size() < 4 || d[0] != 0xFF || d[1] != 0xD8) return false;
  const std::string prefix = std::string(kSamplesMarkKey) + "=";
  for (size_t at = 2; at + 4 <= d.size();) {
    if (d[at] != 0xFF) return false;
    const uint8_t type = d[at + 1];
    const size_t len = size_t{d[at + 2]} << 8 | d[at + 3];
    if (type == 0xDA) return true;
    if (len < 2 || at + 2 + len > d.size()) return false;
    const std::string body(reinterpret_cast<const char*>(&d[at + 4]), len - 2);
    if (type == 0xFE && body.compare(0, prefix.size(), prefix) == 0)
      *mark = body.substr(prefix.size());
    at += 2 + len;
  }
  return false;
}

bool exr_mark(const std::string& path, std::string* mark) {
  try {
    Imf::InputFile in(path.c_str());
    if (const auto* a = in.header().findTypedAttribute<Imf::StringAttribute>(kSamplesMarkKey))
      *mark = a->value();
    return in.isComplete();
  } catch (const std::exception&) {
    return false;
  }
}

}  // namespace

std::string samples_mark_text(int spp, int asked) {
  return std::to_string(spp) + " of " + std::to_string(asked);
}

OutputStatus output_status(const std::string& path) {
  OutputStatus s;
  std::error_code ec;
  if (!std::filesystem::exists(path, ec)) return s;
  bool ok = false;
  if (image_format_of(path) == ImageFormat::kExr) {
    ok = exr_mark(path, &s.mark);
  } else {
    std::vector<uint8_t> bytes;
    if (read_file(path, &bytes) == 0)
      ok = image_format_of(path) == ImageFormat::kJpeg ? jpeg_mark(bytes, &s.mark)
                                                       : png_mark(bytes, &s.mark);
  }
  // Only a mark makes an output partial: a file this program cannot parse is not one it
  // wrote (its writes are atomic, never cut short), so it counts as there, as it always did.
  if (!ok) s.mark.clear();
  s.state = s.mark.empty() ? OutputState::kComplete : OutputState::kPartial;
  return s;
}

}  // namespace rt
