// The fixture of the executable's tests (cli_test.cpp, cli_input_checks_test.cpp): a tiny
// scene, running the built raytracer with captured output, and the one-error-line check.
#pragma once

#include <gtest/gtest.h>
#include <sys/wait.h>
#include <unistd.h>

#include <chrono>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <iterator>
#include <string>
#include <vector>

#ifndef RT_RAYTRACER_EXE
#error "RT_RAYTRACER_EXE must name the raytracer executable"
#endif

namespace rt_cli_test {

namespace fs = std::filesystem;

// A tiny scene (16 x 8 pixels, two triangles and a sphere) that renders in milliseconds.
inline const char* kScene = R"(<Scene>
    <BackgroundColor>0 0 0</BackgroundColor>
    <Cameras>
        <Camera id="1">
            <Position>0 0 0</Position>
            <Gaze>0 0 -1</Gaze>
            <Up>0 1 0</Up>
            <NearPlane>-1 1 -0.5 0.5</NearPlane>
            <NearDistance>1</NearDistance>
            <ImageResolution>16 8</ImageResolution>
            <ImageName>simple.png</ImageName>
        </Camera>
    </Cameras>
    <Lights>
        <AmbientLight>25 25 25</AmbientLight>
        <PointLight id="1">
            <Position>0 0 0</Position>
            <Intensity>1000 1000 1000</Intensity>
        </PointLight>
    </Lights>
    <Materials>
        <Material id="1">
            <AmbientReflectance>1 1 1</AmbientReflectance>
            <DiffuseReflectance>1 1 1</DiffuseReflectance>
        </Material>
    </Materials>
    <VertexData>
        -0.5 0.5 -2
        -0.5 -0.5 -2
        0.5 -0.5 -2
        0.5 0.5 -2
    </VertexData>
    <Objects>
        <Mesh id="1">
            <Material>1</Material>
            <Faces>
                3 1 2
                1 3 4
            </Faces>
        </Mesh>
        <Sphere id="1">
            <Material>1</Material>
            <Center>4</Center>
            <Radius>0.3</Radius>
        </Sphere>
    </Objects>
</Scene>
)";

inline std::string replaced(std::string s, const std::string& from, const std::string& to) {
  size_t at = s.find(from);
  EXPECT_NE(at, std::string::npos) << from;
  if (at != std::string::npos) s.replace(at, from.size(), to);
  return s;
}

inline std::string quote(const std::string& s) {
  std::string q = "'";
  for (char c : s) q += c == '\'' ? std::string("'\\''") : std::string(1, c);
  return q + "'";
}

inline std::string slurp(const fs::path& p) {
  std::ifstream in(p, std::ios::binary);
  return {std::istreambuf_iterator<char>(in), {}};
}

struct Outcome {
  int code = -1;  // Exit status; 124 when `timeout` killed it.
  std::string out, err;
  double seconds = 0;
};

class CliBadInput : public ::testing::Test {
 protected:
  void SetUp() override {
    const auto* info = ::testing::UnitTest::GetInstance()->current_test_info();
    dir_ = fs::temp_directory_path() / ("rt_cli_" + std::to_string(getpid()) + "_" + info->name());
    fs::remove_all(dir_);
    fs::create_directories(dir_ / "out");
    out_ = (dir_ / "out").string();
  }
  void TearDown() override { fs::remove_all(dir_); }

  std::string write(const std::string& name, const std::string& text) {
    fs::path p = dir_ / name;
    std::ofstream(p, std::ios::binary) << text;
    return p.string();
  }

  // Runs the raytracer with `args` (already quoted), stdin empty, stdout and stderr captured
  // to files (so neither is a terminal), under a 10 s timeout.
  Outcome run(const std::string& args, const std::string& env = "") {
    fs::path o = dir_ / "stdout.txt", e = dir_ / "stderr.txt";
    std::string cmd = env + " timeout 10 " + quote(RT_RAYTRACER_EXE) + " " + args + " <" +
                      quote("/dev/null") + " >" + quote(o.string()) + " 2>" + quote(e.string());
    auto t0 = std::chrono::steady_clock::now();
    int status = std::system(cmd.c_str());
    Outcome r;
    r.seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
    r.code = WIFEXITED(status) ? WEXITSTATUS(status) : -1;
    r.out = slurp(o);
    r.err = slurp(e);
    return r;
  }
  // The usual options: CPU, quiet, the temporary output directory.
  Outcome render(const std::string& scene, const std::string& extra = "") {
    return run(quote(scene) + " --device cpu --quiet --output-dir " + quote(out_) + " " + extra);
  }

  std::vector<std::string> output_files() const {
    std::vector<std::string> names;
    for (const auto& e : fs::directory_iterator(dir_ / "out")) names.push_back(e.path().filename());
    return names;
  }

  fs::path dir_;
  std::string out_;
};

// One line: exactly one newline, at the end, after the "raytracer: error: " prefix.
inline void expect_one_error_line(const Outcome& r) {
  EXPECT_EQ(r.err.rfind("raytracer: error: ", 0), 0u) << r.err;
  ASSERT_FALSE(r.err.empty());
  EXPECT_EQ(r.err.back(), '\n') << r.err;
  EXPECT_EQ(r.err.find('\n'), r.err.size() - 1) << "more than one line:\n" << r.err;
}

}  // namespace rt_cli_test
