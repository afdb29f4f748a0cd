#include "support/live_heap.h"

#include <malloc.h>

#include <atomic>
#include <cstdlib>
#include <new>

namespace {
std::atomic<bool> g_counting{false};
std::atomic<long long> g_live{0}, g_peak{0};
void Count(void* p, int sign) {
  if (!p || !g_counting.load(std::memory_order_relaxed)) return;
  const long long now = g_live += sign * static_cast<long long>(malloc_usable_size(p));
  long long peak = g_peak.load();
  while (now > peak && !g_peak.compare_exchange_weak(peak, now)) {
  }
}
}  // namespace

void* operator new(std::size_t n) {
  void* p = std::malloc(n ? n : 1);
  if (!p) throw std::bad_alloc();
  Count(p, +1);
  return p;
}
void operator delete(void* p) noexcept {
  Count(p, -1);
  std::free(p);
}
void operator delete(void* p, std::size_t) noexcept { operator delete(p); }

namespace uuvplan::testing {

void StartCountingHeap() {
  g_live = 0;
  g_peak = 0;
  g_counting = true;
}

long long StopCountingHeap() {
  g_counting = false;
  return g_peak.load();
}

}  // namespace uuvplan::testing
