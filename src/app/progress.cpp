#include "progress.h"

#include <fcntl.h>
#include <sys/ioctl.h>
#include <unistd.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <fstream>
#include <set>

namespace rt {
namespace {

using Clock = std::chrono::steady_clock;

double seconds_since(Clock::time_point t) {
  return std::chrono::duration<double>(Clock::now() - t).count();
}

// The terminal's width in columns; 0 when stderr is not a terminal (under mpirun it is
// a pipe, and the job line is kept short instead).
size_t terminal_columns() {
  winsize w{};
  return ioctl(STDERR_FILENO, TIOCGWINSZ, &w) == 0 ? w.ws_col : 0;
}

// `text` cut to one row of the terminal: a line that wrapped would be redrawn from its
// last row only, leaving the rows above behind. The head is cut, so the figures at the
// end stay.
std::string fit(const std::string& text) {
  const size_t cols = terminal_columns();
  if (cols < 8 || text.size() < cols) return text;
  return "..." + text.substr(text.size() - (cols - 4));
}

// Draws `text` over the current line: \r, the text, then "erase to the end of the line",
// so a shorter line leaves nothing of a longer one behind.
void draw_line(const std::string& text) {
  std::fprintf(stderr, "\r%s\x1b[K", fit(text).c_str());
  std::fflush(stderr);
}

// The parent of process `pid` and its command name, from /proc (Linux); false elsewhere.
bool parent_of(int pid, int* ppid, std::string* comm) {
  std::ifstream stat("/proc/" + std::to_string(pid) + "/stat");
  std::string line;
  if (!std::getline(stat, line)) return false;
  const size_t open = line.find('('), close = line.rfind(')');
  if (open == std::string::npos || close == std::string::npos) return false;
  *comm = line.substr(open + 1, close - open - 1);
  char state = 0;
  return std::sscanf(line.c_str() + close + 1, " %c %d", &state, ppid) == 2;
}

// Whether the MPI launcher that started this process (mpirun, mpiexec: an ancestor on this
// node) writes its stderr to a terminal. Open MPI hands every rank a pipe for stderr (and
// a pseudo-terminal for stdout whatever the launcher's own output is), so neither of the
// rank's own descriptors tells.
bool launcher_on_terminal() {
  static const std::set<std::string> launchers = {"mpirun",  "mpiexec",       "orterun",
                                                  "prterun", "mpiexec.hydra", "mpiexec.openmpi"};
  int pid = getpid();
  for (int depth = 0; depth < 4; ++depth) {
    int ppid = 0;
    std::string comm;
    if (!parent_of(pid, &ppid, &comm) || ppid <= 1) return false;
    std::string parent_comm;
    int unused = 0;
    if (!parent_of(ppid, &unused, &parent_comm)) return false;
    if (launchers.count(parent_comm)) {
      const std::string fd = "/proc/" + std::to_string(ppid) + "/fd/2";
      const int f = open(fd.c_str(), O_WRONLY | O_NOCTTY);
      if (f < 0) return false;
      const bool tty = isatty(f);
      close(f);
      return tty;
    }
    pid = ppid;
  }
  return false;
}

}  // namespace

std::string format_duration(double s) {
  char buf[48];
  if (!(s >= 0) || !std::isfinite(s)) return "?";
  if (s < 60) {
    std::snprintf(buf, sizeof buf, "%.1f s", s);
  } else if (s < 3600) {
    const long t = std::lround(s);
    std::snprintf(buf, sizeof buf, "%ld min %02ld s", t / 60, t % 60);
  } else {
    const long m = std::lround(s / 60);
    std::snprintf(buf, sizeof buf, "%ld h %02ld min", m / 60, m % 60);
  }
  return buf;
}

Progress::Progress(bool enabled, std::string label, uint64_t pixels, int spp)
    : enabled_(enabled), label_(std::move(label)), pixels_(pixels), spp_(spp) {
  start_ = last_draw_ = Clock::now();
}

bool Progress::wanted(bool quiet) { return !quiet && isatty(STDERR_FILENO); }

bool Progress::wanted_mpi(bool quiet) {
  return !quiet && (isatty(STDERR_FILENO) || launcher_on_terminal());
}

void Progress::begin() {
  std::lock_guard<std::mutex> lock(mutex_);
  start_ = Clock::now();
  last_draw_ = start_ - std::chrono::seconds(1);  // The first add draws.
}

void Progress::start_at(int spp) {
  resumed_ = pixels_ * static_cast<uint64_t>(std::max(spp, 0));
  samples_ = resumed_;
}

double Progress::elapsed_s() const { return seconds_since(start_); }

void Progress::add(uint64_t samples, uint64_t rays) {
  samples_ += samples;
  rays_ += rays;
  if (!enabled_) return;
  const auto now = Clock::now();
  std::unique_lock<std::mutex> lock(mutex_, std::try_to_lock);
  if (!lock.owns_lock() || now - last_draw_ < std::chrono::milliseconds(200)) return;
  last_draw_ = now;
  draw();
}

void Progress::finish() {
  if (!enabled_) return;
  std::lock_guard<std::mutex> lock(mutex_);
  clear_status(true);
}

void Progress::draw() {
  const double elapsed = seconds_since(start_);
  const uint64_t done = samples_.load();
  const uint64_t total = pixels_ * static_cast<uint64_t>(spp_);
  const double frac = total ? static_cast<double>(done) / total : 1.0;
  // Whole samples of every pixel: passes cover the image in bands, so mid-pass some rows
  // hold one sample more; the line shows what every pixel has.
  const uint64_t spp_done = pixels_ ? done / pixels_ : 0;
  const uint64_t taken = done - std::min(done, resumed_);  // In this run.
  char buf[160];
  std::snprintf(
      buf, sizeof buf, ": %llu of %d spp (%.1f %%), elapsed %s, %.2f Mrays/s, left %s",
      static_cast<unsigned long long>(spp_done), spp_, 100 * frac, format_duration(elapsed).c_str(),
      elapsed > 0 ? rays_.load() / elapsed * 1e-6 : 0.0,
      taken > 0 ? format_duration(elapsed * (total - std::min(done, total)) / taken).c_str() : "?");
  draw_line(label_ + buf);
}

void show_status(bool enabled, const std::string& text) {
  if (enabled) draw_line(text);
}

void clear_status(bool enabled) {
  if (!enabled) return;
  std::fputs("\r\x1b[K", stderr);
  std::fflush(stderr);
}

namespace {
std::atomic<bool> status_reports{false};
}  // namespace

void enable_status_reports(bool enabled) { status_reports = enabled; }

void report_status(const std::string& text) { show_status(status_reports.load(), text); }

void print_wrote(bool shown, const std::string& file, int spp, double seconds) {
  if (!shown) return;
  std::fprintf(stderr, "wrote %s (%d spp, %.2f s)\n", file.c_str(), spp, seconds);
}

JobProgress::JobProgress(bool enabled, int images, int tasks, uint64_t samples, uint64_t resumed)
    : enabled_(enabled),
      images_(images),
      tasks_(tasks),
      samples_(samples),
      resumed_(resumed),
      samples_done_(resumed) {
  start_ = last_draw_ = Clock::now();
  if (enabled_) draw();
}

void JobProgress::task_done(uint64_t samples, bool image_written) {
  samples_done_ += samples;
  ++tasks_done_;
  if (image_written) ++images_done_;
  if (!enabled_) return;
  const auto now = Clock::now();
  if (now - last_draw_ < std::chrono::milliseconds(200) && tasks_done_ < tasks_) return;
  last_draw_ = now;
  draw();
}

void JobProgress::tick() {
  if (!enabled_ || Clock::now() - last_draw_ < std::chrono::seconds(1)) return;
  last_draw_ = Clock::now();
  draw();
}

void JobProgress::finish() { clear_status(enabled_); }

void JobProgress::draw() {
  const double elapsed = seconds_since(start_);
  const double frac = samples_ ? static_cast<double>(samples_done_) / samples_ : 1.0;
  const uint64_t taken = samples_done_ - std::min(samples_done_, resumed_);  // In this run.
  char buf[200];
  std::snprintf(
      buf, sizeof buf, "job: %d of %d %s, %d of %d images written (%.1f %%), elapsed %s, left %s",
      tasks_done_, tasks_, tasks_ == images_ ? "images" : "tiles", images_done_, images_,
      100 * frac, format_duration(elapsed).c_str(),
      taken > 0 ? format_duration(elapsed * (samples_ - std::min(samples_done_, samples_)) / taken)
                      .c_str()
                : "?");
  draw_line(buf);
}

}  // namespace rt
