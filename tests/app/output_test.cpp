// Outputs: the atomic file writer (io/file_util.h), the image writer that picks PNG or EXR
// by extension (io/image_output.h), and what a user sees through the executable.
#include <OpenEXR/ImfChannelList.h>
#include <OpenEXR/ImfFrameBuffer.h>
#include <OpenEXR/ImfHeader.h>
#include <OpenEXR/ImfInputFile.h>
#include <gtest/gtest.h>

#include <algorithm>
#include <cerrno>
#include <filesystem>
#include <fstream>
#include <string>
#include <vector>

#include "io/file_util.h"
#include "io/image_output.h"
#include "io/png_io.h"
#include "support/cli_harness.h"

namespace {

namespace fs = std::filesystem;
using namespace rt::test;

// Reads R, G, B of an EXR as floats, row-major.
std::vector<float> read_exr_rgb(const std::string& path, int* width, int* height) {
  Imf::InputFile in(path.c_str());
  const Imath::Box2i dw = in.header().dataWindow();
  *width = dw.max.x - dw.min.x + 1;
  *height = dw.max.y - dw.min.y + 1;
  std::vector<float> rgb(static_cast<size_t>(*width) * *height * 3);
  Imf::FrameBuffer fb;
  const size_t xs = 3 * sizeof(float), ys = xs * *width;
  const char* names[3] = {"R", "G", "B"};
  for (int c = 0; c < 3; ++c) {
    EXPECT_EQ(in.header().channels().findChannel(names[c])->type, Imf::FLOAT) << names[c];
    char* base = reinterpret_cast<char*>(rgb.data() + c) - dw.min.x * xs - dw.min.y * ys;
    fb.insert(names[c], Imf::Slice(Imf::FLOAT, base, xs, ys));
  }
  in.setFrameBuffer(fb);
  in.readPixels(dw.min.y, dw.max.y);
  return rgb;
}

class Outputs : public CliFixture {};

TEST_F(Outputs, AtomicWriteReadsBackAndLeavesOnlyTheFile) {
  const std::string path = (dir_ / "out" / "data.bin").string();
  const std::vector<uint8_t> bytes = {0, 1, 2, 255, 7};
  ASSERT_EQ(rt::write_file_atomic(path, bytes.data(), bytes.size()), 0);
  std::vector<uint8_t> back;
  EXPECT_EQ(rt::read_file(path, &back), 0);
  EXPECT_EQ(back, bytes);
  EXPECT_EQ(output_files(), std::vector<std::string>{"data.bin"});
  EXPECT_EQ(fs::status(path).permissions() & fs::perms::owner_write, fs::perms::owner_write);
}

TEST_F(Outputs, AtomicWriteFailureLeavesNothing) {
  const std::vector<uint8_t> bytes(10, 1);
  EXPECT_EQ(rt::write_file_atomic((dir_ / "out" / "no_dir" / "x").string(), bytes.data(), 10),
            ENOENT);
  fs::create_directory(dir_ / "out" / "taken");  // rename() onto a directory fails
  EXPECT_NE(rt::write_file_atomic((dir_ / "out" / "taken").string(), bytes.data(), 10), 0);
  EXPECT_EQ(output_files(), std::vector<std::string>{"taken"});
  std::vector<uint8_t> back;
  EXPECT_EQ(rt::read_file((dir_ / "out" / "missing").string(), &back), ENOENT);
  EXPECT_EQ(rt::read_file(out_, &back), EISDIR);
}

TEST_F(Outputs, ExrKeepsLinearValuesUnclamped) {
  const std::vector<float> rgb = {1000.5f, 0.25f, 255.0f, -0.0f, 3e6f, 12.125f};
  const std::string path = (dir_ / "out" / "hdr.EXR").string();
  rt::write_image(path, 2, 1, rgb);
  int w = 0, h = 0;
  EXPECT_EQ(read_exr_rgb(path, &w, &h), rgb);
  EXPECT_EQ(w, 2);
  EXPECT_EQ(h, 1);
  EXPECT_EQ(output_files(), std::vector<std::string>{"hdr.EXR"});
}

// Clamped, then truncated by default (the course's conversion) or rounded on request.
TEST_F(Outputs, OtherNamesGetTheClampedPng) {
  const std::vector<float> rgb = {1000.5f, 0.25f, 254.6f};
  rt::write_image((dir_ / "out" / "ldr.png").string(), 1, 1, rgb);
  EXPECT_EQ(rt::read_png((dir_ / "out" / "ldr.png").string()).rgb,
            (std::vector<uint8_t>{255, 0, 254}));
  rt::write_image((dir_ / "out" / "ldr.png").string(), 1, 1, rgb, rt::Quantize::kRound);
  EXPECT_EQ(rt::read_png((dir_ / "out" / "ldr.png").string()).rgb,
            (std::vector<uint8_t>{255, 0, 255}));
}

// The tiny scene's light gives the quad's centre more than 255: the EXR keeps it, the PNG
// of the same render clamps it, and both agree everywhere else.
TEST_F(Outputs, ExecutableWritesExrByExtension) {
  const std::string png_scene = write("png.xml", kTinyScene);
  const std::string exr_scene =
      write("exr.xml", replaced(kTinyScene, "simple.png</ImageName>", "simple.exr</ImageName>"));
  ASSERT_EQ(render(png_scene).code, 0);
  Outcome r = render(exr_scene);
  ASSERT_EQ(r.code, 0) << r.err;
  int w = 0, h = 0;
  const std::vector<float> hdr = read_exr_rgb((dir_ / "out" / "simple.exr").string(), &w, &h);
  const rt::Image8 png = rt::read_png((dir_ / "out" / "simple.png").string());
  ASSERT_EQ(w, png.width);
  ASSERT_EQ(h, png.height);
  float brightest = 0;
  for (float v : hdr) brightest = std::max(brightest, v);
  EXPECT_GT(brightest, 255.0f);
  EXPECT_EQ(rt::to_8bit(w, h, hdr).rgb, png.rgb);
}

// A 250-character name is valid on every common file system; the temporary file written
// before the rename must fit as well.
TEST_F(Outputs, LongImageNameIsWritten) {
  const std::string name = std::string(246, 'n') + ".png";
  const std::string scene =
      write("long.xml", replaced(kTinyScene, "simple.png</ImageName>", name + "</ImageName>"));
  Outcome r = render(scene);
  EXPECT_EQ(r.code, 0) << r.err;
  EXPECT_EQ(output_files(), std::vector<std::string>{name});
}

// Several scene files (an animation's frames) are rendered in order in one run, each image
// the same bytes as when its file is rendered alone.
TEST_F(Outputs, EverySceneFileGivenIsRendered) {
  const std::string a = write("a.xml", replaced(kTinyScene, "simple.png<", "frame_a.png<"));
  const std::string b = write("b.xml", replaced(kTinyScene, "simple.png<", "frame_b.png<"));
  ASSERT_EQ(render(b).code, 0);
  const std::string alone = slurp(dir_ / "out" / "frame_b.png");
  std::filesystem::remove(dir_ / "out" / "frame_b.png");
  Outcome r = run(quote(a) + " " + quote(b) + " --device cpu --quiet --output-dir " + quote(out_));
  ASSERT_EQ(r.code, 0) << r.err;
  std::vector<std::string> files = output_files();
  std::sort(files.begin(), files.end());
  EXPECT_EQ(files, (std::vector<std::string>{"frame_a.png", "frame_b.png"}));
  EXPECT_EQ(slurp(dir_ / "out" / "frame_b.png"), alone);
}

// --skip-existing renders only the missing images: an existing file is left untouched.
TEST_F(Outputs, SkipExistingRendersOnlyMissingImages) {
  const std::string a = write("a.xml", replaced(kTinyScene, "simple.png<", "frame_a.png<"));
  const std::string b = write("b.xml", replaced(kTinyScene, "simple.png<", "frame_b.png<"));
  std::filesystem::create_directories(dir_ / "out");
  { std::ofstream(dir_ / "out" / "frame_a.png") << "kept"; }
  Outcome r = run(quote(a) + " " + quote(b) +
                  " --device cpu --quiet --skip-existing --output-dir " + quote(out_));
  ASSERT_EQ(r.code, 0) << r.err;
  EXPECT_EQ(slurp(dir_ / "out" / "frame_a.png"), "kept");
  EXPECT_FALSE(slurp(dir_ / "out" / "frame_b.png").empty());
}

}  // namespace
