// The pieces behind the messages in words: the edit distance and its suggestions, the
// diagnosis of malformed XML, the magic numbers of foreign files, and the JPEG writer
// against the reader (which refuses a truncated file).
#include <gtest/gtest.h>

#include <filesystem>
#include <string>
#include <vector>

#include "image/read_ldr.h"
#include "io/image_output.h"
#include "io/jpeg_io.h"
#include "scene/xml_diagnosis.h"
#include "support/test_scene.h"
#include "util/spelling.h"

namespace rt {
namespace {

TEST(Spelling, EditDistance) {
  EXPECT_EQ(edit_distance("Radius", "Radius"), 0u);
  EXPECT_EQ(edit_distance("Radious", "Radius"), 1u);
  EXPECT_EQ(edit_distance("radius", "Radius"), 0u);  // Case is no edit.
  EXPECT_EQ(edit_distance("", "abc"), 3u);
  EXPECT_EQ(edit_distance("kitten", "sitting"), 3u);
}

TEST(Spelling, ClosestNameOnlyWhenNear) {
  const std::vector<std::string> names{"Radius", "Center", "Material"};
  EXPECT_EQ(closest_name("Radious", names), "Radius");
  EXPECT_EQ(closest_name("Centre", names), "Center");
  EXPECT_EQ(closest_name("Colour", names), "");  // Too far from all of them.
  EXPECT_EQ(closest_name("Radius", names), "");  // Itself is no suggestion.
}

TEST(XmlDiagnosis, NamesTheMistakeAndItsLine) {
  XmlProblem p = find_xml_problem("<Scene>\n  <A>1</A>\n\n");
  EXPECT_EQ(p.line, 4);
  EXPECT_EQ(p.what, "the element <Scene> opened at line 1 is never closed");
  p = find_xml_problem("<Scene>\n<A>\n<B>1</B>\n</Scene>");
  EXPECT_EQ(p.line, 4);
  EXPECT_EQ(p.what, "the element <A> opened at line 2 is not closed before </Scene>");
  p = find_xml_problem("<Scene>\n</B>\n</Scene>");
  EXPECT_EQ(p.what, "</B> does not match the open element <Scene> (line 1)");
  p = find_xml_problem("<Scene>\n<!-- never ends\n</Scene>");
  EXPECT_EQ(p.line, 2);
  EXPECT_NE(p.what.find("comment opened at line 2 is never closed"), std::string::npos);
  p = find_xml_problem("<Scene>\n<A x=1/>\n</Scene>");
  EXPECT_NE(p.what.find("not in quotes"), std::string::npos) << p.what;
  p = find_xml_problem("<Scene>1 < 2</Scene>");
  EXPECT_NE(p.what.find("&lt;"), std::string::npos) << p.what;
  // Well-formed text has no problem, whatever its elements.
  EXPECT_TRUE(find_xml_problem("<?xml version=\"1.0\"?>\n<Scene a='1'><B/><![CDATA[<]]>&amp;"
                               "&#38;&#x26;</Scene>")
                  .what.empty());
  EXPECT_TRUE(find_xml_problem(test::kTinyScene).what.empty());
}

TEST(XmlDiagnosis, ForeignFileKinds) {
  EXPECT_EQ(non_xml_kind("ply\nformat binary_little_endian 1.0\n"), "PLY");
  EXPECT_EQ(non_xml_kind(std::string("\x89PNG\r\n\x1a\n", 8)), "PNG");
  EXPECT_EQ(non_xml_kind("\xff\xd8\xff\xe1"), "JPEG");
  EXPECT_EQ(non_xml_kind("\x76\x2f\x31\x01\x02"), "OpenEXR");
  EXPECT_EQ(non_xml_kind("#?RADIANCE\n"), "Radiance HDR");
  EXPECT_EQ(non_xml_kind("<Scene/>"), "");
  EXPECT_EQ(non_xml_kind("plywood"), "");
}

class JpegWrite : public test::TempDirTest {};

TEST_F(JpegWrite, RoundTripsWithinAFewLevelsAndTruncationIsRefused) {
  Image8 img;
  img.width = 16;
  img.height = 8;
  for (int i = 0; i < img.width * img.height; ++i)
    for (int c = 0; c < 3; ++c) img.rgb.push_back(static_cast<uint8_t>(40 + 60 * c + (i % 16)));
  const std::string path = (dir_ / "a.jpg").string();
  write_jpeg(path, img);
  ImageF back = read_ldr(path);
  ASSERT_EQ(back.width, 16);
  ASSERT_EQ(back.height, 8);
  for (size_t i = 0; i < img.rgb.size(); ++i) EXPECT_NEAR(back.pixels[i], img.rgb[i], 4.0) << i;
  // The same file cut short: the reader's warning is an error naming the file.
  const std::string bytes = test::slurp(path);
  const std::string cut = write("cut.jpg", bytes.substr(0, bytes.size() - bytes.size() / 3));
  try {
    read_ldr(cut);
    ADD_FAILURE() << "a truncated JPEG was read";
  } catch (const std::runtime_error& e) {
    EXPECT_NE(std::string(e.what()).find(cut + ": cannot read image: JPEG:"), std::string::npos)
        << e.what();
  }
}

TEST(ImageFormat, ByExtension) {
  EXPECT_EQ(image_format_of("a.png"), ImageFormat::kPng);
  EXPECT_EQ(image_format_of("a"), ImageFormat::kPng);
  EXPECT_EQ(image_format_of("sub/a.JPG"), ImageFormat::kJpeg);
  EXPECT_EQ(image_format_of("a.jpeg"), ImageFormat::kJpeg);
  EXPECT_EQ(image_format_of("a.Exr"), ImageFormat::kExr);
  EXPECT_EQ(image_format_of("a.bmp"), ImageFormat::kUnknown);
  EXPECT_EQ(tonemap_path_for("out/a.exr"), "out/a.png");
}

}  // namespace
}  // namespace rt
