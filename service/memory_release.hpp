#pragma once

namespace bezier::service {

/// Memory given back to the system after a burst (glibc's allocator; elsewhere these do
/// nothing).
///
/// Why it is needed: a costly request (a path sweep that stores its candidate pairs, a
/// batch's answers) may allocate tens of megabytes on a compute thread. glibc keeps what
/// is freed in the thread's arena for reuse and returns only the free top of a heap,
/// and its mmap threshold grows with every large block freed, so after a burst of such
/// requests the process keeps its peak resident set for good: a pod sized for its steady
/// state is pushed towards its memory limit by one burst.
///
/// configure_allocator() (once, at start-up, before any thread): a fixed mmap threshold
/// of kMmapThreshold, so every block that large is its own mapping, returned to the
/// system when freed (a fixed threshold also stops glibc from raising it), and a trim
/// threshold of kTrimThreshold for the free top of a heap.
void configure_allocator();

/// After a request on a compute thread: when the arenas hold more than kTrimThreshold
/// of free memory, malloc_trim(0) returns their free pages to the system (in the middle
/// of a heap too). Its cost is a walk of the arenas, paid only after a request that left
/// that much free.
void release_free_memory();

}  // namespace bezier::service
