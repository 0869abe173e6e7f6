// Moment files end to end: the EXR round trip, `raytracer --moments`, and the `compare`
// subcommands' exit codes, verdict lines and images on small renders of the example scene.
#include <gtest/gtest.h>
#include <unistd.h>

#include <cmath>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <limits>
#include <sstream>
#include <string>

#include "io/moments.h"

namespace fs = std::filesystem;

namespace {

fs::path TempDir(const std::string& name) {
  fs::path d = fs::temp_directory_path() / ("rt_moments_" + name + "_" + std::to_string(getpid()));
  fs::remove_all(d);
  fs::create_directories(d);
  return d;
}

// Runs a shell command; returns its exit status and its standard output in *out.
int RunCommand(const std::string& cmd, std::string* out = nullptr) {
  std::string full = cmd + " 2>&1";
  FILE* p = popen(full.c_str(), "r");
  std::string text;
  char buf[4096];
  while (size_t n = fread(buf, 1, sizeof buf, p)) text.append(buf, n);
  int status = pclose(p);
  if (out) *out = text;
  return WIFEXITED(status) ? WEXITSTATUS(status) : -1;
}

TEST(Moments, RoundTripKeepsEveryChannelAndAttribute) {
  rt::MomentImage m;
  m.width = 3;
  m.height = 2;
  m.info = {42u, 16, "box", "test-device", "scene.xml", 1};
  for (size_t i = 0; i < m.pixels(); ++i) {
    for (int c = 0; c < 3; ++c) {
      m.mean.push_back(0.5f * i + c);
      m.var.push_back(1.25f * i + c);
      m.normal.push_back(c == 2 ? 1.0f : 0.0f);
    }
    m.count.push_back(16 + static_cast<uint32_t>(i));
    bool hit = i != 4;
    m.first_t.push_back(hit ? 3.5f + i : std::numeric_limits<float>::infinity());
    m.instance.push_back(hit ? static_cast<int32_t>(i) : -1);
    m.primitive.push_back(hit ? 1000000 + static_cast<int32_t>(i) : -1);
  }
  fs::path d = TempDir("roundtrip");
  std::string path = (d / "x.moments.exr").string();
  rt::write_moments(path, m);
  rt::MomentImage r = rt::read_moments(path);
  EXPECT_EQ(r.width, 3);
  EXPECT_EQ(r.height, 2);
  EXPECT_EQ(r.mean, m.mean);
  EXPECT_EQ(r.var, m.var);
  EXPECT_EQ(r.normal, m.normal);
  EXPECT_EQ(r.count, m.count);
  EXPECT_EQ(r.first_t, m.first_t);
  EXPECT_EQ(r.instance, m.instance);
  EXPECT_EQ(r.primitive, m.primitive);
  EXPECT_EQ(r.info.seed, 42u);
  EXPECT_EQ(r.info.spp, 16);
  EXPECT_EQ(r.info.filter, "box");
  EXPECT_EQ(r.info.device, "test-device");
  EXPECT_EQ(r.info.scene, "scene.xml");
  EXPECT_EQ(r.info.camera, 1);
  for (const auto& e : fs::directory_iterator(d))
    EXPECT_EQ(e.path().filename(), "x.moments.exr");  // No temporary left behind.
  fs::remove_all(d);
}

TEST(Moments, ReadingSomethingElseFailsWithOneLine) {
  fs::path d = TempDir("bad");
  std::ofstream(d / "x.exr") << "not an exr";
  try {
    rt::read_moments((d / "x.exr").string());
    FAIL() << "no exception";
  } catch (const std::runtime_error& e) {
    EXPECT_NE(std::string(e.what()).find("cannot read moments"), std::string::npos);
  }
  EXPECT_THROW(rt::write_moments((d / "missing" / "y.exr").string(), rt::MomentImage{}),
               std::runtime_error);
  fs::remove_all(d);
}

TEST(Moments, PathBesideThePng) {
  EXPECT_EQ(rt::moments_path_for("out/dir/img.png"), "out/dir/img.moments.exr");
  EXPECT_EQ(rt::moments_path_for("img"), "img.moments.exr");
}

class CompareCli : public ::testing::Test {
 protected:
  static void SetUpTestSuite() {
    dir_ = TempDir("cli");
    // 24x18 pixels, 6 spp (independent samples): well under a second each.
    for (const char* seed : {"1", "2"}) {
      fs::path out = dir_ / seed;
      fs::create_directories(out);
      std::string cmd = std::string(RT_RAYTRACER_EXE) + " " + RT_SOURCE_DIR +
                        "/scenes/example.xml --device cpu --quiet --moments --spp 6 "
                        "--resolution-scale 0.05 --seed " + seed + " --output-dir " +
                        out.string();
      ASSERT_EQ(RunCommand(cmd), 0) << cmd;
    }
  }
  static void TearDownTestSuite() { fs::remove_all(dir_); }
  static std::string File(const char* seed) { return (dir_ / seed / "example.png").string(); }
  static std::string Compare(const std::string& args) {
    return std::string(RT_COMPARE_EXE) + " " + args;
  }
  static fs::path dir_;
};
fs::path CompareCli::dir_;

TEST_F(CompareCli, RaytracerWritesMomentsBesideThePng) {
  rt::MomentImage m = rt::read_moments((dir_ / "1" / "example.moments.exr").string());
  EXPECT_EQ(m.width, 24);
  EXPECT_EQ(m.height, 18);
  EXPECT_EQ(m.info.spp, 6);
  EXPECT_EQ(m.info.seed, 1u);
  EXPECT_EQ(m.info.device, "cpu-reference");
  for (uint32_t n : m.count) EXPECT_EQ(n, 6u);
  for (float v : m.var) EXPECT_GE(v, 0.0f);
  for (size_t i = 0; i < m.pixels(); ++i) EXPECT_EQ(m.instance[i] < 0, std::isinf(m.first_t[i]));
}

TEST_F(CompareCli, WelchPassesTwoSeedsAndWritesItsImages) {
  std::string out, maps = (dir_ / "maps").string();
  std::string cmd = Compare("welch " + File("1") + " " + File("2") + " --out-dir " + maps);
  EXPECT_EQ(RunCommand(cmd, &out), 0) << out;
  EXPECT_NE(out.find("verdict: PASS"), std::string::npos) << out;
  EXPECT_NE(out.find("smallest p"), std::string::npos);
  EXPECT_NE(out.find("Sidak per-test level"), std::string::npos);
  for (const char* f : {"welch-diff.png", "welch-pvalue.png", "welch-mask.png"})
    EXPECT_TRUE(fs::exists(fs::path(maps) / f)) << f;
}

TEST_F(CompareCli, ExactAndPairedPassTheSameRender) {
  std::string out;
  EXPECT_EQ(RunCommand(Compare("exact " + File("1") + " " + File("1")), &out), 0) << out;
  EXPECT_EQ(RunCommand(Compare("paired " + File("1") + " " + File("1")), &out), 0) << out;
  // Different seeds: different first rays, so exact must fail.
  EXPECT_EQ(RunCommand(Compare("exact " + File("1") + " " + File("2")), &out), 1) << out;
  EXPECT_NE(out.find("verdict: FAIL"), std::string::npos);
}

TEST_F(CompareCli, DiffWithMomentsTestsAgainstAnImage) {
  std::string out;
  std::string m = (dir_ / "2" / "example.moments.exr").string();
  EXPECT_EQ(RunCommand(Compare("diff " + File("1") + " " + File("2")), &out), 0) << out;
  EXPECT_NE(out.find("4x4: mae"), std::string::npos);
  // A 6-spp render is no converged reference: the test is expected to notice.
  int rc = RunCommand(Compare("diff " + File("1") + " " + File("2") + " --moments " + m), &out);
  EXPECT_TRUE(rc == 0 || rc == 1) << out;
  EXPECT_NE(out.find("verdict: "), std::string::npos) << out;
}

TEST_F(CompareCli, BadUsageExitsTwo) {
  std::string out;
  EXPECT_EQ(RunCommand(Compare(""), &out), 2);
  EXPECT_EQ(RunCommand(Compare("welch " + File("1")), &out), 2);
  EXPECT_EQ(RunCommand(Compare("welch " + File("1") + " " + File("2") + " --bogus"), &out), 2);
  EXPECT_EQ(RunCommand(Compare("welch " + File("1") + " /nonexistent.exr"), &out), 2);
  EXPECT_NE(out.find("cannot read moments"), std::string::npos) << out;
  EXPECT_EQ(RunCommand(Compare("frobnicate a b"), &out), 2);
}

TEST_F(CompareCli, HelpDocumentsEverySubcommand) {
  std::string out;
  ASSERT_EQ(RunCommand(Compare("--help"), &out), 0);
  for (const char* s : {"welch A B", "paired A B", "exact A B", "diff A.png B.png", "H0:",
                        "--tile", "--bh", "--out-dir", "-pvalue.png", "-mask.png", "-diff.png",
                        "Sidak", "uniform"})
    EXPECT_NE(out.find(s), std::string::npos) << s;
}

}  // namespace
