// The job-wide output plan (src/app/output_plan.h), through the executable: two writers of
// one file (a tone-mapped PNG, letter case, two scene files, moments files, "./" spellings)
// and a writer over an input (a texture, a PLY another scene file names, the scene itself
// through a checkpoint) are refused before the first sample, in one line naming both, with
// nothing written; a later scene file that is missing or malformed is found before the
// first renders.
#include <unistd.h>

#include <algorithm>
#include <filesystem>
#include <fstream>
#include <string>
#include <vector>

#include "support/cli_harness.h"

namespace {

namespace fs = std::filesystem;
using namespace rt::test;

const std::string kTonemap =
    "</ImageName><Tonemap><TMO>Photographic</TMO><TMOOptions>0.18 1</TMOOptions></Tonemap>";

// kTinyScene writing `image`.
std::string scene_writing(const std::string& image) {
  return replaced(kTinyScene, "simple.png</ImageName>", image + "</ImageName>");
}

// kTinyScene writing `image`, an .exr, with <Tonemap>: also its tone-mapped PNG.
std::string tone_mapped(const std::string& image) {
  return replaced(kTinyScene, "simple.png</ImageName>", image + kTonemap);
}

// `scene` with a second camera (id 2) writing `image`.
std::string with_second_camera(const std::string& scene, const std::string& image) {
  const size_t b = scene.find("        <Camera id=\"1\">"), e = scene.find("</Camera>") + 10;
  std::string cam = replaced(scene.substr(b, e - b), "id=\"1\"", "id=\"2\"");
  const size_t n0 = cam.find("<ImageName>") + 11, n1 = cam.find("</ImageName>");
  cam = cam.substr(0, n0) + image + cam.substr(n1);
  return replaced(scene, "    </Cameras>", cam + "    </Cameras>");
}

class OutputPlan : public CliFixture {
 protected:
  // The raytracer on the CPU, quiet, with `args` (quoted scene files, options) and, unless
  // `args` chooses one, the test's output folder.
  Outcome go(const std::string& args) {
    const bool dir = args.find("--output-dir") != std::string::npos;
    return run("--device cpu --quiet " + (dir ? "" : "--output-dir " + quote(out_) + " ") + args);
  }
  // Runs `args`, expects it refused with one line holding every one of `words`, and no
  // output written.
  void refused(const std::string& args, const std::vector<std::string>& words) {
    const Outcome r = go(args);
    EXPECT_EQ(r.code, 1) << r.err;
    expect_one_error_line(r);
    for (const std::string& w : words) EXPECT_NE(r.err.find(w), std::string::npos) << w << r.err;
    EXPECT_EQ(sorted_outputs(), before_) << r.err;
  }
  std::vector<std::string> sorted_outputs() const {
    std::vector<std::string> names = output_files();
    std::sort(names.begin(), names.end());
    return names;
  }
  std::vector<std::string> before_;  // What the output folder held before the refused run.
};

TEST_F(OutputPlan, ToneMappedPngOfAnotherSceneFileRefused) {
  const std::string a = write("a.xml", tone_mapped("shot.exr"));
  const std::string b = write("b.xml", scene_writing("shot.png"));
  refused(quote(a) + " " + quote(b),
          {"b.xml: Cameras > Camera id=1 > ImageName: 'shot.png': the image would replace the "
           "tone-mapped image of camera 0 (Cameras > Camera id=1 > ImageName) of " +
               a,
           "two outputs share 'shot.png'"});
  // Each alone is fine.
  EXPECT_EQ(go(quote(a)).code, 0);
  EXPECT_EQ(sorted_outputs(), (std::vector<std::string>{"shot.exr", "shot.png"}));
}

TEST_F(OutputPlan, NamesThatDifferOnlyInLetterCaseRefused) {
  const std::string s = write("s.xml", with_second_camera(kTinyScene, "SIMPLE.Png"));
  refused(quote(s), {"Camera id=2 > ImageName: 'SIMPLE.Png': the image would replace the image "
                     "of camera 0 (Cameras > Camera id=1 > ImageName)",
                     "'simple.png' and 'SIMPLE.Png' differ only in letter case"});
}

TEST_F(OutputPlan, TwoToneMappedExrWithOneStemRefused) {
  // a.exr and a.EXR: their tone-mapped PNGs are both a.png, and the images one file where
  // case folds.
  const std::string s = write("s.xml", with_second_camera(tone_mapped("a.exr"), "a.EXR"));
  refused(quote(s), {"Camera id=2 > ImageName: 'a.EXR", "of camera 0 (Cameras > Camera id=1",
                     "'a.exr' and 'a.EXR' differ only in letter case"});
}

TEST_F(OutputPlan, TwoSceneFilesWritingOneImageRefused) {
  const std::string a = write("a.xml", kTinyScene), b = write("b.xml", kTinyScene);
  refused(quote(a) + " " + quote(b),
          {b +
           ": Cameras > Camera id=1 > ImageName: 'simple.png': the image would replace "
           "the image of camera 0 (Cameras > Camera id=1 > ImageName) of " +
           a});
  // The same file twice is two writers too.
  refused(quote(a) + " " + quote(a), {"of " + a, "two outputs share 'simple.png'"});
}

TEST_F(OutputPlan, OneFileSpelledTwoWaysRefused) {
  const std::string s = write("s.xml", with_second_camera(kTinyScene, "./simple.png"));
  refused(
      quote(s) + " --output-dir " + quote(out_ + "/../out"),
      {"Camera id=2 > ImageName: './simple.png'", "'simple.png' and './simple.png' are one file"});
}

TEST_F(OutputPlan, MomentsFileOfAnotherSceneFileRefused) {
  const std::string a = write("a.xml", scene_writing("shot.png"));
  const std::string b = write("b.xml", scene_writing("shot.moments.exr"));
  EXPECT_EQ(go(quote(a) + " " + quote(b)).code, 0);  // Without --moments: no conflict.
  for (const auto& f : fs::directory_iterator(out_)) fs::remove(f.path());
  refused(quote(a) + " " + quote(b) + " --moments",
          {"'shot.moments.exr': the image would replace the moments file of camera 0", "of " + a});
}

TEST_F(OutputPlan, OutputOverATextureRefused) {
  ASSERT_EQ(go(quote(write("a.xml", kTinyScene))).code, 0);
  const std::string texture = slurp(fs::path(out_) / "simple.png");
  const std::string textured =
      replaced(replaced(kTinyScene, "    <Objects>",
                        "    <Textures><Images><Image id=\"1\">out/simple.png</Image></Images>"
                        "<TextureMap id=\"1\" type=\"image\"><ImageId>1</ImageId>"
                        "<DecalMode>replace_kd</DecalMode></TextureMap></Textures>\n    <Objects>"),
               "<Material>1</Material>\n            <Faces>",
               "<Material>1</Material><Textures>1</Textures>\n            <Faces>");
  const std::string t = write("t.xml", textured);
  before_ = sorted_outputs();
  refused(quote(t), {"t.xml: Cameras > Camera id=1 > ImageName: 'simple.png': the image would "
                     "overwrite the input file '" +
                     (dir_ / "out/simple.png").string() + "'"});
  EXPECT_EQ(slurp(fs::path(out_) / "simple.png"), texture);
}

TEST_F(OutputPlan, OutputOverAPlyOfALaterSceneFileRefused) {
  // The first file would render m.png; the second reads it as its mesh.
  const std::string ply =
      "ply\nformat ascii 1.0\nelement vertex 3\nproperty float x\nproperty float y\n"
      "property float z\nelement face 1\nproperty list uchar int vertex_indices\nend_header\n"
      "0 0 -2\n1 0 -2\n1 1 -2\n3 0 1 2\n";
  std::ofstream(fs::path(out_) / "m.png") << ply;
  before_ = sorted_outputs();
  const std::string a = write("a.xml", scene_writing("m.png"));
  const std::string b = write("b.xml", tiny_scene_with_ply_mesh("out/m.png"));
  refused(quote(a) + " " + quote(b),
          {a + ": Cameras > Camera id=1 > ImageName: 'm.png': the image would overwrite the "
               "input file '",
           "m.png' of " + b});
  EXPECT_EQ(slurp(fs::path(out_) / "m.png"), ply);
}

TEST_F(OutputPlan, CheckpointOverTheSceneFileRefused) {
  // A finished image removes its checkpoint: here that would remove the scene file.
  const std::string scene = (fs::path(out_) / "simple.png.rtcheckpoint").string();
  std::ofstream(scene) << kTinyScene;
  before_ = sorted_outputs();
  refused(quote(scene), {"'simple.png': the checkpoint would overwrite the input file"});
  EXPECT_EQ(slurp(scene), kTinyScene);
}

TEST_F(OutputPlan, CheckpointNameTooLongRefusedWhenCheckpointsAreWritten) {
  // The image's name fits; "<image>.rtcheckpoint" does not, which only --checkpoint and
  // --resume write.
  const long name_max = pathconf(out_.c_str(), _PC_NAME_MAX);
  ASSERT_GT(name_max, 20);
  const std::string name = std::string(name_max - 4 - 6, 'n') + ".png";
  const std::string s = write("s.xml", scene_writing(name));
  refused(quote(s) + " --checkpoint 100",
          {"the checkpoint name is " + std::to_string(name_max + 7) +
           " bytes; the file system allows " + std::to_string(name_max)});
  EXPECT_EQ(go(quote(s)).code, 0);
  EXPECT_EQ(sorted_outputs(), std::vector<std::string>{name});
}

TEST_F(OutputPlan, LaterSceneFileMissingOrMalformedFoundBeforeTheFirstRenders) {
  const std::string a = write("a.xml", kTinyScene);
  refused(quote(a) + " " + quote((dir_ / "missing.xml").string()),
          {(dir_ / "missing.xml").string() + ": file: cannot open"});
  const std::string bad = write("bad.xml", "<Scene><Cameras>\n</Scene>\n");
  refused(quote(a) + " " + quote(bad), {bad + ":", "malformed XML"});
  const std::string b = write("b.xml", scene_writing("b.png"));
  refused(quote(a) + " " + quote(b) + " --camera 1", {a + ": Cameras: no camera 1"});
}

TEST_F(OutputPlan, ExistingOutputsAreNoConflictForSkipExistingAndResume) {
  const std::string a = write("a.xml", scene_writing("a.png"));
  const std::string b = write("b.xml", scene_writing("b.png"));
  ASSERT_EQ(go(quote(a) + " " + quote(b)).code, 0);
  for (const char* again : {"", "--skip-existing", "--resume"}) {
    const Outcome r = go(quote(a) + " " + quote(b) + " " + again);
    EXPECT_EQ(r.code, 0) << again << r.err;
    EXPECT_EQ(sorted_outputs(), (std::vector<std::string>{"a.png", "b.png"})) << again;
  }
}

}  // namespace
