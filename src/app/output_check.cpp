#include "output_check.h"

#include <unistd.h>

#include <filesystem>

#include "scene/xml_text.h"

namespace rt {
namespace {

namespace fs = std::filesystem;

// The folder's own limits; POSIX minimums where the file system does not say.
long limit(const std::string& dir, int name, long fallback) {
  const long v = pathconf(dir.c_str(), name);
  return v > 0 ? v : fallback;
}

}  // namespace

std::string output_file_problem(const std::string& output_dir, const std::string& path) {
  const long name_max = limit(output_dir, _PC_NAME_MAX, 255);
  const long path_max = limit(output_dir, _PC_PATH_MAX, 4096);
  const fs::path p(path);
  const std::string name = p.filename().string();
  if (static_cast<long>(name.size()) > name_max)
    return "name is " + std::to_string(name.size()) + " bytes; the file system allows " +
           std::to_string(name_max);
  if (static_cast<long>(fs::absolute(p).string().size()) >= path_max)
    return "path is longer than the file system's limit of " + std::to_string(path_max) + " bytes";
  std::error_code ec;
  // A relative ImageName ("renders/a.png") writes into a folder below the output folder,
  // which must be there: the renderer creates no folders.
  const fs::path folder = p.parent_path();
  if (!fs::is_directory(folder, ec))
    return "would go into '" + shorten(folder.string(), 200) + "', which " +
           (fs::exists(folder, ec) ? "is not a folder" : "does not exist") +
           " (create it, or choose the output folder with --output-dir)";
  if (fs::is_directory(p, ec)) return "'" + shorten(path) + "' is a directory";
  return "";
}

}  // namespace rt
