// Runs independent jobs on a few threads. Each job writes only its own slot of the caller's
// output, so the result does not depend on the number of threads or their timing. Shared by
// identification, Monte Carlo and diagnosis (ident) and the loop's candidate evaluation
// (planner): one pattern for every `--threads` option.
#pragma once

#include <algorithm>
#include <atomic>
#include <cstddef>
#include <exception>
#include <thread>
#include <vector>

namespace uuvplan::model {

/// The number of threads `threads` asks for (0: one per hardware core).
inline std::size_t Workers(int threads) {
  return threads > 0 ? static_cast<std::size_t>(threads)
                     : std::max(1u, std::thread::hardware_concurrency());
}

namespace internal {
/// True on a thread while it runs a job of a ParallelFor that uses several threads.
inline thread_local bool in_parallel_job = false;
}  // namespace internal

/// Calls job(i) for every i in [0, n) on up to `threads` threads (0: one per hardware core).
/// Inside a job of an outer ParallelFor that already uses several threads it runs its jobs in
/// turn: one level of threads, the outermost (the schedule's DOFs, the verdict's box points, the
/// loop's candidates), not threads × threads on the same cores.
template <typename Job>
void ParallelFor(std::size_t n, int threads, const Job& job) {
  const std::size_t workers = internal::in_parallel_job ? 1 : std::min(Workers(threads), n);
  if (workers <= 1) {
    for (std::size_t i = 0; i < n; ++i) job(i);
    return;
  }
  std::atomic<std::size_t> next{0};
  std::vector<std::exception_ptr> errors(n);  // rethrown in job order, as a serial loop would
  auto work = [&] {
    internal::in_parallel_job = true;
    for (std::size_t i = next++; i < n; i = next++) {
      try {
        job(i);
      } catch (...) {
        errors[i] = std::current_exception();
      }
    }
    internal::in_parallel_job = false;
  };
  std::vector<std::thread> pool;
  for (std::size_t w = 1; w < workers; ++w) pool.emplace_back(work);
  work();
  for (std::thread& t : pool) t.join();
  for (const std::exception_ptr& e : errors) {
    if (e) std::rethrow_exception(e);
  }
}

}  // namespace uuvplan::model
