#include "engine/allocator_tuning.h"

#include <malloc.h>

namespace hdprior {

void keepFreedMemoryMapped() {
  mallopt(M_MMAP_THRESHOLD, 64 << 20);  // blocks below 64 MiB come from the heap, not mmap
  mallopt(M_TRIM_THRESHOLD, 512 << 20);  // and freed heap memory stays mapped up to 512 MiB
  mallopt(M_TOP_PAD, 16 << 20);
}

}  // namespace hdprior
