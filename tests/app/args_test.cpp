// The option tables (src/util/args.h, src/app/cli.cpp): parsing, the one-line usage errors,
// the defaults shown, mounted tables, and the README's option table kept in step.
#include <gtest/gtest.h>

#include <fstream>
#include <iterator>
#include <string>
#include <vector>

#include "app/cli.h"
#include "util/args.h"

namespace rt {
namespace {

// argv as main() gets it, program name first.
struct Argv {
  explicit Argv(std::vector<std::string> args) : strings(std::move(args)) {
    strings.insert(strings.begin(), "prog");
    for (std::string& s : strings) pointers.push_back(s.data());
  }
  int argc() const { return static_cast<int>(pointers.size()); }
  char** argv() { return pointers.data(); }
  std::vector<std::string> strings;
  std::vector<char*> pointers;
};

// Parses into a fresh CliOptions with the raytracer's table; returns the usage error, if any.
std::string parse(std::vector<std::string> args, CliOptions* out,
                  std::string* exit_text = nullptr) {
  Argv a(std::move(args));
  std::string text;
  try {
    raytracer_option_table().parse(a.argc(), a.argv(), out, exit_text ? exit_text : &text);
  } catch (const UsageError& e) {
    return e.what();
  }
  return "";
}

TEST(RaytracerOptions, ParsesEveryKindInAnyOrder) {
  CliOptions o;
  EXPECT_EQ(parse({"--spp", "7", "scene.xml", "--filter=gaussian", "--fast-math", "-q",
                   "--resolution-scale", "0.5", "--device", "cpu", "--no-scene-epsilon",
                   "--quantize", "round", "--bvh-bins=8", "--cl-device", "pocl"},
                  &o),
            "");
  EXPECT_EQ(o.render.spp, 7);
  EXPECT_EQ(o.render.filter, RT_FILTER_GAUSSIAN);
  EXPECT_TRUE(o.render.fast_math);
  EXPECT_TRUE(o.quiet);
  EXPECT_EQ(o.resolution_scale, 0.5);
  EXPECT_EQ(o.device, Device::kCpu);
  EXPECT_FALSE(o.render.use_scene_epsilon);
  EXPECT_EQ(o.quantize, Quantize::kRound);
  EXPECT_EQ(o.render.bvh.bins, 8);
  EXPECT_EQ(o.cl_device, "pocl");
}

TEST(RaytracerOptions, DefaultsAreTheStructsAndTruncate) {
  CliOptions o;
  EXPECT_EQ(parse({"scene.xml"}, &o), "");
  CliOptions d;
  EXPECT_EQ(o.quantize, Quantize::kTruncate);
  EXPECT_EQ(o.render.bvh.bins, d.render.bvh.bins);
  EXPECT_EQ(o.render.seed, d.render.seed);
  EXPECT_TRUE(o.kernel_cache);
}

// The course's conventions are the defaults; each option names the other choice, and
// --frame world hands the devices the file's own coordinates instead of the camera's frame.
TEST(RaytracerOptions, ConventionChoicesDefaultToTheCourse) {
  CliOptions o;
  EXPECT_EQ(parse({"scene.xml"}, &o), "");
  EXPECT_TRUE(o.render.camera_frame);
  EXPECT_FALSE(o.render.robust_offset);
  EXPECT_FALSE(o.render.exact_camera_rays);
  EXPECT_FALSE(o.render.geometric_offset);
  EXPECT_FALSE(o.render.facing_reflection);
  CliOptions w;
  EXPECT_EQ(parse({"scene.xml", "--frame", "world", "--ray-offset", "robust", "--camera-rays",
                   "exact", "--shadow-offset", "geometric", "--reflection-offset", "facing"},
                  &w),
            "");
  EXPECT_FALSE(w.render.camera_frame);
  EXPECT_TRUE(w.render.robust_offset);
  EXPECT_TRUE(w.render.exact_camera_rays);
  EXPECT_TRUE(w.render.geometric_offset);
  EXPECT_TRUE(w.render.facing_reflection);
  EXPECT_EQ(parse({"--frame", "object"}, &w), "--frame: 'object' is not one of camera, world");
}

TEST(RaytracerOptions, UsageErrorsNameTheOptionAndTheValue) {
  CliOptions o;
  EXPECT_EQ(parse({"--spp", "abc"}, &o), "--spp: 'abc' is not a whole number in [1, 1048576]");
  EXPECT_EQ(parse({"--spp"}, &o), "--spp needs a value");
  EXPECT_EQ(parse({"--frobnicate"}, &o), "unknown option '--frobnicate'");
  EXPECT_EQ(parse({"--device", "gpu"}, &o), "--device: 'gpu' is not one of auto, cl, cpu");
  EXPECT_EQ(parse({"--time-limit", "-1"}, &o), "--time-limit: '-1' is not a positive number");
  EXPECT_EQ(parse({"--resolution-scale=17"}, &o),
            "--resolution-scale: '17' is not a number in (0, 16]");
  EXPECT_EQ(parse({"--stats=1"}, &o), "--stats takes no value");
  EXPECT_EQ(parse({"--seed", "4294967296"}, &o),
            "--seed: '4294967296' is not a whole number in [0, 4294967295]");
  EXPECT_EQ(parse({"--filter-sigma", "nan"}, &o),
            "--filter-sigma: 'nan' is not a number in [0.054, 100)");
}

TEST(RaytracerOptions, HelpListsEveryOptionDefaultAndVariable) {
  CliOptions o;
  std::string help;
  EXPECT_EQ(parse({"--help"}, &o, &help), "");
  for (const OptionInfo& info : raytracer_option_table().options())
    EXPECT_NE(help.find(info.names[0]), std::string::npos) << info.names[0];
  for (const char* s : {"RT_CL_OPTIONS", "XDG_CACHE_HOME", "HOME", "(default 16)",
                        "(default truncate)", "(reaches the device)", "--version"})
    EXPECT_NE(help.find(s), std::string::npos) << s;
  std::string version;
  EXPECT_EQ(parse({"--version"}, &o, &version), "");
  EXPECT_EQ(version.rfind("raytracer ", 0), 0u);
}

// The device options are exactly the mounted device table, plus the kernel choice.
TEST(RaytracerOptions, DeviceOptionsAreKeptApart) {
  std::vector<std::string> device;
  for (const OptionInfo& info : raytracer_option_table().options())
    if (info.reach == Reach::kDevice) device.push_back(info.names[0]);
  std::vector<std::string> expected;
  for (const OptionInfo& info : device_option_table().options()) expected.push_back(info.names[0]);
  expected.push_back("--kernel");
  EXPECT_EQ(device, expected);
}

struct Toy {
  int n = 3;
  std::vector<double> alphas = {0.01};
  std::vector<std::string> expects;
  RenderOptions render;
};

TEST(OptionTable, ListsMountsAndPositionals) {
  OptionTable<Toy> t("toy", "toy A B", "A toy.");
  t.integer("--n", "N", Range::closed(1, 9), RT_FIELD(n), "a count")
      .list(
          "--alpha", "A[,A...]", RT_FIELD(alphas),
          [](const std::string& s) { return parse_number(s, Range::open(0, 1)); }, "levels")
      .list(
          "--expect", "SPEC", RT_FIELD(expects), [](const std::string& s) { return s; },
          "repeatable", true)
      .include(device_option_table(), RT_FIELD(render));
  EXPECT_EQ(t.options()[0].default_text, "3");
  EXPECT_EQ(t.options()[1].default_text, "0.01");
  Argv a({"x.xml", "--alpha", "0.05,0.1", "--expect", "a:1", "y.png", "--expect", "b:2",
          "--cull-back-faces", "--n=4"});
  Toy toy;
  std::string exit_text;
  std::vector<std::string> pos = t.parse(a.argc(), a.argv(), &toy, &exit_text);
  EXPECT_EQ(pos, (std::vector<std::string>{"x.xml", "y.png"}));
  EXPECT_EQ(toy.alphas, (std::vector<double>{0.05, 0.1}));
  EXPECT_EQ(toy.expects, (std::vector<std::string>{"a:1", "b:2"}));
  EXPECT_TRUE(toy.render.cull_back_faces);
  EXPECT_EQ(toy.n, 4);
  Argv bad({"--alpha", "0.05,2"});
  EXPECT_THROW(t.parse(bad.argc(), bad.argv(), &toy, &exit_text), UsageError);
}

// The README's table is what --help-markdown prints; tools/readme_options.sh rewrites it.
TEST(ReadmeOptions, MatchesTheOptionTable) {
  std::ifstream in(std::string(RT_SOURCE_DIR) + "/docs/options.md");
  ASSERT_TRUE(in) << "README.md not found";
  std::string readme{std::istreambuf_iterator<char>(in), {}};
  const std::string begin = "<!-- options: generated by tools/readme_options.sh -->\n";
  const std::string end = "<!-- end of options -->";
  size_t b = readme.find(begin), e = readme.find(end);
  ASSERT_NE(b, std::string::npos);
  ASSERT_NE(e, std::string::npos);
  b += begin.size();
  EXPECT_EQ(readme.substr(b, e - b), raytracer_option_table().markdown())
      << "the README's option table is out of step: run tools/readme_options.sh";
}

}  // namespace
}  // namespace rt
