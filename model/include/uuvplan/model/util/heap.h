// The process's heap tuned for uuvplan's loads: long logs and many short simulations.
#pragma once

namespace uuvplan::model {

// glibc's heap, set for uuvplan's two loads (docs/performance.md, "Memory"):
// - blocks of 128 KiB and more (a long log's vectors) are mapped on their own and given back
//   to the system when freed. By default glibc raises this threshold to the size of the
//   largest such block freed (up to 32 MiB); the vectors that follow then come from the heap,
//   and the holes they leave stay resident: 3–4 MB more peak RSS on a 1,000,000-row log;
// - up to 1 MiB free at the heap's top is kept rather than returned at every free. Fixing
//   the first threshold also fixes this one at 128 KiB, and the planner's simulations, each
//   taking and freeing its buffers, then spent 9.7 s of system time in page faults besides
//   18.4 s of user time on BlueROV2's heave schedule (0.01 + 12.5 s with 1 MiB; 4 and 16 MiB
//   gave no more; 32 MiB cost 5.6 MB of peak RSS on the 1,000,000-row log, 1 MiB 0.3 MB).
// Called once at the start of main: the program's and the test programs'.
void SetHeapThresholds();

}  // namespace uuvplan::model
