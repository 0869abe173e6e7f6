// Every option of the device sections of the option table (the rows of `raytracer
// --help-markdown` that reach the device), through the executable: each value other than
// the default renders a small scene it applies to (tests/app/device_options/) on the CPU
// reference and on OpenCL, which must agree on every output (the EXR and PNG bytes, and
// every value and attribute of the moments file but the device's name), and must change
// those outputs versus the option's default, unless the option's help says it cannot:
// --kernel (either kernel renders the same image) and --fast-math (the CPU reference stays
// precise; OpenCL's image is then not bound to the CPU's). An option or value of the table
// without a case below fails EveryDeviceOptionHasACase, so a new one gets a case.
#include <gtest/gtest.h>

#include <algorithm>
#include <cctype>
#include <cmath>
#include <cstring>
#include <filesystem>
#include <map>
#include <regex>
#include <sstream>
#include <string>
#include <vector>

#include "io/moments.h"
#include "support/cli_harness.h"
#include "support/device_harness.h"

#ifndef RT_DEVICE_OPTION_SCENES
#error "RT_DEVICE_OPTION_SCENES must name tests/app/device_options"
#endif

namespace {

namespace fs = std::filesystem;
using namespace rt::test;

// What a value of an option does to the outputs, versus its default.
enum class Effect {
  kChanges,   // Changes them, with the same bytes on both devices.
  kSame,      // Keeps them (--kernel: the specialized and generic kernels agree).
  kClOnly,    // Applies to OpenCL only: the CPU keeps them, OpenCL is not compared.
  kNeedsFp64  // As kChanges, where the OpenCL device computes in double.
};

struct Case {
  const char* scene;    // In tests/app/device_options/.
  const char* context;  // Given to both renders (the default's and the value's).
  const char* args;     // The option with its value.
  Effect effect = Effect::kChanges;
};

void PrintTo(const Case& c, std::ostream* os) {
  *os << c.scene << ": " << c.context << " " << c.args;
}

// "tree" is the ray tracer's scene, "path" the path tracer's.
const std::vector<Case>& Cases() {
  static const std::vector<Case> cases = {
      {"tree", "", "--spp 2"},
      {"tree", "", "--seed 7"},
      {"tree", "", "--filter gaussian"},
      {"tree", "--filter gaussian", "--filter-sigma 0.3"},
      {"tree", "", "--lens disk"},
      {"tree", "", "--dielectric choose"},
      {"path", "", "--dielectric choose"},
      {"path", "", "--russian-roulette unbiased"},
      {"path", "", "--path-estimator mis"},
      {"path", "--path-estimator mis", "--sampler independent"},
      {"tree", "", "--sampler sobol"},
      {"path", "", "--sampler sobol"},
      {"tree", "", "--ellipsoid-lights exact"},
      {"tree", "", "--cull-back-faces"},
      {"tree", "", "--background-on-secondary-miss"},
      {"tree", "", "--reflection-offset facing"},
      {"tree", "", "--ray-offset robust"},
      {"tree", "", "--camera-rays exact"},
      {"tree", "", "--frame world"},
      {"tree", "", "--shadow-offset geometric"},
      {"tree", "", "--hit-point surface"},
      {"tree", "", "--no-scene-epsilon"},
      {"tree", "", "--precision double", Effect::kNeedsFp64},
      {"tree", "", "--precision auto", Effect::kNeedsFp64},
      {"tree", "", "--fast-math", Effect::kClOnly},
      {"tree", "", "--kernel generic", Effect::kSame},
      {"path", "", "--kernel generic", Effect::kSame},
  };
  return cases;
}

// A row of the option table: the option, its values when it is a choice (else its
// argument's name, or nothing for a flag), its default, and where it reaches.
struct Row {
  std::string name, arg, fallback, reach;
  std::vector<std::string> values;
};

std::vector<Row> TableRows(const std::string& markdown) {
  std::vector<Row> rows;
  const std::regex row(
      R"(^\| `(--[a-z0-9-]+)(?:, -[a-z])?( [^`]+)?` \| (?:`([^`]*)`)? *\| (\w+) \|)");
  std::istringstream in(markdown);
  for (std::string line; std::getline(in, line);) {
    std::smatch m;
    if (!std::regex_search(line, m, row)) continue;
    Row r{m[1], m[2].matched ? std::string(m[2]).substr(1) : "", m[3], m[4], {}};
    if (r.arg.find("\\|") != std::string::npos)
      for (size_t at = 0;;) {
        const size_t bar = r.arg.find("\\|", at);
        r.values.push_back(r.arg.substr(at, bar == std::string::npos ? bar : bar - at));
        if (bar == std::string::npos) break;
        at = bar + 2;
      }
    rows.push_back(r);
  }
  return rows;
}

// "" when the two arrays agree bit for bit (NaN and -0 included), else how many of their
// values differ and by how much at most.
template <typename T>
std::string BitDifference(const char* what, const std::vector<T>& a, const std::vector<T>& b) {
  if (a.size() != b.size()) return std::string(" ") + what + " (sizes differ);";
  size_t n = 0;
  double most = 0;
  for (size_t i = 0; i < a.size(); ++i)
    if (std::memcmp(&a[i], &b[i], sizeof(T)) != 0) {
      ++n;
      most = std::max(most, std::abs(static_cast<double>(a[i]) - static_cast<double>(b[i])));
    }
  if (n == 0) return "";
  std::ostringstream s;
  s << " " << what << " (" << n << " of " << a.size() << " values, by up to " << most << ");";
  return s.str();
}

// A render's outputs: the EXR and PNG bytes and the moments file.
struct Outputs {
  std::string exr, png;
  rt::MomentImage moments;
};

// "" when the two are the same, else what differs.
std::string Difference(const Outputs& a, const Outputs& b) {
  std::string d;
  if (a.exr != b.exr) d += " EXR bytes;";
  if (a.png != b.png) d += " PNG bytes;";
  const rt::MomentImage &m = a.moments, &n = b.moments;
  rt::MomentInfo i = m.info, j = n.info;
  i.device = j.device = "";
  if (m.width != n.width || m.height != n.height || i.seed != j.seed || i.spp != j.spp ||
      i.filter != j.filter || i.scene != j.scene || i.camera != j.camera ||
      i.samples_mark != j.samples_mark)
    d += " moments' attributes;";
  d += BitDifference("moments' means", m.mean, n.mean);
  d += BitDifference("moments' variances", m.var, n.var);
  d += BitDifference("moments' counts", m.count, n.count);
  d += BitDifference("first hits' distances", m.first_t, n.first_t);
  d += BitDifference("first hits' instances", m.instance, n.instance);
  d += BitDifference("first hits' primitives", m.primitive, n.primitive);
  d += BitDifference("first hits' normals", m.normal, n.normal);
  return d;
}

class DeviceOptions : public CliFixture, public ::testing::WithParamInterface<Case> {
 protected:
  void SetUp() override {
    CliFixture::SetUp();
    timeout_s_ = 120;  // A kernel not in the cache yet is built under the suite's load.
  }
  // Renders `scene` on `device` with `args` into a folder of its own; sets *err on failure.
  Outputs Render(const std::string& scene, rt::Device device, const std::string& args,
                 std::string* err = nullptr) {
    const fs::path out = dir_ / (std::to_string(renders_++) + device_label(device));
    fs::create_directories(out);
    const Outcome r = run(quote(std::string(RT_DEVICE_OPTION_SCENES) + "/" + scene + ".xml") +
                          " --quiet --moments --device " + device_label(device) + " --output-dir " +
                          quote(out.string()) + " " + args);
    Outputs o;
    if (r.code != 0) {
      if (err)
        *err = r.err.empty() ? "exit status " + std::to_string(r.code) : r.err;
      else
        ADD_FAILURE() << device_label(device) << " " << args << ": " << r.err;
      return o;
    }
    o.exr = slurp(out / (scene + ".exr"));
    o.png = slurp(out / (scene + ".png"));
    o.moments = rt::read_moments((out / (scene + ".moments.exr")).string());
    return o;
  }
  int renders_ = 0;
};

TEST_P(DeviceOptions, BothDevicesAgreeAndTheOptionDoesWhatItSays) {
  const Case& c = GetParam();
  std::string why;
  const bool cl = shared_device(rt::Device::kOpenCl, &why) != nullptr;
  const std::string with = std::string(c.context) + " " + c.args;
  const Outputs base_cpu = Render(c.scene, rt::Device::kCpu, c.context);
  const Outputs cpu = Render(c.scene, rt::Device::kCpu, with);
  ASSERT_FALSE(HasFailure());
  const std::string changed = Difference(cpu, base_cpu);
  if (c.effect == Effect::kChanges || c.effect == Effect::kNeedsFp64)
    EXPECT_NE(changed, "") << c.args << " changes nothing on the CPU";
  else
    EXPECT_EQ(changed, "") << c.args << " changes the CPU's outputs:" << changed;
  if (!cl) GTEST_SKIP() << "no OpenCL device: " << why;
  std::string err;
  if (c.effect == Effect::kNeedsFp64) {  // --precision double says whether it computes in double.
    Render(c.scene, rt::Device::kOpenCl, "--precision double", &err);
    if (err.find("cl_khr_fp64") != std::string::npos)
      GTEST_SKIP() << "the OpenCL device has no double precision: " << err;
  }
  const Outputs on_cl = Render(c.scene, rt::Device::kOpenCl, with, &err);
  ASSERT_EQ(err, "") << with;
  if (c.effect == Effect::kClOnly) return;  // Not bound to the CPU's bits.
  EXPECT_EQ(Difference(on_cl, cpu), "") << c.scene << " " << with << ": the devices differ in";
  if (c.effect == Effect::kSame) {
    const Outputs base_cl = Render(c.scene, rt::Device::kOpenCl, c.context);
    EXPECT_EQ(Difference(on_cl, base_cl), "") << c.args << " changes OpenCL's outputs";
  }
}

std::string CaseName(const ::testing::TestParamInfo<Case>& info) {
  std::string name = std::string(info.param.scene) + "_" + info.param.args;
  for (char& ch : name)
    if (!std::isalnum(static_cast<unsigned char>(ch))) ch = '_';
  return name;
}

INSTANTIATE_TEST_SUITE_P(Table, DeviceOptions, ::testing::ValuesIn(Cases()), CaseName);

// Every device option of the table has a case for each of its values but the default (a
// flag: set; a number: some value), and every case names such an option and value.
TEST_F(CliFixture, EveryDeviceOptionHasACase) {
  const Outcome r = run("--help-markdown");
  ASSERT_EQ(r.code, 0) << r.err;
  const std::vector<Row> rows = TableRows(r.out);
  std::map<std::string, Row> device;
  for (const Row& row : rows)
    if (row.reach == "device") device[row.name] = row;
  ASSERT_GE(device.size(), 20u) << "the table was not read:\n" << r.out;
  std::map<std::string, std::vector<std::string>> covered;  // Option -> values given.
  for (const Case& c : Cases()) {
    std::istringstream words(c.args);
    std::string name, value;
    words >> name >> value;
    ASSERT_TRUE(device.count(name)) << c.args << ": not a device option of the table";
    covered[name].push_back(value);
  }
  for (const auto& [name, row] : device) {
    ASSERT_TRUE(covered.count(name)) << name << " has no case in device_options_test.cpp";
    const std::vector<std::string>& given = covered[name];
    for (const std::string& v : row.values) {
      if (v == row.fallback) continue;
      EXPECT_NE(std::find(given.begin(), given.end(), v), given.end())
          << name << " " << v << " has no case in device_options_test.cpp";
    }
    for (const std::string& v : given) {
      if (!row.values.empty()) {
        EXPECT_NE(std::find(row.values.begin(), row.values.end(), v), row.values.end())
            << name << " has no value " << v;
      } else if (row.arg.empty()) {
        EXPECT_EQ(v, "") << name << " is a flag";
      } else {
        EXPECT_NE(v, "") << name << " takes a value";
      }
    }
  }
}

}  // namespace
