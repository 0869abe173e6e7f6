// HDR image readers (src/image/read_hdr.h): OpenEXR files written here with the OpenEXR
// library, Radiance RGBE files assembled byte by byte, and bad input of each kind.
#include <OpenEXR/ImfChannelList.h>
#include <OpenEXR/ImfFrameBuffer.h>
#include <OpenEXR/ImfHeader.h>
#include <OpenEXR/ImfOutputFile.h>
#include <gtest/gtest.h>
#include <unistd.h>

#include <cstdio>
#include <fstream>
#include <string>
#include <vector>

#include "util/errors.h"
#include "image/read_hdr.h"

namespace {

std::string TempPath(const std::string& name) {
  return testing::TempDir() + "read_hdr_" + std::to_string(getpid()) + "_" + name;
}

void WriteBytes(const std::string& path, const std::string& header,
                const std::vector<unsigned char>& body) {
  std::ofstream out(path, std::ios::binary);
  out << header;
  out.write(reinterpret_cast<const char*>(body.data()), static_cast<std::streamsize>(body.size()));
}

// Expects `read` to throw rt::InputError whose message starts with the path.
template <class F>
void ExpectInputError(const std::string& path, F read, const std::string& fragment) {
  try {
    read(path);
    ADD_FAILURE() << "no error for " << path;
  } catch (const rt::InputError& e) {
    std::string what = e.what();
    EXPECT_EQ(what.rfind(path, 0), 0u) << what;
    EXPECT_NE(what.find(fragment), std::string::npos) << what;
  }
}

}  // namespace

// Full-float RGB with a data window that does not start at (0, 0).
TEST(ReadExr, FloatRgbWithOffsetDataWindow) {
  const int w = 3, h = 2;
  std::vector<float> rgb(w * h * 3);
  for (size_t i = 0; i < rgb.size(); ++i) rgb[i] = 0.125f * i + 1e-3f;
  std::string path = TempPath("rgb.exr");
  Imath::Box2i dw(Imath::V2i(5, 7), Imath::V2i(5 + w - 1, 7 + h - 1));
  Imf::Header header(dw, dw);
  const char* names[3] = {"R", "G", "B"};
  Imf::FrameBuffer fb;
  size_t xs = 3 * sizeof(float), ys = xs * w;
  for (int c = 0; c < 3; ++c) {
    header.channels().insert(names[c], Imf::Channel(Imf::FLOAT));
    char* base = reinterpret_cast<char*>(rgb.data() + c) - 5 * xs - 7 * ys;
    fb.insert(names[c], Imf::Slice(Imf::FLOAT, base, xs, ys));
  }
  {
    Imf::OutputFile file(path.c_str(), header);
    file.setFrameBuffer(fb);
    file.writePixels(h);
  }
  rt::ImageF img = rt::read_hdr_image(path);
  EXPECT_EQ(img.width, w);
  EXPECT_EQ(img.height, h);
  EXPECT_EQ(img.channels, 3);
  EXPECT_EQ(img.max_value, 0.0f);
  EXPECT_EQ(img.pixels, rgb);
  std::remove(path.c_str());
}

// A half-float luminance-only file comes back as one grey channel.
TEST(ReadExr, HalfLuminanceOnly) {
  std::vector<half> y = {half(0.5f), half(2.0f)};
  std::string path = TempPath("y.EXR");
  Imf::Header header(2, 1);
  header.channels().insert("Y", Imf::Channel(Imf::HALF));
  Imf::FrameBuffer fb;
  fb.insert("Y", Imf::Slice(Imf::HALF, reinterpret_cast<char*>(y.data()), sizeof(half),
                            2 * sizeof(half)));
  {
    Imf::OutputFile file(path.c_str(), header);
    file.setFrameBuffer(fb);
    file.writePixels(1);
  }
  rt::ImageF img = rt::read_hdr_image(path);  // The extension is matched in any case.
  EXPECT_EQ(img.channels, 1);
  EXPECT_EQ(img.pixels, (std::vector<float>{0.5f, 2.0f}));
  std::remove(path.c_str());
}

TEST(ReadExr, BadFiles) {
  std::string missing = TempPath("missing.exr");
  ExpectInputError(missing, rt::read_exr, "cannot read EXR");
  std::string garbage = TempPath("garbage.exr");
  WriteBytes(garbage, "this is not an OpenEXR file", {});
  ExpectInputError(garbage, rt::read_exr, "cannot read EXR");
  std::remove(garbage.c_str());
}

// Two flat pixels: (128, 64, 32, e = 129) decodes to (128.5, 64.5, 32.5) / 128 and an exponent
// of zero to black.
TEST(ReadRadianceHdr, FlatScanline) {
  std::string path = TempPath("flat.hdr");
  WriteBytes(path, "#?RADIANCE\nFORMAT=32-bit_rle_rgbe\nEXPOSURE=1\n\n-Y 1 +X 2\n",
             {128, 64, 32, 129, 200, 200, 200, 0});
  rt::ImageF img = rt::read_hdr_image(path);
  ASSERT_EQ(img.width, 2);
  ASSERT_EQ(img.height, 1);
  EXPECT_EQ(img.pixels,
            (std::vector<float>{128.5f / 128, 64.5f / 128, 32.5f / 128, 0.0f, 0.0f, 0.0f}));
  std::remove(path.c_str());
}

// One run-length-encoded scanline of 8 pixels: R one run, G literals, B a run and literals,
// E one run (2^(130 - 136) = 1/64 per mantissa step).
TEST(ReadRadianceHdr, RunLengthScanline) {
  std::string path = TempPath("rle.hdr");
  WriteBytes(path, "#?RGBE\n\n-Y 1 +X 8\n",
             {2,       2,  0, 8,                     // New-style RLE marker, width 8.
              128 + 8, 10,                           // R: 8 x 10.
              8,       0,  1, 2,  3,  4,  5,  6, 7,  // G: 8 literals.
              128 + 4, 9,  4, 20, 21, 22, 23,        // B: 4 x 9, then 4 literals.
              128 + 8, 130});                        // E: 8 x 130.
  rt::ImageF img = rt::read_radiance_hdr(path);
  ASSERT_EQ(img.pixels.size(), 24u);
  const unsigned char b[8] = {9, 9, 9, 9, 20, 21, 22, 23};
  for (int x = 0; x < 8; ++x) {
    EXPECT_EQ(img.pixels[x * 3 + 0], 10.5f / 64) << x;
    EXPECT_EQ(img.pixels[x * 3 + 1], (x + 0.5f) / 64) << x;
    EXPECT_EQ(img.pixels[x * 3 + 2], (b[x] + 0.5f) / 64) << x;
  }
  std::remove(path.c_str());
}

TEST(ReadRadianceHdr, BadFiles) {
  struct Case {
    const char* name;
    std::string header;
    std::vector<unsigned char> body;
    const char* fragment;
  };
  const std::vector<Case> cases = {
      {"nosig.hdr", "P6\n", {}, "signature"},
      {"noend.hdr", "#?RADIANCE\nFORMAT=32-bit_rle_rgbe\n", {}, "header has no end"},
      {"xyze.hdr", "#?RADIANCE\nFORMAT=32-bit_rle_xyze\n\n-Y 1 +X 1\n", {1, 1, 1, 128}, "xyze"},
      {"flip.hdr", "#?RADIANCE\n\n+Y 1 +X 1\n", {1, 1, 1, 128}, "resolution"},
      {"huge.hdr", "#?RADIANCE\n\n-Y 100000 +X 100000\n", {}, "image size"},
      // Fewer bytes than the smallest encoding of the claimed pixels: refused before decoding.
      {"short.hdr", "#?RADIANCE\n\n-Y 2 +X 2\n", {1, 1, 1, 128}, "too short for 2x2 pixels"},
      // An RLE run that overflows the scanline (padded past the size check, so the decoder
      // meets the run).
      {"overrun.hdr", "#?RADIANCE\n\n-Y 1 +X 8\n",
       {2, 2, 0, 8, 128 + 9, 1, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0}, "scanline 0"},
      // A zero-length run would loop forever in a careless decoder.
      {"zero.hdr", "#?RADIANCE\n\n-Y 1 +X 8\n",
       {2, 2, 0, 8, 128, 1, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0}, "scanline 0"},
  };
  for (const Case& c : cases) {
    std::string path = TempPath(c.name);
    WriteBytes(path, c.header, c.body);
    ExpectInputError(path, rt::read_radiance_hdr, c.fragment);
    std::remove(path.c_str());
  }
  ExpectInputError(TempPath("absent.hdr"), rt::read_radiance_hdr, "cannot open");
  EXPECT_THROW(rt::read_hdr_image("picture.png"), rt::InputError);
}
