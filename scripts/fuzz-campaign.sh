#!/usr/bin/env bash
# SPDX-License-Identifier: MIT
# A longer fuzz campaign than ctest's: the mutation fuzz test of the case files and Gmsh meshes
# (tests/fuzz/test_fuzz.cpp) with several seeds and SCALE times the mutants of each, then the
# reproducers of tests/fuzz/reproducers (ctest -L fuzz -R reproducer). Prints the counts it ran
# (recorded in docs/verification.md); mutants that break the contract are kept under
# <build>/tests/fuzz/work/failures/.
# usage: scripts/fuzz-campaign.sh [BUILD_DIR] [SCALE] [SEED...]   (default: build 4 1 2 3)
set -uo pipefail
cd "$(dirname "$0")/.."
build=${1:-build}
scale=${2:-4}
shift $(( $# > 2 ? 2 : $# ))
seeds=("$@")
[ ${#seeds[@]} -gt 0 ] || seeds=(1 2 3)
fuzz="$build/tests/fuzz/test_fuzz"
[ -x "$fuzz" ] || { echo "fuzz-campaign: build $fuzz first (cmake --build $build)" >&2; exit 1; }

status=0 checks=0 runs=0
for seed in "${seeds[@]}"; do
  log=$(mktemp)
  TRIFEM_FUZZ_SEED=$seed TRIFEM_FUZZ_SCALE=$scale "$fuzz" --gtest_brief=1 >"$log" 2>&1 || status=1
  c=$(awk '/^\[ fuzz \]/ { n += $(NF - 7) } END { print n + 0 }' "$log")
  r=$(awk '/^\[ fuzz \]/ { n += $(NF - 4) } END { print n + 0 }' "$log")
  failed=$(grep -c '^\[  FAILED  \]' "$log" || true)
  echo "seed $seed, scale $scale: $c check and $r run mutants, $failed failed test(s)"
  [ "$failed" -eq 0 ] || grep -A5 'Failure' "$log" | head -40
  checks=$((checks + c)) runs=$((runs + r))
  rm -f "$log"
done
(cd "$build" && ctest -L fuzz -R '^reproducer\.' --output-on-failure -j "$(nproc)") || status=1
echo "fuzz campaign: $checks check and $runs run mutants over ${#seeds[@]} seed(s); status $status"
exit $status
