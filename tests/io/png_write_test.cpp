// Writing PNG files: exact float -> 8-bit conversion, exact round trips, and atomic writes
// that leave nothing behind on failure.
#include <gtest/gtest.h>

#include <filesystem>
#include <limits>
#include <stdexcept>
#include <string>
#include <vector>

#include "io/png_io.h"
#include "support/png_builder.h"

namespace rt {
namespace {

using namespace test;
namespace fs = std::filesystem;

TEST(ToEightBit, RoundsHalfAwayFromZeroAndClamps) {
  const float nan = std::numeric_limits<float>::quiet_NaN();
  const float inf = std::numeric_limits<float>::infinity();
  const std::vector<float> in = {254.5f, -3.0f, 300.0f, nan, 127.49f, 127.5f,
                                 0.5f,   0.49f, 255.0f, inf, -inf,    -0.0f};
  const Image8 img = to_8bit(4, 1, in, Quantize::kRound);
  EXPECT_EQ(img.width, 4);
  EXPECT_EQ(img.height, 1);
  EXPECT_EQ(img.rgb, (Bytes{255, 0, 255, 0, 127, 128, 1, 0, 255, 255, 0, 0}));
}

// The default, as the course's renderer: clamp, then drop the fraction.
TEST(ToEightBit, TruncatesByDefaultAfterClamping) {
  const float nan = std::numeric_limits<float>::quiet_NaN();
  const float inf = std::numeric_limits<float>::infinity();
  const std::vector<float> in = {254.99f, -3.0f, 300.0f, nan, 127.49f, 127.5f,
                                 0.99f,   1.0f,  255.0f, inf, -inf,    -0.0f};
  EXPECT_EQ(to_8bit(4, 1, in).rgb, (Bytes{254, 0, 255, 0, 127, 127, 0, 1, 255, 255, 0, 0}));
  EXPECT_EQ(to_8bit(4, 1, in, Quantize::kTruncate).rgb, to_8bit(4, 1, in).rgb);
}

TEST(ToEightBit, RejectsWrongBufferSize) {
  EXPECT_THROW(to_8bit(2, 2, std::vector<float>(11)), std::invalid_argument);
  EXPECT_THROW(to_8bit(-1, 2, std::vector<float>(6)), std::invalid_argument);
  EXPECT_EQ(to_8bit(0, 0, {}).rgb.size(), 0u);
}

TEST_F(PngIoTest, RoundTripIsExactAndLeavesOnlyTheFile) {
  const Image8 img = pattern_image(7, 5);
  write_png(path("out.png"), img);
  const Image8 back = read_png(path("out.png"));
  EXPECT_EQ(back.width, 7);
  EXPECT_EQ(back.height, 5);
  EXPECT_EQ(back.rgb, img.rgb);
  EXPECT_EQ(entries(dir_), std::vector<std::string>{"out.png"});
}

TEST_F(PngIoTest, ReplacesExistingFile) {
  write_bytes(path("out.png"), Bytes{'o', 'l', 'd'});
  const Image8 img = pattern_image(3, 2);
  write_png(path("out.png"), img);
  EXPECT_EQ(read_png(path("out.png")).rgb, img.rgb);
  EXPECT_EQ(entries(dir_), std::vector<std::string>{"out.png"});
}

TEST_F(PngIoTest, MissingDirectoryThrowsAndLeavesNothing) {
  const std::string target = path("no_such_dir/out.png");
  const std::string msg = error_of([&] { write_png(target, pattern_image(2, 2)); });
  EXPECT_NE(msg.find(target + ": cannot write PNG: "), std::string::npos) << msg;
  EXPECT_NE(msg.find("No such file or directory"), std::string::npos) << msg;
  EXPECT_EQ(msg.find('\n'), std::string::npos);
  EXPECT_TRUE(entries(dir_).empty());
}

TEST_F(PngIoTest, UncreatableProcPathThrows) {
  // /proc refuses new files even for root, unlike a chmod'ed directory.
  const std::string target = "/proc/png_io_test_" + std::to_string(::getpid()) + ".png";
  const std::string msg = error_of([&] { write_png(target, pattern_image(2, 2)); });
  EXPECT_EQ(msg.rfind(target + ": cannot write PNG: ", 0), 0u) << msg;
  EXPECT_FALSE(fs::exists(target));
}

TEST_F(PngIoTest, ReadOnlyDirectoryThrowsAndLeavesNothing) {
  if (::geteuid() == 0) GTEST_SKIP() << "running as root: directory permissions do not apply";
  fs::permissions(dir_, fs::perms::owner_read | fs::perms::owner_exec);
  const std::string target = path("out.png");
  const std::string msg = error_of([&] { write_png(target, pattern_image(2, 2)); });
  EXPECT_NE(msg.find(target + ": cannot write PNG: Permission denied"), std::string::npos) << msg;
  fs::permissions(dir_, fs::perms::owner_all);
  EXPECT_TRUE(entries(dir_).empty());
}

TEST_F(PngIoTest, RenameFailureRemovesTemporaryFile) {
  // The temporary file is written fine; only the final rename over a directory fails.
  fs::create_directory(path("out.png"));
  const std::string msg = error_of([&] { write_png(path("out.png"), pattern_image(2, 2)); });
  EXPECT_NE(msg.find(path("out.png") + ": cannot write PNG: "), std::string::npos) << msg;
  EXPECT_EQ(entries(dir_), std::vector<std::string>{"out.png"});
  EXPECT_TRUE(fs::is_directory(path("out.png")));
}

TEST_F(PngIoTest, InconsistentImageThrowsWithoutWriting) {
  Image8 bad = pattern_image(2, 2);
  bad.rgb.pop_back();
  EXPECT_NE(error_of([&] { write_png(path("a.png"), bad); }).find("cannot write PNG"),
            std::string::npos);
  EXPECT_NE(error_of([&] { write_png(path("b.png"), Image8{}); }).find("cannot write PNG"),
            std::string::npos);
  EXPECT_TRUE(entries(dir_).empty());
}

}  // namespace
}  // namespace rt
