// What a render tells the person who started it, on stderr:
// - on a terminal only (Progress::wanted): a live line redrawn in place,
//   "[k/n] NAME: S of N spp (P %), elapsed E, R Mrays/s, left L", and transient status
//   lines for the slow steps before it (loading the scene, building the BVH, compiling the
//   OpenCL kernel), so the terminal is never blank;
// - unless --quiet, also in logs (stderr not a terminal): one "wrote FILE (S spp, T s)" line
//   per image, the record of what a run produced.
// Under mpirun rank 0's stderr is a pipe to the launcher; Progress::wanted_mpi asks whether
// the launcher's own stderr is a terminal instead.
#pragma once

#include <atomic>
#include <chrono>
#include <cstdint>
#include <mutex>
#include <string>

namespace rt {

class Progress {
 public:
  // One image of `pixels` pixels and `spp` samples per pixel; `label` heads the line
  // ("[2/9] tap_0200.png"). A Progress that is not enabled, a sink for the scheduler's
  // reports, needs no counts.
  Progress(bool enabled, std::string label, uint64_t pixels = 0, int spp = 1);
  // Sampling starts now: elapsed time and the rate leave out loading and compiling.
  void begin();
  // The film already holds `spp` samples of every pixel (a checkpoint continued): the line
  // starts there, and the time left follows from the samples this run takes.
  void start_at(int spp);
  // Adds finished work (pixel samples, rays cast); safe from any thread; redraws at most
  // 5 times a second.
  void add(uint64_t samples, uint64_t rays);
  // Clears the live line (the caller prints the image's "wrote" line).
  void finish();
  double elapsed_s() const;
  bool enabled() const { return enabled_; }

  // True when progress should be drawn: stderr is a terminal and not quiet.
  static bool wanted(bool quiet);
  // Under mpirun: true when not quiet and stderr, or the launcher's stderr, is a terminal.
  static bool wanted_mpi(bool quiet);

 private:
  void draw();

  bool enabled_;
  std::string label_;
  uint64_t pixels_;
  int spp_;
  std::atomic<uint64_t> samples_{0}, rays_{0};
  uint64_t resumed_ = 0;  // Samples the film held before this run.
  std::chrono::steady_clock::time_point start_, last_draw_;
  std::mutex mutex_;
};

// A transient status on the live line's place ("loading scene.xml…"), replaced by the
// next status or the progress line; nothing when !enabled.
void show_status(bool enabled, const std::string& text);
// Erases the live line or status, so that a line printed next starts clean.
void clear_status(bool enabled);
// The record of a finished image: "wrote FILE (S spp, T s)", beside the progress it ends:
// only when `shown` (a terminal, not --quiet), like the live line.
void print_wrote(bool shown, const std::string& file, int spp, double seconds);
// Status from steps deep inside a device (the OpenCL kernel compile): shown through
// show_status once a driver has enabled it (off by default: tests, tools, --quiet).
void enable_status_reports(bool enabled);
void report_status(const std::string& text);
// "12.3 s", "4 min 05 s", "2 h 03 min".
std::string format_duration(double seconds);

// The job-wide line of a distributed render (rank 0): tasks (images or tiles) done of
// the total, images written, the share of the job's pixel samples taken, elapsed and time
// left from the samples this run took. `resumed`: the samples the checkpoints it continues
// hold, counted as done from the start.
class JobProgress {
 public:
  JobProgress(bool enabled, int images, int tasks, uint64_t samples, uint64_t resumed = 0);
  // A task is done that took `samples` pixel samples.
  void task_done(uint64_t samples, bool image_written);
  // Redraws at most once a second, so elapsed time moves while long tasks run.
  void tick();
  // Erases the line (before another line is printed); the next task_done draws it again.
  void clear() { clear_status(enabled_); }
  void finish();
  bool enabled() const { return enabled_; }

 private:
  void draw();
  bool enabled_;
  int images_, tasks_, images_done_ = 0, tasks_done_ = 0;
  uint64_t samples_, resumed_, samples_done_;
  std::chrono::steady_clock::time_point start_, last_draw_;
};

}  // namespace rt
