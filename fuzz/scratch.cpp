#include "fuzz/scratch.h"

#include <unistd.h>

#include <filesystem>
#include <fstream>
#include <stdexcept>

namespace rt {
namespace {

struct ScratchFolder {
  std::string dir;
  ScratchFolder() {
    std::error_code ec;
    std::filesystem::path base = std::filesystem::is_directory("/dev/shm", ec)
                                     ? std::filesystem::path("/dev/shm")
                                     : std::filesystem::temp_directory_path();
    dir = (base / ("rt-fuzz-" + std::to_string(getpid()))).string();
    std::filesystem::create_directories(dir);
  }
  ~ScratchFolder() {
    std::error_code ec;
    std::filesystem::remove_all(dir, ec);
  }
};

}  // namespace

const std::string& fuzz_scratch_dir() {
  static const ScratchFolder folder;
  return folder.dir;
}

std::string fuzz_scratch_file(const std::string& name, const uint8_t* data, size_t size) {
  std::string path = fuzz_scratch_dir() + "/" + name;
  std::ofstream out(path, std::ios::binary | std::ios::trunc);
  out.write(reinterpret_cast<const char*>(data), static_cast<std::streamsize>(size));
  // A short write would fuzz a different file than the one libFuzzer saves as the artifact.
  if (!out.flush()) throw std::runtime_error("cannot write the fuzz input " + path);
  return path;
}

}  // namespace rt
