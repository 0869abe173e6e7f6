// Replays the inputs kept in fuzz/regressions/<target>/ for the image readers' and
// rtconvert's fuzz targets (the scene, PLY and command-line ones are replayed by
// tests/fuzz/regression_test.cpp). Every input once crashed, hung, leaked or tripped a
// sanitizer, or is a hostile case kept on purpose; each must now be read or refused with one
// line naming the file. A target with no folder yet is a failure: an empty replay proves
// nothing.
#include <gtest/gtest.h>
#include <sys/resource.h>

#include <filesystem>
#include <fstream>
#include <iterator>
#include <string>

#include "fuzz/targets.h"
#include "image/read_hdr.h"

namespace rt {
namespace {

struct Target {
  const char* name;
  void (*function)(const uint8_t*, size_t);
};

class FuzzReplay : public testing::TestWithParam<Target> {};

// Several inputs once made a reader allocate gigabytes for a file of a few bytes. Without
// AddressSanitizer (which reserves terabytes of address space, and whose fuzzer runs have
// -rss_limit_mb instead) a 2 GiB address-space limit turns such an allocation into
// std::bad_alloc, which fails the test.
void limit_memory() {
#if defined(__has_feature)
#if __has_feature(address_sanitizer)
  return;
#endif
#endif
#if defined(__SANITIZE_ADDRESS__)
  return;
#endif
  rlimit limit{};
  limit.rlim_cur = limit.rlim_max = rlim_t{2} << 30;
  ASSERT_EQ(setrlimit(RLIMIT_AS, &limit), 0);
}

TEST_P(FuzzReplay, EveryRegressionInputIsHandled) {
  limit_memory();
  const std::filesystem::path dir =
      std::filesystem::path(RT_SOURCE_DIR) / "fuzz/regressions" / GetParam().name;
  ASSERT_TRUE(std::filesystem::is_directory(dir)) << dir;
  int count = 0;
  for (const auto& entry : std::filesystem::directory_iterator(dir)) {
    if (!entry.is_regular_file()) continue;
    std::ifstream in(entry.path(), std::ios::binary);
    const std::string bytes{std::istreambuf_iterator<char>(in), {}};
    SCOPED_TRACE(entry.path().string());
    EXPECT_NO_THROW(
        GetParam().function(reinterpret_cast<const uint8_t*>(bytes.data()), bytes.size()));
    ++count;
  }
  EXPECT_GT(count, 0) << "no input in " << dir;
}

const Target kTargets[] = {
    {"png", fuzz_png}, {"jpeg", fuzz_jpeg}, {"exr", fuzz_exr}, {"hdr", fuzz_hdr},
#ifdef RT_FUZZ_CONVERT
    {"obj", fuzz_obj}, {"gltf", fuzz_gltf},
#endif
};

INSTANTIATE_TEST_SUITE_P(Targets, FuzzReplay, testing::ValuesIn(kTargets),
                         [](const testing::TestParamInfo<Target>& info) {
                           return std::string(info.param.name);
                         });

// The seeds are valid files: every one must be read, as large as its kind's writer made it,
// so a bound added against hostile headers cannot refuse a real image unnoticed.
TEST(FuzzSeeds, EveryImageSeedIsRead) {
  int count = 0;
  for (const char* kind : {"png", "jpeg", "exr", "hdr"})
    for (const auto& entry : std::filesystem::directory_iterator(
             std::filesystem::path(RT_SOURCE_DIR) / "fuzz/seeds" / kind)) {
      SCOPED_TRACE(entry.path().string());
      ImageF img;
      EXPECT_NO_THROW(img = read_any_image(entry.path().string()));
      EXPECT_GT(img.width, 0);
      EXPECT_GT(img.height, 0);
      EXPECT_EQ(img.pixels.size(), img.size() * img.channels);
      ++count;
    }
  EXPECT_GE(count, 20);
}

}  // namespace
}  // namespace rt
