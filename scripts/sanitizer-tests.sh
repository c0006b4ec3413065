#!/usr/bin/env bash
# SPDX-License-Identifier: MIT
# Builds trifem with AddressSanitizer and UndefinedBehaviorSanitizer in <build dir> (default
# build-asan) and runs the unit (with the CLI tests), tangent and, with --all, the other tests
# there. Any sanitizer report fails the test that triggered it. See docs/development.md.
set -euo pipefail
cd "$(dirname "$0")/.."
build=build-asan
labels='unit|tangent'
for arg in "$@"; do
  case "$arg" in
  --all) labels='' ;;
  *) build="$arg" ;;
  esac
done

cmake -S . -B "$build" -G Ninja -DCMAKE_BUILD_TYPE=RelWithDebInfo \
  -DTRIFEM_SANITIZE=address,undefined -DTRIFEM_BUILD_BENCHMARKS=OFF >/dev/null
cmake --build "$build" -j "$(nproc)"

# slow unwinding gives full stacks through libraries built without frame pointers, so the
# suppressions (OpenMPI's process-lifetime allocations) can match them
export ASAN_OPTIONS=fast_unwind_on_malloc=0:detect_stack_use_after_return=1:strict_string_checks=1
export LSAN_OPTIONS="suppressions=$PWD/scripts/lsan-suppressions.txt:print_suppressions=0"
export UBSAN_OPTIONS=print_stacktrace=1:halt_on_error=1
cd "$build"
if [ -n "$labels" ]; then
  ctest --output-on-failure -j "$(nproc)" --timeout 1500 -L "$labels"
else
  ctest --output-on-failure -j "$(nproc)" --timeout 1500
fi
