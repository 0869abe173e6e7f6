// Replays every input kept in fuzz/regressions/: each once crashed, hung or tripped a
// sanitizer in a fuzzer (tools/fuzz.sh) and must now be handled (loaded or refused with an
// rt::InputError). The sanitized build of these tests (sanitize.unit_tests) also catches
// memory errors and undefined behaviour on them.
#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <iterator>
#include <string>

#include "fuzz/targets.h"

namespace rt {
namespace {

using FuzzFunction = void (*)(const uint8_t*, size_t);

// Returns how many inputs were replayed.
int replay(const std::string& target, FuzzFunction f) {
  const std::filesystem::path dir =
      std::filesystem::path(RT_SOURCE_DIR) / "fuzz/regressions" / target;
  int count = 0;
  for (const auto& entry : std::filesystem::directory_iterator(dir)) {
    if (!entry.is_regular_file() || entry.path().filename() == "README.md") continue;
    std::ifstream in(entry.path(), std::ios::binary);
    const std::string bytes{std::istreambuf_iterator<char>(in), {}};
    SCOPED_TRACE(entry.path().string());
    EXPECT_NO_THROW(f(reinterpret_cast<const uint8_t*>(bytes.data()), bytes.size()));
    ++count;
  }
  return count;
}

TEST(FuzzRegressions, Scene) { EXPECT_GT(replay("scene", fuzz_scene), 0); }
TEST(FuzzRegressions, Ply) { EXPECT_GT(replay("ply", fuzz_ply), 0); }
TEST(FuzzRegressions, Cli) { EXPECT_GT(replay("cli", fuzz_cli), 0); }

}  // namespace
}  // namespace rt
