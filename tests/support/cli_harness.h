// Running the built raytracer executable from a test: a tiny scene, a fixture with its own
// temporary directory, and the outcome of a run (exit status, stdout, stderr).
#pragma once

#include <gtest/gtest.h>

#include <sys/types.h>

#include <filesystem>
#include <string>
#include <vector>

namespace rt::test {

// A tiny scene (16 x 8 pixels, two triangles and a sphere) that renders in milliseconds;
// its image is simple.png.
extern const char* const kTinyScene;

// `s` with the first `from` replaced by `to` (a test failure when `from` is absent).
std::string replaced(std::string s, const std::string& from, const std::string& to);
// `s` quoted for sh.
std::string quote(const std::string& s);
// The bytes of a file ("" when unreadable).
std::string slurp(const std::filesystem::path& p);

struct Outcome {
  int code = -1;  // Exit status; 124 when `timeout` killed it; 128 + n for signal n.
  std::string out, err;
  double seconds = 0;
};

// One line: exactly one newline, at the end, after the "raytracer: error: " prefix.
void expect_one_error_line(const Outcome& r);

class CliFixture : public ::testing::Test {
 protected:
  void SetUp() override;
  void TearDown() override;

  // Writes `text` to `name` in the test's directory; returns its path.
  std::string write(const std::string& name, const std::string& text);
  // Runs the raytracer with `args` (already quoted), stdin empty, stdout and stderr captured
  // to files (so neither is a terminal), under a 10 s timeout; `env` prefixes the command.
  Outcome run(const std::string& args, const std::string& env = "");
  // The usual options: CPU, quiet, the temporary output directory.
  Outcome render(const std::string& scene, const std::string& extra = "");
  // Starts the raytracer with `args` in the background like run(), and returns its pid
  // once its signal handlers are installed (so a signal finds them).
  pid_t start(const std::string& args);
  // Waits for a started raytracer (killing it after 30 s) and returns its outcome.
  Outcome finish(pid_t pid);
  // The names in the output directory.
  std::vector<std::string> output_files() const;

  std::filesystem::path dir_;
  std::string out_;
};

}  // namespace rt::test
