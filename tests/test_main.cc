// The test programs' main: the heap set as the program sets it (model/util/heap.h), so that
// the tests run the library as `uuvplan` does, then GoogleTest.
#include <gtest/gtest.h>

#include "uuvplan/model/util/heap.h"

int main(int argc, char** argv) {
  uuvplan::model::SetHeapThresholds();
  ::testing::InitGoogleTest(&argc, argv);
  return RUN_ALL_TESTS();
}
