// The live heap of the test program while counting: the blocks most of the program's malloc
// family (and so operator new, Eigen's matrices, …) hands out, by malloc_usable_size, and its
// peak since counting started (for tests that bound a computation's memory by what it is
// given, not by time). Linking this file replaces the program's malloc, calloc, realloc,
// memalign, aligned_alloc, posix_memalign, free and global operator new/delete (glibc: it
// forwards to __libc_malloc and friends; valloc and pvalloc are not counted). Not in a
// sanitizer build, which replaces the allocator itself: nothing is counted there.
#pragma once

namespace uuvplan::testing {

/// False in a sanitizer build (tests of memory skip).
bool HeapCountingAvailable();
/// Starts counting from zero (live and peak).
void StartCountingHeap();
/// Stops counting; returns the peak live heap (bytes) since StartCountingHeap.
long long StopCountingHeap();

}  // namespace uuvplan::testing
