#include "support/live_heap.h"

#include <malloc.h>

#include <atomic>
#include <cerrno>
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

#if defined(__has_feature)
#if __has_feature(address_sanitizer) || __has_feature(thread_sanitizer) || \
    __has_feature(memory_sanitizer)
#define UUVPLAN_SANITIZED 1
#endif
#endif
#if defined(__SANITIZE_ADDRESS__) || defined(__SANITIZE_THREAD__)
#define UUVPLAN_SANITIZED 1
#endif

#ifndef UUVPLAN_SANITIZED  // a sanitizer replaces the allocator itself: nothing counted there
// glibc's allocator under its exported internal names: the program's malloc family below
// counts and forwards to it (Eigen allocates with std::malloc, not operator new: a count of
// operator new alone missed every matrix and vector of Eigen).
extern "C" {
void* __libc_malloc(std::size_t n);
void* __libc_calloc(std::size_t n, std::size_t size);
void* __libc_realloc(void* p, std::size_t n);
void* __libc_memalign(std::size_t alignment, std::size_t n);
void __libc_free(void* p);

void* malloc(std::size_t n) noexcept {
  void* p = __libc_malloc(n);
  Count(p, +1);
  return p;
}
void* calloc(std::size_t n, std::size_t size) noexcept {
  void* p = __libc_calloc(n, size);
  Count(p, +1);
  return p;
}
void* realloc(void* old, std::size_t n) noexcept {
  Count(old, -1);
  void* p = __libc_realloc(old, n);
  // realloc(old, 0) frees; a failed realloc leaves the old block alive.
  Count(p ? p : (n ? old : nullptr), +1);
  return p;
}
void* memalign(std::size_t alignment, std::size_t n) noexcept {
  void* p = __libc_memalign(alignment, n);
  Count(p, +1);
  return p;
}
void* aligned_alloc(std::size_t alignment, std::size_t n) noexcept {
  return memalign(alignment, n);
}
int posix_memalign(void** out, std::size_t alignment, std::size_t n) noexcept {
  void* p = memalign(alignment, n);
  if (!p && n) return ENOMEM;
  *out = p;
  return 0;
}
void free(void* p) noexcept {
  Count(p, -1);
  __libc_free(p);
}
}  // extern "C"

void* operator new(std::size_t n) {
  void* p = std::malloc(n ? n : 1);  // counted by malloc
  if (!p) throw std::bad_alloc();
  return p;
}
void operator delete(void* p) noexcept { std::free(p); }
void operator delete(void* p, std::size_t) noexcept { operator delete(p); }
#endif  // UUVPLAN_SANITIZED

namespace uuvplan::testing {

bool HeapCountingAvailable() {
#ifdef UUVPLAN_SANITIZED
  return false;
#else
  return true;
#endif
}

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
