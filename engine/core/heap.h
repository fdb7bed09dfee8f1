// The process's heap policy, set once by an executable's main().
//
// GPT-2 fine-tuning allocates and frees activation buffers of 1-30 MB in every
// forward and backward pass. With glibc's defaults those blocks go back to the
// kernel when freed (trimmed from the heap top, or unmapped when they were
// mmapped), so the next pass takes a page fault per 4 KiB and zeroes every page
// again: the mirror-symmetric recipe's first 64 episodes spent 14 of 57 s in
// the kernel and a quarter of user time in memset (perf, 1 thread). Keeping the
// freed memory in the heap ran the same 64 episodes in 25 s with every
// parameter bit-identical (bench_policy's "mirror recipe" line measures both).
#pragma once

namespace squawk::heap {

// Keeps freed memory in the process heap for reuse: no trimming of the heap
// top, blocks up to 32 MiB (glibc's largest mmap threshold) served from the
// heap, 64 MiB extra on each heap growth. Resident memory then stays near its
// peak. A no-op where the C library is not glibc. Call before the work starts.
void keep_freed_memory();

}  // namespace squawk::heap
