#include "job_count.h"

#include <cstring>
#include <fstream>
#include <iterator>

namespace rt {

int count_scene_cameras(const std::string& path) {
  std::ifstream in(path, std::ios::binary);
  if (!in) return 0;
  const std::string text((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
  int n = 0;
  for (size_t i = text.find('<'); i != std::string::npos; i = text.find('<', i + 1)) {
    if (text.compare(i, 4, "<!--") == 0) {
      i = text.find("-->", i + 4);
      if (i == std::string::npos) break;
      continue;
    }
    // "<Camera" followed by a space or the end of the tag: not "<Cameras".
    if (text.compare(i, 7, "<Camera") == 0 && i + 7 < text.size() &&
        std::strchr(" \t\r\n>/", text[i + 7]))
      ++n;
  }
  return n;
}

}  // namespace rt
