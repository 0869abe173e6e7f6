#include "progress.h"

#include <unistd.h>

#include <cstdio>

namespace rt {

Progress::Progress(bool enabled, std::string label, uint64_t total_samples)
    : enabled_(enabled), label_(std::move(label)), total_(total_samples) {
  start_ = last_draw_ = std::chrono::steady_clock::now();
}

bool Progress::wanted(bool quiet) { return !quiet && isatty(STDERR_FILENO); }

void Progress::add(uint64_t samples, uint64_t rays) {
  samples_ += samples;
  rays_ += rays;
  if (!enabled_) return;
  auto now = std::chrono::steady_clock::now();
  std::unique_lock<std::mutex> lock(mutex_, std::try_to_lock);
  if (!lock.owns_lock() || now - last_draw_ < std::chrono::milliseconds(200)) return;
  last_draw_ = now;
  draw(false);
}

void Progress::finish() {
  if (!enabled_) return;
  std::lock_guard<std::mutex> lock(mutex_);
  draw(true);
}

void Progress::draw(bool final) {
  double elapsed = std::chrono::duration<double>(std::chrono::steady_clock::now() - start_).count();
  uint64_t done = samples_.load();
  double frac = total_ ? static_cast<double>(done) / total_ : 1.0;
  double left = frac > 0 ? elapsed * (1 - frac) / frac : 0;
  std::fprintf(stderr, "\r%s: %5.1f%%  %llu/%llu samples  %.2f Mrays/s  %s %.1f s   ",
               label_.c_str(), 100 * frac, static_cast<unsigned long long>(done),
               static_cast<unsigned long long>(total_),
               elapsed > 0 ? rays_.load() / elapsed * 1e-6 : 0.0, final ? "took" : "left",
               final ? elapsed : left);
  if (final) std::fputc('\n', stderr);
  std::fflush(stderr);
}

}  // namespace rt
