// A stack of jobs that a few threads drain together, jobs pushing more jobs as they run
// (a recursive build split across threads), with records the jobs fill for a later,
// single-threaded pass. Which thread runs which job varies from run to run; whatever the
// jobs compute must depend on the job alone.
#pragma once

#include <condition_variable>
#include <deque>
#include <mutex>
#include <thread>
#include <vector>

namespace rt {

template <class Job, class Record>
class JobStack {
 public:
  void push(const Job& j) {
    {
      std::lock_guard<std::mutex> lock(mutex_);
      jobs_.push_back(j);
    }
    wake_.notify_one();
  }

  // Runs fn(job) for every job pushed, before or during the run, on `threads` threads
  // (the caller's included), the last pushed first: depth first, so a thread keeps working
  // on the memory it just touched. Returns when no job is left and none is running.
  template <class Fn>
  void run(int threads, Fn fn) {
    auto work = [&] {
      std::unique_lock<std::mutex> lock(mutex_);
      for (;;) {
        wake_.wait(lock, [&] { return !jobs_.empty() || busy_ == 0; });
        if (jobs_.empty()) return;  // Nothing queued and nobody left to queue more.
        Job j = jobs_.back();
        jobs_.pop_back();
        ++busy_;
        lock.unlock();
        fn(j);
        lock.lock();
        if (--busy_ == 0 && jobs_.empty()) wake_.notify_all();
      }
    };
    std::vector<std::thread> pool;
    for (int t = 1; t < threads; ++t) pool.emplace_back(work);
    work();
    for (auto& t : pool) t.join();
  }

  // A new record, valid as long as the stack: a deque never moves its elements.
  Record* new_record() {
    std::lock_guard<std::mutex> lock(mutex_);
    records_.emplace_back();
    return &records_.back();
  }

 private:
  std::mutex mutex_;
  std::condition_variable wake_;
  std::vector<Job> jobs_;
  std::deque<Record> records_;
  int busy_ = 0;
};

}  // namespace rt
