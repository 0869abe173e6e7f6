#include "distributed/local_worker.h"

#include <memory>

#include "app/interrupt.h"

namespace rt {

LocalWorker::LocalWorker(const CliOptions& opt, int gpu_rank, int threads)
    : thread_([this, &opt, gpu_rank, threads] { loop(opt, gpu_rank, threads); }) {}

LocalWorker::~LocalWorker() {
  {
    std::lock_guard<std::mutex> lock(m_);
    quit_ = true;
  }
  cv_.notify_all();
  thread_.join();
}

void LocalWorker::assign(int32_t index, const TileTask& task) {
  {
    std::lock_guard<std::mutex> lock(m_);
    index_ = index;
    task_ = task;
  }
  cv_.notify_all();
}

bool LocalWorker::poll(int32_t* index, TileResult* result, std::string* error) {
  std::lock_guard<std::mutex> lock(m_);
  if (!error_.empty()) {
    *error = error_;
    error_.clear();
    return false;
  }
  if (!done_) return false;
  done_ = false;
  *index = done_index_;
  *result = std::move(result_);
  return true;
}

bool LocalWorker::poll_snapshot(int32_t* index, TileResult* snapshot) {
  std::lock_guard<std::mutex> lock(m_);
  if (!has_snapshot_) return false;
  has_snapshot_ = false;
  *index = running_;
  *snapshot = std::move(snapshot_);
  return true;
}

std::string LocalWorker::device_name() {
  std::unique_lock<std::mutex> lock(m_);
  cv_.wait(lock, [this] { return opened_; });
  return device_name_;
}

void LocalWorker::loop(const CliOptions& opt, int gpu_rank, int threads) {
  std::unique_ptr<TileWorker> worker;
  try {
    worker = std::make_unique<TileWorker>(opt, gpu_rank, threads);
  } catch (const std::exception& e) {
    std::lock_guard<std::mutex> lock(m_);
    error_ = e.what();
  }
  {
    std::lock_guard<std::mutex> lock(m_);
    opened_ = true;
    if (worker) device_name_ = worker->device_name();
  }
  cv_.notify_all();
  if (!worker) return;
  for (;;) {
    std::unique_lock<std::mutex> lock(m_);
    cv_.wait(lock, [this] { return quit_ || index_ >= 0; });
    if (quit_) return;
    const int32_t index = index_;
    const TileTask task = task_;
    index_ = -1;
    running_ = index;
    lock.unlock();
    try {
      TileResult r;
      if (!stop_requested().load())
        r = worker->render(task, [this](const TileResult& snap) {
          std::lock_guard<std::mutex> guard(m_);
          snapshot_ = snap;
          has_snapshot_ = true;
        });
      lock.lock();
      has_snapshot_ = false;  // The result supersedes it.
      result_ = std::move(r);
      done_index_ = index;
      done_ = true;
    } catch (const std::exception& e) {
      lock.lock();
      error_ = e.what();
      return;
    }
  }
}

}  // namespace rt
