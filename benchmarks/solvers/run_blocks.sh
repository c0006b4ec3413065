#!/usr/bin/env bash
# SPDX-License-Identifier: MIT
# Runs the 3-D triphasic block benchmark for each size and backend and prints one table row
# per run: cells, backend, equations, Newton and linear (Krylov) iterations, wall time [s],
# peak memory [MB],
# factorization and solve time [s], all from the run's summary.json.
#   run_blocks.sh [TRIFEM] [SIZES] [BACKENDS]
# defaults: build/bin/trifem, "6 10 14", "umfpack mumps mumps+reuse krylov"
# (mumps+reuse: single-precision factorizations; mumps+reuse+double: double-precision ones)
set -euo pipefail
here=$(cd "$(dirname "$0")" && pwd)
trifem=${1:-$here/../../build/bin/trifem}
sizes=${2:-"6 10 14"}
backends=${3:-"umfpack mumps mumps+reuse krylov"}
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT

value() { # value KEY FILE: the number after "KEY": in a summary.json
  sed -n "s/.*\"$1\": \([0-9.e+-]*\).*/\1/p" "$2" | head -1
}

printf '| cells | backend | equations | Newton its | linear its | wall [s] | peak memory [MB] | factorization [s] | solve [s] |\n'
printf '|---|---|---|---|---|---|---|---|---|\n'
for n in $sizes; do
  for backend in $backends; do
    precision=single
    solver=${backend%+double}
    [ "$backend" != "$solver" ] && precision=double
    solver=${solver%+reuse}
    reuse=false
    [ "$backend" != "$solver" ] && reuse=true
    bash "$here/block_case.sh" "$n" "$solver" "" "$reuse" lu donnan 2.5 1 "$precision" \
      > "$work/case.toml"
    "$trifem" -q run "$work/case.toml" -o "$work/out" > /dev/null 2>&1 || true
    s="$work/out/summary.json"
    printf '| %s³ | %s | %s | %s | %s | %.2f | %.0f | %.2f | %.2f |\n' "$n" "$backend" \
      "$(value equations "$s")" "$(value newton_iterations "$s")" \
      "$(value linear_iterations "$s")" "$(value total "$s")" \
      "$(value peak_memory_mb "$s")" "$(value factorization "$s")" "$(value solve "$s")"
  done
done
