#!/usr/bin/env bash
# SPDX-License-Identifier: MIT
# Runs FEBio's test problems through trifem and prints a Markdown table: problem, outcome, and
# the first refusal or failure. The problems are the .feb files of a checkout of FEBio's public
# TestSuite (its Verify folder), which is not part of this repository.
#
#   scripts/febio-suite.sh <Verify folder> [prefix ...]
#
# Prefixes default to trifem's field (bp tr mp bi co ma fi ri rj dy ex mi). Environment:
# TRIFEM (the executable, default build/bin/trifem), TRIFEM_SUITE_TIMEOUT (seconds per problem,
# default 600). Outcomes: completes (exit 0), refused (2: invalid or unsupported input), fails
# (3: the analysis failed), timeout, or the exit code.
set -u
if [ $# -lt 1 ] || [ ! -d "$1" ]; then
  echo "usage: $0 <TestSuite Verify folder> [prefix ...]" >&2
  exit 2
fi
folder=$1
shift
prefixes=("$@")
[ ${#prefixes[@]} -eq 0 ] && prefixes=(bp tr mp bi co ma fi ri rj dy ex mi)
trifem=${TRIFEM:-build/bin/trifem}
limit=${TRIFEM_SUITE_TIMEOUT:-600}
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT

declare -A count
echo "| Problem | Outcome | First refusal or failure |"
echo "|---|---|---|"
for prefix in "${prefixes[@]}"; do
  for file in "$folder"/"$prefix"[0-9]*.feb; do
    [ -e "$file" ] || continue
    name=$(basename "$file" .feb)
    timeout "$limit" "$trifem" -q run "$file" -o "$work/$name" > "$work/$name.log" 2>&1
    code=$?
    case $code in
      0) outcome=completes ;;
      2) outcome=refused ;;
      3) outcome=fails ;;
      124) outcome=timeout ;;
      *) outcome="exit $code" ;;
    esac
    count[$outcome]=$(( ${count[$outcome]:-0} + 1 ))
    reason=""
    [ "$code" -ne 0 ] && reason=$(grep -m1 -i "error" "$work/$name.log" | cut -c1-200 | tr '|' '/')
    echo "| $name | $outcome | ${reason#"$folder"/} |"
    rm -rf "${work:?}/$name"
  done
done
echo
for outcome in "${!count[@]}"; do
  echo "$outcome: ${count[$outcome]}"
done | sort
