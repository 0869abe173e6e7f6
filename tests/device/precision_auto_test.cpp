// --precision auto: double where the device computes it, else float with a notice. The
// decision is one function (src/device/precision.h), tested here with made-up capabilities; the
// devices report theirs (the CPU reference always, PoCL through cl_khr_fp64), and the
// executable renders auto exactly as it renders the precision it resolved to.
#include <gtest/gtest.h>

#include <string>
#include <vector>

#include "app/cli.h"
#include "device/device.h"
#include "device/precision.h"
#include "support/cli_harness.h"

namespace rt {
namespace {

TEST(ResolvePrecision, AutoIsDoubleWhereTheDeviceHasIt) {
  std::string notice = "stale";
  EXPECT_EQ(resolve_precision(Precision::kAuto, true, "gpu", &notice), Precision::kDouble);
  EXPECT_EQ(notice, "");
}

TEST(ResolvePrecision, AutoFallsBackToFloatWithANoticeNamingTheDevice) {
  std::string notice;
  EXPECT_EQ(resolve_precision(Precision::kAuto, false, "Mali-G78", &notice), Precision::kFloat);
  EXPECT_NE(notice.find("Mali-G78"), std::string::npos) << notice;
  EXPECT_NE(notice.find("cl_khr_fp64"), std::string::npos) << notice;
  EXPECT_NE(notice.find("float"), std::string::npos) << notice;
  EXPECT_EQ(notice.find('\n'), std::string::npos) << "one line";
}

TEST(ResolvePrecision, ExplicitChoicesPassThrough) {
  std::string notice;
  for (bool fp64 : {false, true}) {
    EXPECT_EQ(resolve_precision(Precision::kFloat, fp64, "d", &notice), Precision::kFloat);
    EXPECT_EQ(notice, "");
    // A device without fp64 refuses double when its program is built (cl_program.cpp).
    EXPECT_EQ(resolve_precision(Precision::kDouble, fp64, "d", &notice), Precision::kDouble);
    EXPECT_EQ(notice, "");
  }
}

CliOptions parse(std::vector<std::string> args) {
  args.insert(args.begin(), "raytracer");
  args.push_back("scene.xml");
  std::vector<char*> argv;
  for (std::string& a : args) argv.push_back(a.data());
  std::string exit_text;
  return parse_arguments(static_cast<int>(argv.size()), argv.data(), &exit_text);
}

TEST(PrecisionOption, ParsesEveryChoiceAndDefaultsToFloat) {
  EXPECT_EQ(parse({}).render.precision, Precision::kFloat);
  EXPECT_EQ(parse({"--precision", "float"}).render.precision, Precision::kFloat);
  EXPECT_EQ(parse({"--precision", "double"}).render.precision, Precision::kDouble);
  EXPECT_EQ(parse({"--precision", "auto"}).render.precision, Precision::kAuto);
  EXPECT_THROW(parse({"--precision", "half"}), UsageError);
}

TEST(PrecisionAuto, ResolvesToDoubleOnTheCpuReference) {
  std::string notice;
  DeviceOptions o;
  o.kind = Device::kCpu;
  std::unique_ptr<RenderDevice> cpu = create_device(o, &notice);
  EXPECT_EQ(resolve_precision(Precision::kAuto, cpu->has_double(), cpu->name(), &notice),
            Precision::kDouble);
}

TEST(PrecisionAuto, ResolvesToDoubleOnPocl) {
  std::string notice;
  DeviceOptions o;
  o.kind = Device::kOpenCl;
  std::unique_ptr<RenderDevice> cl;
  try {
    cl = create_device(o, &notice);
  } catch (const std::exception& e) {
    GTEST_SKIP() << "no OpenCL device: " << e.what();
  }
  // PoCL's CPU devices are named pthread-<cpu> (or cpu-<cpu> in newer releases), and
  // report cl_khr_fp64.
  const std::string name = cl->name();
  if (name.rfind("pthread", 0) != 0 && name.rfind("cpu", 0) != 0)
    GTEST_SKIP() << name << " is not PoCL's CPU device";
  EXPECT_TRUE(cl->has_double()) << name;
  EXPECT_EQ(resolve_precision(Precision::kAuto, cl->has_double(), name, &notice),
            Precision::kDouble);
  EXPECT_EQ(notice, "");
}

// The executable renders auto as the precision it resolves to: on the CPU reference, the
// moment file (the unclamped float means, to the last bit) equals that of double, not
// that of float.
class PrecisionAutoCli : public test::CliFixture {};

TEST_F(PrecisionAutoCli, CpuRendersAutoExactlyAsDouble) {
  const std::string scene = write("s.xml", test::kTinyScene);
  auto moments_of = [&](const std::string& precision) {
    test::Outcome r = render(scene, "--moments --precision " + precision);
    EXPECT_EQ(r.code, 0) << r.err;
    EXPECT_EQ(r.err, "") << "--quiet prints nothing";
    return test::slurp(dir_ / "out" / "simple.moments.exr");
  };
  const std::string in_double = moments_of("double"), in_auto = moments_of("auto");
  ASSERT_FALSE(in_double.empty());
  EXPECT_TRUE(in_auto == in_double);
  // Float rounds differently in the last bits of some means, so the check can fail.
  EXPECT_FALSE(in_auto == moments_of("float"));
}

}  // namespace
}  // namespace rt
