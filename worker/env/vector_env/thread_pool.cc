#include "worker/env/vector_env/thread_pool.h"

#include <algorithm>

namespace rlpos {

std::size_t DefaultThreadCount(std::size_t n) {
  const std::size_t hardware = std::max<std::size_t>(1, std::thread::hardware_concurrency());
  return std::max<std::size_t>(1, std::min(hardware, n));
}

ThreadPool::ThreadPool(std::size_t threads) {
  if (threads == 0)
    threads = std::max<std::size_t>(1, std::thread::hardware_concurrency());
  errors_.resize(threads);
  workers_.reserve(threads - 1);
  try {
    for (std::size_t share = 1; share < threads; ++share)
      workers_.emplace_back([this, share] { Work(share); });
  } catch (...) {  // a thread could not start: stop the ones that did
    {
      std::lock_guard<std::mutex> lock(mutex_);
      stopping_ = true;
    }
    wake_.notify_all();
    for (auto& t : workers_)
      t.join();
    throw;
  }
}

ThreadPool::~ThreadPool() {
  {
    std::lock_guard<std::mutex> lock(mutex_);
    stopping_ = true;
  }
  wake_.notify_all();
  for (auto& t : workers_)
    t.join();
}

void ThreadPool::RunShare(std::size_t share) {
  const std::size_t count = Size();
  const std::size_t begin = n_ * share / count;
  const std::size_t end = n_ * (share + 1) / count;
  std::exception_ptr& error = errors_[share];
  error = nullptr;
  for (std::size_t i = begin; i < end; ++i) {
    try {
      (*f_)(i);
    } catch (...) {
      if (!error)
        error = std::current_exception();
    }
  }
}

void ThreadPool::Work(std::size_t share) {
  std::size_t seen = 0;
  std::unique_lock<std::mutex> lock(mutex_);
  for (;;) {
    wake_.wait(lock, [&] { return stopping_ || generation_ != seen; });
    if (stopping_)
      return;
    seen = generation_;
    lock.unlock();
    RunShare(share);
    lock.lock();
    if (--pending_ == 0)
      done_.notify_one();
  }
}

void ThreadPool::ForEach(std::size_t n, const std::function<void(std::size_t)>& f) {
  if (n == 0)
    return;
  {
    std::lock_guard<std::mutex> lock(mutex_);
    n_ = n;
    f_ = &f;
    pending_ = workers_.size();
    ++generation_;
  }
  wake_.notify_all();
  RunShare(0);
  {
    std::unique_lock<std::mutex> lock(mutex_);
    done_.wait(lock, [&] { return pending_ == 0; });
    f_ = nullptr;
  }
  // Shares are index ranges in order: the first share with an error holds the lowest index.
  for (const std::exception_ptr& error : errors_) {
    if (error)
      std::rethrow_exception(error);
  }
}

}  // namespace rlpos
