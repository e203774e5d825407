#include "raytrace/parallel.hpp"

#include <algorithm>
#include <atomic>
#include <exception>
#include <mutex>
#include <thread>
#include <vector>

namespace rt {

int defaultThreads() { return int(std::max(1u, std::thread::hardware_concurrency())); }

void parallelFor(int count, int threads, const std::function<void(int)>& task) {
  std::atomic<int> next{0};
  std::atomic<bool> failed{false};
  std::exception_ptr error;
  std::mutex errorMutex;
  const auto work = [&] {
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
  std::vector<std::thread> helpers;
  for (int t = 1; t < std::min(threads, count); ++t) helpers.emplace_back(work);
  work();
  for (std::thread& h : helpers) h.join();
  if (error) std::rethrow_exception(error);
}

void parallelForBlocks(size_t count, size_t block, int threads, const std::function<void(size_t, size_t)>& task) {
  parallelFor(int((count + block - 1) / block), threads,
              [&](int b) { task(size_t(b) * block, std::min(count, size_t(b + 1) * block)); });
}

}  // namespace rt
