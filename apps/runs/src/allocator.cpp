#include "volmesh/runs/allocator.hpp"

#ifdef __GLIBC__
#include <malloc.h>
#endif

namespace volmesh::cli {

namespace {

// Blocks up to kMmapThreshold come from the heap, which is trimmed only past
// kTrimThreshold of free memory and grows by kTopPad at a time.
constexpr int kMmapThreshold = 32 << 20;
constexpr int kTrimThreshold = 1 << 30;
constexpr int kTopPad = 256 << 20;

}  // namespace

void keep_freed_memory() {
#ifdef __GLIBC__
  mallopt(M_MMAP_THRESHOLD, kMmapThreshold);
  mallopt(M_TRIM_THRESHOLD, kTrimThreshold);
  mallopt(M_TOP_PAD, kTopPad);
#endif
}

}  // namespace volmesh::cli
