#!/usr/bin/env bash
# SPDX-License-Identifier: MIT
# The indentation benchmark (docs/performance.md): examples/indentation at several mesh sizes,
# one load step (the first second of the ramp: 0.015 mm of indentation, the contact zone
# forming), for each backend. One table row per run, from the run's summary.json: cells,
# backend, equations, Newton and linear iterations, wall time [s], peak memory [MB],
# factorization and solve time [s]; with REPEATS > 1 the row of the run with the median wall
# time.
#   run_indentation.sh [TRIFEM] ["N:NZ ..."] [BACKENDS] [REPEATS] [PROCESSES]
# defaults: build/bin/trifem, "8:4 16:4 24:6", "umfpack mumps mumps+reuse", 1, 1
# (mumps+reuse: single-precision factorizations; mumps+reuse+double: double-precision ones)
# PROCESSES > 1: each run through mpirun -np PROCESSES (the distributed MUMPS whatever the
# backend; memory: the sum of the processes' peaks)
# (python3 writes the meshes with examples/indentation/make_mesh.py)
set -euo pipefail
here=$(cd "$(dirname "$0")" && pwd)
example="$here/../../examples/indentation"
trifem=${1:-$here/../../build/bin/trifem}
sizes=${2:-"8:4 16:4 24:6"}
backends=${3:-"umfpack mumps mumps+reuse"}
repeats=${4:-1}
processes=${5:-1}
launch=()
if [ "$processes" -gt 1 ]; then
  export OMPI_ALLOW_RUN_AS_ROOT=1 OMPI_ALLOW_RUN_AS_ROOT_CONFIRM=1
  launch=(mpirun --oversubscribe -np "$processes")
fi
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT

value() { # value KEY FILE: the number after "KEY": in a summary.json
  sed -n "s/.*\"$1\": \([0-9.e+-]*\).*/\1/p" "$2" | head -1
}

# case FILE SOLVER REUSE PRECISION: the example on the mesh FILE, its first step only, no VTU
# output
write_case() {
  sed -e "s|^file = .*|file = \"$1\"|" -e '/^\[solver\]/,/^$/d' -e '/^# MUMPS reusing/,/^# 8 000/d' \
    "$example/indentation.toml" |
    awk '/^\[\[step\]\]/ && seen++ { exit } { print }' |
    sed -e 's/^end_time = 10.0/end_time = 1.0/'
  printf '\n[output]\nvtu = false\n\n[solver]\nlinear_solver = "%s"\nreuse_factorization = %s\n' "$2" "$3"
  [ "$3" = true ] && printf 'factorization_precision = "%s"\n' "$4"
  return 0
}

printf '| cells (N×N×NZ) | backend | equations | Newton its | linear its | wall [s] | peak memory [MB] | factorization [s] | solve [s] |\n'
printf '|---|---|---|---|---|---|---|---|---|\n'
for size in $sizes; do
  n=${size%:*}
  nz=${size#*:}
  python3 "$example/make_mesh.py" --cells "$n" --layers "$nz" -o "$work/mesh.msh" > /dev/null
  for backend in $backends; do
    precision=single # "mumps+reuse+double": double-precision factorizations
    solver=${backend%+double}
    [ "$backend" != "$solver" ] && precision=double
    solver=${solver%+reuse}
    reuse=false
    [ "$backend" != "$solver" ] && reuse=true
    write_case "$work/mesh.msh" "$solver" "$reuse" "$precision" > "$work/case.toml"
    for r in $(seq "$repeats"); do
      "${launch[@]}" "$trifem" -q run "$work/case.toml" -o "$work/out$r" > /dev/null 2>&1 || true
      echo "$(value total "$work/out$r/summary.json") $r"
    done | sort -g > "$work/times"
    median=$(sed -n "$(((repeats + 1) / 2))p" "$work/times" | cut -d' ' -f2)
    s="$work/out$median/summary.json"
    memory=$(value peak_memory_mb_total "$s")
    [ -n "$memory" ] || memory=$(value peak_memory_mb "$s")
    label=$backend
    [ "$processes" -gt 1 ] && label="$backend, $processes processes"
    printf '| %s×%s×%s | %s | %s | %s | %s | %.2f | %.0f | %.2f | %.2f |\n' "$n" "$n" "$nz" \
      "$label" "$(value equations "$s")" "$(value newton_iterations "$s")" \
      "$(value linear_iterations "$s")" "$(value total "$s")" \
      "$memory" "$(value factorization "$s")" "$(value solve "$s")"
  done
done
