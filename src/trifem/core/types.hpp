// SPDX-License-Identifier: MIT
// Scalar and index types shared by every module.
#pragma once

#include <Eigen/Core>
#include <Eigen/SparseCore>
#include <cstdint>

namespace trifem {

/// Real scalar type of all physical quantities.
using Real = double;
/// Index of nodes, cells and equations (32-bit; the UMFPACK backend converts to 64-bit).
using Index = int;

/// Dynamic real vector (solution and residual vectors).
using Vector = Eigen::VectorXd;
/// Column-major sparse matrix with int indices (UMFPACK `di` interface).
using SparseMatrix = Eigen::SparseMatrix<Real, Eigen::ColMajor, Index>;

} // namespace trifem
