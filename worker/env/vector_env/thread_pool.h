#pragma once
// A small fixed pool of persistent threads with one job: run f(i) for every i in [0, n) and
// return when all are done. The caller's thread takes a share, so a pool of T threads starts
// T - 1. Indices are split into T contiguous ranges, one per thread (a static partition): which
// thread runs an index never changes what f computes, only when.
#include <condition_variable>
#include <cstddef>
#include <exception>
#include <functional>
#include <mutex>
#include <thread>
#include <vector>

namespace rlpos {

class ThreadPool {
 public:
  // `threads` = 0: std::thread::hardware_concurrency() (at least 1).
  explicit ThreadPool(std::size_t threads = 0);
  // Joins the threads.
  ~ThreadPool();
  ThreadPool(const ThreadPool&) = delete;
  ThreadPool& operator=(const ThreadPool&) = delete;

  std::size_t Size() const { return workers_.size() + 1; }

  // f(i) for i in [0, n) over the pool. An exception of a task does not stop the others: once
  // every task of the call has finished, the exception of the lowest index is rethrown. One
  // call at a time per pool.
  void ForEach(std::size_t n, const std::function<void(std::size_t)>& f);

 private:
  void Work(std::size_t share);      // a pool thread's loop
  void RunShare(std::size_t share);  // share `share` of the current call

  std::vector<std::thread> workers_;
  std::mutex mutex_;
  std::condition_variable wake_;  // a new call, or the end
  std::condition_variable done_;  // a share finished
  std::size_t generation_ = 0;    // counts calls, so a thread runs each call once
  std::size_t pending_ = 0;       // shares of the current call still running on pool threads
  bool stopping_ = false;
  // The current call.
  std::size_t n_ = 0;
  const std::function<void(std::size_t)>* f_ = nullptr;
  std::vector<std::exception_ptr> errors_;  // per share: its first exception
};

// min(hardware threads, n), at least 1: the default size of a pool for n independent tasks.
std::size_t DefaultThreadCount(std::size_t n);

}  // namespace rlpos
