#include "service/memory_release.hpp"

#include <cstddef>

#if defined(__GLIBC__)
#include <malloc.h>
#endif

namespace bezier::service {

namespace {

// Blocks of 256 KiB and more are mappings of their own: a request's large vectors (its
// candidate pairs, its answer) go back to the system as soon as they are freed. Smaller
// blocks stay in the arenas, where reusing them is cheap.
constexpr int kMmapThreshold = 256 * 1024;
// Free memory an arena may keep for reuse before it is returned.
constexpr std::size_t kTrimThreshold = std::size_t{4} << 20;

}  // namespace

void configure_allocator() {
#if defined(__GLIBC__)
  mallopt(M_MMAP_THRESHOLD, kMmapThreshold);
  mallopt(M_TRIM_THRESHOLD, static_cast<int>(kTrimThreshold));
#endif
}

void release_free_memory() {
#if defined(__GLIBC__) && (__GLIBC__ > 2 || (__GLIBC__ == 2 && __GLIBC_MINOR__ >= 33))
  if (mallinfo2().fordblks > kTrimThreshold) malloc_trim(0);
#endif
}

}  // namespace bezier::service
