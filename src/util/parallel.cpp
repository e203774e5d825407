#include "raytrace/util/parallel.hpp"

#include <algorithm>
#include <atomic>
#include <chrono>
#include <condition_variable>
#include <cstdint>
#include <exception>
#include <mutex>
#include <system_error>
#include <thread>
#include <vector>

#include "raytrace/util/limits.hpp"

namespace rt {

namespace {

// Helper threads kept for the whole run. A render hands out work several times (a large file's parts, the
// hierarchy's levels, the tiles, the PNG's segments), and a thread started anew for each would first have to
// wait for its core. Between jobs a helper spins before it sleeps, so that the next job, as a rule a few
// milliseconds later, finds it running (docs/performance-notes.md, "Helper threads").
class Helpers {
 public:
  static Helpers& instance() {
    static Helpers helpers;
    return helpers;
  }

  // Starts helpers, without waiting for them to run, until there are `count`, or as many as memory
  // (kBytesPerThread) and the system (ulimit -u) allow; returns how many there are. Fewer threads give the
  // same results, later.
  int start(int count) {
    const std::lock_guard<std::mutex> lock(mutex_);
    try {
      while (int(threads_.size()) < count && availableMemory() >= kBytesPerThread) {
        threads_.emplace_back([this, i = int(threads_.size())] { loop(i); });
      }
    } catch (const std::system_error&) {
    }
    return int(threads_.size());
  }

  // Runs work() on the calling thread and on up to `count` helpers at once, and returns once every call has
  // returned; work() must not throw. False, with nothing run, when there is no helper to be had: another
  // caller's job holds them, or none could be started.
  bool run(int count, const std::function<void()>& work) {
    const std::unique_lock<std::mutex> job(busy_, std::try_to_lock);
    if (!job.owns_lock()) return false;
    count = std::min(count, start(count));
    if (count == 0) return false;
    {
      const std::lock_guard<std::mutex> lock(mutex_);
      work_ = &work;
      wanted_ = count;
      running_ = count;
      ++generation_;
    }
    wake_.notify_all();
    work();
    while (running_ > 0) std::this_thread::yield();
    return true;
  }

  ~Helpers() {
    {
      const std::lock_guard<std::mutex> lock(mutex_);
      stop_ = true;
    }
    wake_.notify_all();
    for (std::thread& t : threads_) t.join();
  }

 private:
  // How long an idle helper spins before it sleeps: longer than the serial steps between two jobs of a
  // render, short enough not to hold a core long after the last one (docs/performance-notes.md).
  static constexpr std::chrono::milliseconds kSpin{5};

  void loop(int index) {
    uint64_t seen = 0;
    for (;;) {
      const auto idle = std::chrono::steady_clock::now();
      while (generation_ == seen && !stop_ && std::chrono::steady_clock::now() - idle < kSpin) {
        std::this_thread::yield();
      }
      std::unique_lock<std::mutex> lock(mutex_);
      wake_.wait(lock, [&] { return generation_ != seen || stop_; });
      if (stop_) return;
      seen = generation_;
      const std::function<void()>* work = work_;
      const bool wanted = index < wanted_;
      lock.unlock();
      if (wanted) {
        (*work)();
        --running_;
      }
    }
  }

  std::mutex busy_;   // held by the caller whose job the helpers run
  std::mutex mutex_;  // guards what a job is and wakes sleeping helpers
  std::condition_variable wake_;
  std::atomic<uint64_t> generation_{0};  // the number of jobs given so far
  std::atomic<int> running_{0};          // helpers still in the current job
  std::atomic<bool> stop_{false};
  const std::function<void()>* work_ = nullptr;
  int wanted_ = 0;
  std::vector<std::thread> threads_;
};

}  // namespace

void startHelpers(int threads) {
  if (threads > 1) Helpers::instance().start(threads - 1);
}

int defaultThreads() { return int(std::max(1u, std::thread::hardware_concurrency())); }

void parallelFor(int count, int threads, const std::function<void(int)>& task) {
  std::atomic<int> next{0};
  std::atomic<bool> failed{false};
  std::exception_ptr error;
  std::mutex errorMutex;
  const std::function<void()> work = [&] {
    for (int i = next++; i < count && !failed; i = next++) {
      try {
        task(i);
      } catch (...) {
        const std::lock_guard<std::mutex> lock(errorMutex);
        if (!error) error = std::current_exception();
        failed = true;
      }
    }
  };
  // A task that itself asks for threads finds the helpers busy, and runs its own job on its thread.
  const int helpers = std::min(threads, count) - 1;
  if (helpers <= 0 || !Helpers::instance().run(helpers, work)) work();
  if (error) std::rethrow_exception(error);
}

void parallelForChunks(size_t count, size_t chunk, int threads, const std::function<void(size_t, size_t)>& task) {
  parallelFor(int((count + chunk - 1) / chunk), threads,
              [&](int c) { task(size_t(c) * chunk, std::min(count, size_t(c + 1) * chunk)); });
}

}  // namespace rt
