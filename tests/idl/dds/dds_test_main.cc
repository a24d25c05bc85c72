// The DDS tests' main: either the tests, or (with --rlpos-child-writer or --rlpos-child-reader)
// a second process of the liveliness tests, or (--rlpos-child-late-coordinator) that of the
// campaign client test. That mode is decided before any DDS call, and the child is started with
// fork + exec, so it never inherits the test process's Cyclone state or threads.
#include <gtest/gtest.h>

#include <cstring>

#include "tests/idl/dds/dds_test_support.h"

int main(int argc, char** argv) {
  if (argc >= 2 && std::strcmp(argv[1], rlpos::testing::kChildWriterFlag) == 0) {
    return rlpos::testing::RunChildWriter(argc, argv);
  }
  if (argc >= 2 && std::strcmp(argv[1], rlpos::testing::kChildReaderFlag) == 0) {
    return rlpos::testing::RunChildReader(argc, argv);
  }
  if (argc >= 2 && std::strcmp(argv[1], rlpos::testing::kChildLateCoordinatorFlag) == 0) {
    return rlpos::testing::RunChildLateCoordinator(argc, argv);
  }
  ::testing::InitGoogleTest(&argc, argv);
  return RUN_ALL_TESTS();
}
