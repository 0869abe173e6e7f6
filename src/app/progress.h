// Progress on a terminal: samples done, rays/s and time left, redrawn in place on
// stderr. Silent when stderr is not a terminal or --quiet is given.
#pragma once

#include <atomic>
#include <chrono>
#include <cstdint>
#include <mutex>
#include <string>

namespace rt {

class Progress {
 public:
  Progress(bool enabled, std::string label, uint64_t total_samples);
  // Adds finished work; safe to call from any thread; redraws at most 5 times a second.
  void add(uint64_t samples, uint64_t rays);
  void finish();

  // True when progress should be drawn: stderr is a terminal and not quiet.
  static bool wanted(bool quiet);

 private:
  void draw(bool final);

  bool enabled_;
  std::string label_;
  uint64_t total_;
  std::atomic<uint64_t> samples_{0}, rays_{0};
  std::chrono::steady_clock::time_point start_, last_draw_;
  std::mutex mutex_;
};

}  // namespace rt
