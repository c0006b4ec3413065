// SPDX-License-Identifier: MIT
// The main() of test executables that also run under mpirun (ctest cases "<name>.np<N>"):
// MPI is initialised first, so the models of the tests are assembled and solved in parts, as in
// `mpirun trifem run`; every process checks every assertion on its copy of the whole state.
#include "trifem/parallel/communicator.hpp"

#include <gtest/gtest.h>

int main(int argc, char** argv) {
  trifem::parallel::initialize(argc, argv);
  ::testing::InitGoogleTest(&argc, argv);
  return RUN_ALL_TESTS();
}
