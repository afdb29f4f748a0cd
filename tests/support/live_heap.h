// The live heap of the test program while counting: every block the program's operator
// new/delete see, by malloc_usable_size, and its peak since counting started (for tests that
// bound a computation's memory by what it is given, not by time). Linking this file replaces
// the program's global operator new/delete.
#pragma once

namespace uuvplan::testing {

/// Starts counting from zero (live and peak).
void StartCountingHeap();
/// Stops counting; returns the peak live heap (bytes) since StartCountingHeap.
long long StopCountingHeap();

}  // namespace uuvplan::testing
