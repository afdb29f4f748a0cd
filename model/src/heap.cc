#include "uuvplan/model/util/heap.h"

#include <malloc.h>

namespace uuvplan::model {

void SetHeapThresholds() {
  mallopt(M_MMAP_THRESHOLD, 128 * 1024);
  mallopt(M_TRIM_THRESHOLD, 1024 * 1024);
}

}  // namespace uuvplan::model
