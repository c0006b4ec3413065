// SPDX-License-Identifier: MIT
#include "trifem/tensor/kinematics.hpp"

namespace trifem::kinematics {

Mat3 cofactor(const Mat3& F) {
  Mat3 C;
  C(0, 0) = F(1, 1) * F(2, 2) - F(1, 2) * F(2, 1);
  C(0, 1) = F(1, 2) * F(2, 0) - F(1, 0) * F(2, 2);
  C(0, 2) = F(1, 0) * F(2, 1) - F(1, 1) * F(2, 0);
  C(1, 0) = F(0, 2) * F(2, 1) - F(0, 1) * F(2, 2);
  C(1, 1) = F(0, 0) * F(2, 2) - F(0, 2) * F(2, 0);
  C(1, 2) = F(0, 1) * F(2, 0) - F(0, 0) * F(2, 1);
  C(2, 0) = F(0, 1) * F(1, 2) - F(0, 2) * F(1, 1);
  C(2, 1) = F(0, 2) * F(1, 0) - F(0, 0) * F(1, 2);
  C(2, 2) = F(0, 0) * F(1, 1) - F(0, 1) * F(1, 0);
  return C;
}

} // namespace trifem::kinematics
