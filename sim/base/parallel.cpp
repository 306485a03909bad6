#include "sim/base/parallel.h"

#include <atomic>
#include <condition_variable>
#include <cstdlib>
#include <mutex>
#include <thread>
#include <vector>

namespace csm {
namespace {

thread_local bool tInsideTask = false;

// Workers sleep on a condition variable between loops; a loop hands out its task indices
// through an atomic counter, the caller taking its share, and waits until every index is done.
class ThreadPool {
 public:
  explicit ThreadPool(size_t workers) : workerCount_(workers) {}

  ~ThreadPool() {
    {
      std::lock_guard<std::mutex> lock(mutex_);
      stopping_ = true;
    }
    wake_.notify_all();
    for (std::thread& t : threads_) t.join();
  }

  size_t started() {
    std::lock_guard<std::mutex> lock(mutex_);
    return threads_.size();
  }

  void run(size_t count, const std::function<void(size_t)>& task) {
    std::unique_lock<std::mutex> owner(ownerMutex_, std::try_to_lock);
    if (tInsideTask || !owner.owns_lock() || workerCount_ == 0) {
      runInline(count, task);
      return;
    }
    {
      std::lock_guard<std::mutex> lock(mutex_);
      while (threads_.size() < workerCount_) threads_.emplace_back([this] { work(); });
      task_ = &task;
      count_ = count;
      next_.store(0);
      done_ = 0;
      ++generation_;
    }
    wake_.notify_all();
    const size_t mine = drain();
    std::unique_lock<std::mutex> lock(mutex_);
    done_ += mine;
    // Every worker out of the loop as well, so none reads the next loop's task half set up.
    finished_.wait(lock, [&] { return done_ == count_ && active_ == 0; });
    task_ = nullptr;
  }

 private:
  static void runInline(size_t count, const std::function<void(size_t)>& task) {
    const bool outer = tInsideTask;
    tInsideTask = true;
    for (size_t i = 0; i < count; ++i) task(i);
    tInsideTask = outer;
  }

  // Takes indices until none are left; returns how many this thread ran.
  size_t drain() {
    tInsideTask = true;
    size_t ran = 0;
    for (size_t i = next_.fetch_add(1); i < count_; i = next_.fetch_add(1)) {
      (*task_)(i);
      ++ran;
    }
    tInsideTask = false;
    return ran;
  }

  void work() {
    unsigned long seen = 0;
    for (;;) {
      {
        std::unique_lock<std::mutex> lock(mutex_);
        wake_.wait(lock, [&] { return stopping_ || generation_ != seen; });
        if (stopping_) return;
        seen = generation_;
        ++active_;
      }
      const size_t ran = drain();
      std::lock_guard<std::mutex> lock(mutex_);
      done_ += ran;
      --active_;
      if (done_ == count_ && active_ == 0) finished_.notify_one();
    }
  }

  const size_t workerCount_;
  std::mutex ownerMutex_;  // one loop at a time; others run inline
  std::mutex mutex_;
  std::condition_variable wake_, finished_;
  std::vector<std::thread> threads_;
  const std::function<void(size_t)>* task_ = nullptr;
  size_t count_ = 0, done_ = 0, active_ = 0;
  std::atomic<size_t> next_{0};
  unsigned long generation_ = 0;
  bool stopping_ = false;
};

ThreadPool& sharedPool() {
  static ThreadPool pool(coreCount() - 1);
  return pool;
}

}  // namespace

size_t coreCount() {
  static const size_t count = [] {
    size_t n = std::max(1u, std::thread::hardware_concurrency());
    // CSM_THREADS caps the threads (a shared machine; the fuzz targets run on one).
    if (const char* limit = std::getenv("CSM_THREADS")) {
      char* end = nullptr;
      const long asked = std::strtol(limit, &end, 10);
      if (end != limit && *end == '\0' && asked > 0) n = std::min(n, size_t(asked));
    }
    return n;
  }();
  return count;
}

void runOnPool(size_t count, const std::function<void(size_t)>& task) {
  sharedPool().run(count, task);
}

size_t poolThreadsStarted() {
  return sharedPool().started();
}

}  // namespace csm
