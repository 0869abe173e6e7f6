#include "support/cli_harness.h"

#include <sys/wait.h>
#include <unistd.h>

#include <signal.h>

#include <chrono>
#include <cstdlib>
#include <fstream>
#include <iterator>
#include <thread>

#include "support/device_harness.h"

#ifndef RT_RAYTRACER_EXE
#error "RT_RAYTRACER_EXE must name the raytracer executable"
#endif

namespace rt::test {

namespace fs = std::filesystem;

std::string quote(const std::string& s) {
  std::string q = "'";
  for (char c : s) q += c == '\'' ? std::string("'\\''") : std::string(1, c);
  return q + "'";
}

// One line: exactly one newline, at the end, after the "raytracer: error: " prefix.
void expect_one_error_line(const Outcome& r) {
  EXPECT_EQ(r.err.rfind("raytracer: error: ", 0), 0u) << r.err;
  ASSERT_FALSE(r.err.empty());
  EXPECT_EQ(r.err.back(), '\n') << r.err;
  EXPECT_EQ(r.err.find('\n'), r.err.size() - 1) << "more than one line:\n" << r.err;
}

void CliFixture::SetUp() {
  TempDirTest::SetUp();
  fs::create_directories(dir_ / "out");
  out_ = (dir_ / "out").string();
}

Outcome CliFixture::run(const std::string& args, const std::string& env) {
  fs::path o = dir_ / "stdout.txt", e = dir_ / "stderr.txt";
  std::string cmd = env + " timeout " + std::to_string(timeout_s_) + " " + quote(RT_RAYTRACER_EXE) +
                    " " + args + " <" + quote("/dev/null") + " >" + quote(o.string()) + " 2>" +
                    quote(e.string());
  auto t0 = std::chrono::steady_clock::now();
  int status = std::system(cmd.c_str());
  Outcome r;
  r.seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
  r.code = WIFEXITED(status) ? WEXITSTATUS(status) : -1;
  r.out = slurp(o);
  r.err = slurp(e);
  return r;
}
namespace {

// True once `pid` runs the raytracer (not the shell before its exec) with a SIGINT handler.
bool handlers_installed(pid_t pid) {
  const std::string proc = "/proc/" + std::to_string(pid);
  if (slurp(proc + "/comm") != "raytracer\n") return false;
  std::ifstream status(proc + "/status");
  for (std::string line; std::getline(status, line);)
    if (line.rfind("SigCgt:", 0) == 0)
      return (std::stoull(line.substr(7), nullptr, 16) >> (SIGINT - 1)) & 1;
  return false;
}

}  // namespace

pid_t CliFixture::start(const std::string& args) {
  fs::path o = dir_ / "stdout.txt", e = dir_ / "stderr.txt";
  const std::string cmd = "exec " + quote(RT_RAYTRACER_EXE) + " " + args + " <" +
                          quote("/dev/null") + " >" + quote(o.string()) + " 2>" + quote(e.string());
  const pid_t pid = fork();
  if (pid == 0) {
    execl("/bin/sh", "sh", "-c", cmd.c_str(), static_cast<char*>(nullptr));
    _exit(127);
  }
  for (int i = 0; i < 2000 && !handlers_installed(pid); ++i)
    std::this_thread::sleep_for(std::chrono::milliseconds(5));
  EXPECT_TRUE(handlers_installed(pid)) << "the raytracer did not start";
  return pid;
}

Outcome CliFixture::finish(pid_t pid) {
  auto t0 = std::chrono::steady_clock::now();
  int status = 0;
  while (waitpid(pid, &status, WNOHANG) == 0) {
    if (std::chrono::steady_clock::now() - t0 > std::chrono::seconds(30)) {
      ADD_FAILURE() << "the raytracer did not stop within 30 s";
      kill(pid, SIGKILL);
      waitpid(pid, &status, 0);
      break;
    }
    std::this_thread::sleep_for(std::chrono::milliseconds(5));
  }
  Outcome r;
  r.code = WIFEXITED(status) ? WEXITSTATUS(status) : 128 + WTERMSIG(status);
  r.out = slurp(dir_ / "stdout.txt");
  r.err = slurp(dir_ / "stderr.txt");
  return r;
}

Outcome CliFixture::render(const std::string& scene, const std::string& extra) {
  return run(quote(scene) + " --device cpu --quiet --output-dir " + quote(out_) + " " + extra);
}

void DeviceCliFixture::SetUp() {
  CliFixture::SetUp();
  std::string why;
  if (GetParam() == Device::kOpenCl && !shared_device(Device::kOpenCl, &why))
    GTEST_SKIP() << "no OpenCL device: " << why;
}

std::string DeviceCliFixture::device_flag() const {
  return std::string(" --device ") + device_label(GetParam());
}

std::string device_param_name(const ::testing::TestParamInfo<Device>& info) {
  return device_label(info.param);
}

std::vector<std::string> CliFixture::output_files() const {
  std::vector<std::string> names;
  for (const auto& e : fs::directory_iterator(dir_ / "out")) names.push_back(e.path().filename());
  return names;
}

}  // namespace rt::test
