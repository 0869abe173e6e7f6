// Bad input through the executable, in words: malformed XML named by what is wrong and at
// the right line, a foreign file given as the scene, misspelt elements and options with
// "did you mean", files named once, values that would make a silently wrong image (tiny
// directions, a Gaussian filter's vanishing weights, a damaged JPEG texture), ids two
// kinds share, option limits, and image names with folders and formats.
#include <algorithm>
#include <array>
#include <filesystem>
#include <fstream>
#include <string>
#include <vector>

#include "io/png_io.h"
#include "support/cli_harness.h"

namespace {

namespace fs = std::filesystem;
using namespace rt::test;
const char* const kScene = kTinyScene;

// Line number (1-based) in `text` of the first `what`.
int line_of(const std::string& text, const std::string& what) {
  const size_t at = text.find(what);
  EXPECT_NE(at, std::string::npos) << what;
  return 1 + static_cast<int>(std::count(text.begin(), text.begin() + at, '\n'));
}

class CliInputWords : public CliFixture {
 protected:
  // Renders `text` as s.xml and expects a refusal: exit 1, one line, every part in it,
  // nothing written.
  std::string refused(const std::string& text, const std::vector<std::string>& parts,
                      const std::string& extra = "") {
    const std::string scene = write("s.xml", text);
    Outcome r = render(scene, extra);
    EXPECT_EQ(r.code, 1) << r.err;
    expect_one_error_line(r);
    for (const std::string& p : parts)
      EXPECT_NE(r.err.find(p), std::string::npos) << p << "\n" << r.err;
    EXPECT_TRUE(output_files().empty());
    return r.err;
  }
  // A usage error (exit 2) naming every part.
  void usage(const std::string& extra, const std::vector<std::string>& parts) {
    Outcome r = render(write("s.xml", kScene), extra);
    EXPECT_EQ(r.code, 2) << r.err;
    for (const std::string& p : parts)
      EXPECT_NE(r.err.find(p), std::string::npos) << p << "\n" << r.err;
    EXPECT_TRUE(output_files().empty());
  }
};

TEST_F(CliInputWords, UnclosedSceneNamedWithItsLine) {
  const std::string text = replaced(kScene, "</Scene>", "");
  const int last = 1 + static_cast<int>(std::count(text.begin(), text.end(), '\n'));
  const std::string err = refused(text, {"s.xml:" + std::to_string(last) + ": ",
                                         "the element <Scene> opened at line 1 is never closed"});
  EXPECT_EQ(err.find("XML_ERROR"), std::string::npos) << err;
}

TEST_F(CliInputWords, MismatchedClosingTagNamesTheUnclosedElement) {
  const std::string text = replaced(kScene, "<NearDistance>1</NearDistance>", "<NearDistance>1");
  const std::string opened = std::to_string(line_of(text, "<NearDistance>"));
  refused(text, {"s.xml:" + std::to_string(line_of(text, "</Camera>")) + ": ",
                 "the element <NearDistance> opened at line " + opened +
                     " is not closed before </Camera>"});
  const std::string quote = replaced(kScene, "<Camera id=\"1\">", "<Camera id=\"1>");
  refused(quote, {"s.xml:" + std::to_string(line_of(quote, "<Camera ")) + ": ",
                  "the value of the attribute id of <Camera>", "has no closing quote"});
}

TEST_F(CliInputWords, ForeignFileAsSceneSaysWhatItIs) {
  for (const auto& [name, bytes, kind] : std::vector<std::array<std::string, 3>>{
           {"mesh.ply", "ply\nformat ascii 1.0\nelement vertex 0\nend_header\n", "PLY"},
           {"image.png", std::string("\x89PNG\r\n\x1a\n\0\0\0\rIHDR", 16), "PNG"},
           {"photo.jpg", "\xff\xd8\xff\xe0\0\x10JFIF", "JPEG"}}) {
    const std::string path = write(name, bytes);
    Outcome r = render(path);
    EXPECT_EQ(r.code, 1);
    expect_one_error_line(r);
    EXPECT_NE(r.err.find(path + ": not an XML scene file (it starts like a " + kind + " file)"),
              std::string::npos)
        << r.err;
  }
}

TEST_F(CliInputWords, EmptySceneArgumentNamed) {
  Outcome r = render("");
  EXPECT_EQ(r.code, 1);
  expect_one_error_line(r);
  EXPECT_NE(r.err.find("scene file '': the name is empty"), std::string::npos) << r.err;
}

TEST_F(CliInputWords, MisspeltElementGetsDidYouMean) {
  refused(replaced(kScene, "<Radius>0.3</Radius>", "<Radious>0.3</Radious>"),
          {"Sphere id=1: missing <Radius>",
           "<Radious> at line " + std::to_string(line_of(kScene, "<Radius>")),
           "did you mean <Radius>?"});
  // Where nothing is missing, the warning suggests the name (and --strict refuses it).
  const std::string text = replaced(
      kScene, "<ShadowRayEpsilon>1e-3</ShadowRayEpsilon>",
      "<ShadowRayEpsilon>1e-3</ShadowRayEpsilon><BackgroundColour>1 1 1</BackgroundColour>");
  refused(text, {"BackgroundColour: unknown element", "did you mean <BackgroundColor>?"},
          "--strict");
  refused(replaced(kScene, "<Faces>", "<Faces plyFiel=\"x.ply\">"),
          {"unknown attribute plyFiel=\"x.ply\"", "did you mean plyFile?"}, "--strict");
}

TEST_F(CliInputWords, MisspeltOptionGetsDidYouMean) {
  usage("--filtre box", {"unknown option '--filtre'; did you mean --filter?"});
  usage("--quite", {"did you mean --quiet?"});
  usage("--output-dri x", {"did you mean --output-dir?"});
}

TEST_F(CliInputWords, MissingPlyFileNamedOnce) {
  const std::string err =
      refused(tiny_scene_with_ply_mesh("missing_mesh.ply"),
              {"plyFile '" + (dir_ / "missing_mesh.ply").string() + "': cannot open"});
  size_t count = 0;
  for (size_t at = err.find("missing_mesh.ply"); at != std::string::npos;
       at = err.find("missing_mesh.ply", at + 1))
    ++count;
  EXPECT_EQ(count, 1u) << err;
}

TEST_F(CliInputWords, CameraDirectionsOutsideFloatRefused) {
  refused(replaced(kScene, "<Gaze>0 0 -1</Gaze>", "<Gaze>0 0 -1e-30</Gaze>"),
          {"Camera id=1 > Gaze: '0 0 -1e-30' is too short for float"});
  refused(replaced(kScene, "<Up>0 1 0</Up>", "<Up>0 3e20 0</Up>"),
          {"Camera id=1 > Up: '0 3e20 0' is too long for float"});
  // The ends of the range still render.
  EXPECT_EQ(
      render(write("ok.xml", replaced(kScene, "<Gaze>0 0 -1</Gaze>", "<Gaze>0 0 -1e-18</Gaze>")))
          .code,
      0);
}

TEST_F(CliInputWords, GaussianSigmaWhoseWeightsUnderflowRefused) {
  usage("--filter gaussian --filter-sigma 0.01",
        {"--filter-sigma: '0.01' is not a number in [0.054"});
  // The smallest allowed sigma: on a grey background no pixel is black (sigma 0.01 made
  // 56 of the 128 black at 16 samples: their weights underflowed), at 1 and at 16 samples.
  const std::string grey =
      write("grey.xml", replaced(kScene, "<BackgroundColor>0 0 0", "<BackgroundColor>40 40 40"));
  for (const char* spp : {"1", "16"}) {
    Outcome r = render(grey, std::string("--filter gaussian --filter-sigma 0.054 --spp ") + spp);
    ASSERT_EQ(r.code, 0) << r.err;
    const rt::Image8 img = rt::read_png((dir_ / "out" / "simple.png").string());
    int black = 0;
    for (size_t i = 0; i + 2 < img.rgb.size(); i += 3)
      black += img.rgb[i] == 0 && img.rgb[i + 1] == 0 && img.rgb[i + 2] == 0;
    EXPECT_EQ(black, 0) << spp << " samples per pixel";
  }
}

TEST_F(CliInputWords, BrdfsOfTwoKindsWithOneIdRefused) {
  const std::string brdfs =
      "<BRDFs><OriginalPhong id=\"1\"><Exponent>2</Exponent></OriginalPhong>"
      "<TorranceSparrow id=\"1\"><Exponent>5</Exponent></TorranceSparrow></BRDFs><Materials>";
  const std::string text = replaced(kScene, "<Materials>", brdfs);
  refused(text, {"TorranceSparrow id=1: id '1' is also the id of the <OriginalPhong>",
                 "could mean either"});
  refused(text, {"could mean either"}, "--strict");
}

TEST_F(CliInputWords, HugeLimitsNameTheLimit) {
  usage("--noise-target 1e300", {"'1e300' is too large: the limit is 1e+12"});
  usage("--time-limit 1e300", {"'1e300' is too large: the limit is 1e+12"});
}

TEST_F(CliInputWords, ImageNameInAnExistingFolderBelowTheOutputFolder) {
  const std::string text = replaced(kScene, "simple.png", "sub/simple.png");
  refused(text, {"'sub/simple.png'", "does not exist", "--output-dir"});
  fs::create_directory(dir_ / "out" / "sub");
  Outcome r = render(write("s.xml", text));
  EXPECT_EQ(r.code, 0) << r.err;
  EXPECT_TRUE(fs::is_regular_file(dir_ / "out" / "sub" / "simple.png"));
  fs::remove_all(dir_ / "out" / "sub");
  for (const char* bad : {"../simple.png", "sub/../../simple.png", "/tmp/simple.png"})
    refused(replaced(kScene, "simple.png", bad), {"no '..', not absolute", "--output-dir"});
}

TEST_F(CliInputWords, JpegImageNameWritesJpeg) {
  Outcome r = render(write("s.xml", replaced(kScene, "simple.png", "simple.jpg")));
  EXPECT_EQ(r.code, 0) << r.err;
  const std::string bytes = slurp(dir_ / "out" / "simple.jpg");
  ASSERT_GE(bytes.size(), 3u);
  EXPECT_EQ(bytes.substr(0, 3), "\xff\xd8\xff");
  fs::remove(dir_ / "out" / "simple.jpg");
  refused(replaced(kScene, "simple.png", "simple.bmp"), {"'simple.bmp' has an extension"});
}

TEST_F(CliInputWords, ToneMappedPngBesideAnExrIsChecked) {
  // Camera 1 writes a.exr and, tone mapped, a.png; camera 2 writes a.png too.
  const std::string tonemap =
      "a.exr</ImageName><Tonemap><TMO>Photographic</TMO><TMOOptions>0.18 1</TMOOptions>"
      "</Tonemap>";
  std::string text = replaced(kScene, "simple.png</ImageName>", tonemap);
  const size_t b = text.find("        <Camera id=\"1\">"), e = text.find("</Camera>") + 10;
  std::string cam = replaced(text.substr(b, e - b), "id=\"1\"", "id=\"2\"");
  cam = replaced(cam, tonemap, "a.png</ImageName>");
  text = replaced(text, "    </Cameras>", cam + "    </Cameras>");
  refused(text, {"'a.png': the image would replace the tone-mapped image of camera 0"});
}

TEST_F(CliInputWords, TruncatedJpegTextureRefused) {
  const fs::path source =
      fs::path(RT_SHARED_SCENES_DIR) / "hw6/veach-ajar/textures/cherry-wood-texture.jpg";
  if (!fs::exists(source)) GTEST_SKIP() << source << " is missing (the course's scenes)";
  const std::string whole = slurp(source);
  write("cut.jpg", whole.substr(0, whole.size() / 2));
  const std::string texture =
      "<Textures><Images><Image id=\"1\">cut.jpg</Image></Images><TextureMap id=\"1\" "
      "type=\"image\"><ImageId>1</ImageId><DecalMode>replace_kd</DecalMode></TextureMap>"
      "</Textures><Objects>";
  std::string text = replaced(kScene, "<Objects>", texture);
  text = replaced(text, "<Material>1</Material>\n            <Center>",
                  "<Material>1</Material><Textures>1</Textures>\n            <Center>");
  refused(text, {"cut.jpg", "Premature end of JPEG file"});
}

}  // namespace
