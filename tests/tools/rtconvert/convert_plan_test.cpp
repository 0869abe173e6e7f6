// What rtconvert writes checked against what it reads, before anything is written: the
// output and the meshes it puts beside an XML output are refused when one is an input
// (also through letter case), with one line and nothing written; images embedded in a model
// whose names differ only in case are kept apart.
#include <gtest/gtest.h>
#include <unistd.h>

#include <algorithm>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <iterator>
#include <string>
#include <vector>

#include "convert.h"

namespace {

namespace fs = std::filesystem;

std::string read(const fs::path& p) {
  std::ifstream in(p, std::ios::binary);
  return std::string(std::istreambuf_iterator<char>(in), {});
}

// A scene whose one mesh is `ply`: 242 triangles, more than an XML output keeps inline, so
// a conversion to XML writes it as <OUT>_files/mesh1.ply.
const char* kScene = R"(<Scene>
  <Cameras><Camera id="1">
    <Position>0 0 0</Position><Gaze>0 0 -1</Gaze><Up>0 1 0</Up>
    <NearPlane>-1 1 -1 1</NearPlane><NearDistance>1</NearDistance>
    <ImageResolution>8 8</ImageResolution><ImageName>s.png</ImageName>
  </Camera></Cameras>
  <Lights><AmbientLight>25 25 25</AmbientLight></Lights>
  <Materials><Material id="1"><AmbientReflectance>1 1 1</AmbientReflectance></Material></Materials>
  <Objects><Mesh id="1"><Material>1</Material><Faces plyFile="c_files/mesh1.ply"/></Mesh></Objects>
</Scene>
)";

std::string grid_ply() {
  const int n = 11;
  std::string v, f;
  for (int j = 0; j <= n; ++j)
    for (int i = 0; i <= n; ++i)
      v += std::to_string(i * 0.125 - 0.5) + " " + std::to_string(j * 0.125 - 0.5) + " -2\n";
  for (int j = 0; j < n; ++j)
    for (int i = 0; i < n; ++i) {
      const int a = j * (n + 1) + i, b = a + 1, c = a + n + 1, d = c + 1;
      f += "3 " + std::to_string(a) + " " + std::to_string(b) + " " + std::to_string(d) + "\n";
      f += "3 " + std::to_string(a) + " " + std::to_string(d) + " " + std::to_string(c) + "\n";
    }
  return "ply\nformat ascii 1.0\nelement vertex " + std::to_string((n + 1) * (n + 1)) +
         "\nproperty float x\nproperty float y\nproperty float z\nelement face " +
         std::to_string(2 * n * n) + "\nproperty list uchar int vertex_indices\nend_header\n" + v +
         f;
}

class ConvertPlan : public ::testing::Test {
 protected:
  void SetUp() override {
    char tmpl[] = "/tmp/rtconvert_plan_XXXXXX";
    ASSERT_NE(mkdtemp(tmpl), nullptr);
    dir_ = tmpl;
    fs::create_directories(dir_ / "c_files");
    std::ofstream(dir_ / "c_files/mesh1.ply") << grid_ply();
    std::ofstream(dir_ / "s.xml") << kScene;
  }
  void TearDown() override { fs::remove_all(dir_); }

  // rtconvert with `args` in the test's folder: its exit status, stderr in *err.
  int convert(const std::string& args, std::string* err) {
    const fs::path e = dir_ / "stderr.txt";
    const std::string line = "cd '" + dir_.string() + "' && " + RTCONVERT_EXE + " " + args +
                             " 2> '" + e.string() + "' > /dev/null";
    const int status = std::system(line.c_str());
    *err = read(e);
    fs::remove(e);
    return WIFEXITED(status) ? WEXITSTATUS(status) : -1;
  }
  std::vector<std::string> files() const {
    std::vector<std::string> names;
    for (const auto& e : fs::recursive_directory_iterator(dir_))
      names.push_back(fs::relative(e.path(), dir_).string());
    std::sort(names.begin(), names.end());
    return names;
  }

  fs::path dir_;
};

TEST_F(ConvertPlan, MeshBesideTheOutputThatIsAnInputIsRefused) {
  // c.xml's meshes go to c_files/, where s.xml's own mesh is.
  const std::vector<std::string> before = files();
  std::string err;
  EXPECT_EQ(convert("s.xml c.xml", &err), 1);
  EXPECT_EQ(std::count(err.begin(), err.end(), '\n'), 1) << err;
  EXPECT_NE(err.find("c_files/mesh1.ply: the mesh is the input file c_files/mesh1.ply"),
            std::string::npos)
      << err;
  EXPECT_EQ(files(), before);
  EXPECT_EQ(read(dir_ / "c_files/mesh1.ply"), grid_ply());
  // Another name converts, its mesh beside it.
  EXPECT_EQ(convert("s.xml d.xml", &err), 0) << err;
  EXPECT_TRUE(fs::exists(dir_ / "d_files/mesh1.ply"));
}

TEST_F(ConvertPlan, OutputThatIsTheInputInOtherLetterCaseIsRefused) {
  for (const char* out : {"S.XML", "./c_files/../S.xml"}) {
    std::string err;
    EXPECT_EQ(convert(std::string("s.xml ") + out, &err), 1) << out;
    EXPECT_NE(err.find("the output is the input file s.xml"), std::string::npos) << err;
    EXPECT_EQ(read(dir_ / "s.xml"), kScene);
    EXPECT_FALSE(fs::exists(dir_ / "S.XML") || fs::exists(dir_ / "S.xml")) << out;
  }
}

TEST_F(ConvertPlan, EmbeddedImagesWhoseNamesDifferOnlyInCaseAreKeptApart) {
  rtconvert::ImportedScene in;
  for (const char* name : {"Albedo.png", "albedo.png"}) {
    rtconvert::ImageFile f;
    f.bytes = std::string("bytes of ") + name;
    f.name = name;
    in.images.push_back(f);
  }
  rtconvert::Report report;
  rtconvert::write_course_xml(in, (dir_ / "m.xml").string(), report);
  EXPECT_EQ(read(dir_ / "m_files/Albedo.png"), "bytes of Albedo.png");
  EXPECT_EQ(read(dir_ / "m_files/albedo_2.png"), "bytes of albedo.png");
  EXPECT_FALSE(fs::exists(dir_ / "m_files/albedo.png"));
}

}  // namespace
