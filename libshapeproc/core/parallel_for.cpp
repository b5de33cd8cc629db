#include "libshapeproc/core/parallel_for.hpp"

#include <algorithm>
#include <atomic>
#include <exception>
#include <mutex>
#include <thread>
#include <vector>

namespace shapeproc::core {

int loop_threads(int threads, long long count) {
  const int cores = static_cast<int>(std::max(1u, std::thread::hardware_concurrency()));
  const long long wanted = threads > 0 ? threads : cores;
  return static_cast<int>(std::max<long long>(1, std::min(wanted, count)));
}

void parallel_for(long long count, int threads, const std::function<void(long long)>& f) {
  if (count <= 0) return;
  const int n = loop_threads(threads, count);
  if (n == 1) {
    for (long long i = 0; i < count; ++i) f(i);
    return;
  }
  std::atomic<long long> next{0};
  std::mutex mutex;
  long long failed_at = count;
  std::exception_ptr failure;
  auto worker = [&] {
    for (long long i = next++; i < count; i = next++) {
      try {
        f(i);
      } catch (...) {
        const std::lock_guard<std::mutex> lock(mutex);
        if (i < failed_at) {
          failed_at = i;
          failure = std::current_exception();
        }
      }
    }
  };
  std::vector<std::thread> pool;
  for (int t = 1; t < n; ++t) pool.emplace_back(worker);
  worker();
  for (std::thread& t : pool) t.join();
  if (failure) std::rethrow_exception(failure);
}

}  // namespace shapeproc::core
