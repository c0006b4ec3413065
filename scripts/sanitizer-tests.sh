#!/usr/bin/env bash
# SPDX-License-Identifier: MIT
# Builds trifem with AddressSanitizer and UndefinedBehaviorSanitizer in <build dir> (default
# build-asan) and runs the unit, tangent and fuzz (with the reproducers) labels there, the
# library and the trifem command instrumented (CI's third part); with --all, every test, the
# tests' own code instrumented too (the verification, example and CLI tests are then built as
# well). Any sanitizer report fails the test that triggered it. See docs/development.md.
set -euo pipefail
cd "$(dirname "$0")/.."
build=build-asan
labels='unit|tangent|fuzz'
all=OFF
# UndefinedBehaviorSanitizer's checks of every memory access that AddressSanitizer covers
# (null, object-size, pointer-overflow) or x86-64 tolerates (alignment) and of dynamic types
# (vptr): leaving them out cuts a unity file's compile time by 37 % (132 to 83 s); --all keeps them
skip=alignment,null,object-size,pointer-overflow,vptr
for arg in "$@"; do
  case "$arg" in
  --all) labels='' all=ON skip='' ;;
  *) build="$arg" ;;
  esac
done

# -O2: Eigen's code needs inlining (at -O1 a run is 35 times slower than Release, against a
# few times at -O2); -g1 (line tables) gives the reports' stacks at a fraction of -g's cost
cmake -S . -B "$build" -G Ninja -DCMAKE_BUILD_TYPE=RelWithDebInfo \
  -DCMAKE_CXX_FLAGS_RELWITHDEBINFO="-O2 -g1 -DNDEBUG" \
  -DTRIFEM_SANITIZE=address,undefined -DTRIFEM_SANITIZE_SKIP="$skip" \
  -DTRIFEM_BUILD_BENCHMARKS=OFF -DCMAKE_UNITY_BUILD=ON \
  -DTRIFEM_BUILD_VERIFICATION_TESTS=$all -DTRIFEM_BUILD_CLI_TESTS=$all \
  -DTRIFEM_SANITIZE_TESTS=$all >/dev/null
cmake --build "$build" -j "$(nproc)"

# slow unwinding gives full stacks through libraries built without frame pointers, so the
# suppressions (OpenMPI's process-lifetime allocations) can match them
export ASAN_OPTIONS=fast_unwind_on_malloc=0:detect_stack_use_after_return=1:strict_string_checks=1
export LSAN_OPTIONS="suppressions=$PWD/scripts/lsan-suppressions.txt:print_suppressions=0"
export UBSAN_OPTIONS=print_stacktrace=1:halt_on_error=1
export TRIFEM_FUZZ_TIMEOUT_S=120 # a sanitized check or one-step run takes seconds, not 0.1 s
cd "$build"
if [ -n "$labels" ]; then
  ctest --output-on-failure -j "$(nproc)" --timeout 1500 -L "$labels"
else
  ctest --output-on-failure -j "$(nproc)" --timeout 1500
fi
