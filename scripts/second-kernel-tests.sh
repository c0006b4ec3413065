#!/usr/bin/env bash
# SPDX-License-Identifier: MIT
# Runs the verification and tangent tests with OpenBLAS forced onto kernels of another CPU
# (OPENBLAS_CORETYPE; Debian's OpenBLAS selects its kernels at run time) and on one thread; not
# their runs on 2 and 3 MPI processes (label parallel), which assert the answers of the
# one-process tests run here and take both cores each (164 of the 239 s of the pass).
# Usage: scripts/second-kernel-tests.sh [BUILD_DIR] [CORETYPE]
# The default core type, Prescott (SSE3), runs on every x86-64 CPU and differs from the kernels
# a current CPU selects by itself.
set -euo pipefail
build=${1:-build}
core=${2:-Prescott}
if [ "$(uname -m)" != "x86_64" ]; then
  echo "second-kernel-tests: OPENBLAS_CORETYPE applies to x86-64 only; skipped"
  exit 0
fi
echo "second-kernel-tests: verification and tangent labels (not parallel), OPENBLAS_CORETYPE=$core, 1 thread"
cd "$build"
OPENBLAS_CORETYPE=$core OPENBLAS_NUM_THREADS=1 OMP_NUM_THREADS=1 \
  ctest --output-on-failure -L 'verification|tangent' -LE parallel -j 2
