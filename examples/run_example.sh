#!/usr/bin/env bash
# SPDX-License-Identifier: MIT
# Runs an example case (examples/NAME/NAME.toml -> results/NAME, then any other case of the
# folder, examples/NAME/CASE.toml -> results/NAME/CASE) and draws its plots.
# Usage: examples/run_example.sh NAME [BUILD_DIR]
set -euo pipefail
name=${1:?example name}
build=${2:-build}
root=$(cd "$(dirname "$0")/.." && pwd)
dir="$root/examples/$name"
out="$root/results/$name"
[ -f "$dir/$name.toml" ] || { echo "error: no example '$name' ($dir/$name.toml)" >&2; exit 2; }
"$root/$build/bin/trifem" run "$dir/$name.toml" -o "$out"
# the example's other cases (e.g. the run it is compared with) go to results/NAME/CASE/
for case in "$dir"/*.toml; do
  other=$(basename "$case" .toml)
  [ "$other" = "$name" ] || "$root/$build/bin/trifem" run "$case" -o "$out/$other"
done
if [ -f "$dir/plot.gp" ]; then
  if command -v gnuplot >/dev/null 2>&1; then
    (cd "$out" && gnuplot -c "$dir/plot.gp")
    echo "plots:   $(ls "$out"/*.png | tr '\n' ' ')"
  else
    echo "gnuplot not found: skipped the plots (scripts/install-deps.sh installs it)"
  fi
fi
echo "open $out/results.pvd in ParaView for the fields"
