#!/usr/bin/env bash
# feb_second_boundary_section_ignored.feb splits its <Boundary> section in two; the second one
# (the Pull condition that stretches the cube 20 %) was ignored: exit 0 and a zero reaction.
# Clean outcome: both sections are read (as FEBio does): the top moves 0.2 mm and pulls back.
source "$(dirname "$0")/lib.sh"
"$T" -q run "$here/feb_second_boundary_section_ignored.feb" -o "$work/out" >/dev/null 2>"$work/err"
expect_code "run" 0 $?
last=$(tail -1 "$work/out/history.csv")
uz=$(echo "$last" | cut -d, -f10) rz=$(echo "$last" | cut -d, -f7)
awk -v u="$uz" 'BEGIN { exit !(u > 0.2 - 1e-9 && u < 0.2 + 1e-9) }' || fail "top displacement $uz, expected 0.2 mm"
awk -v r="$rz" 'BEGIN { exit !(r > 0.1) }' || fail "top reaction $rz N, expected the pull's (about 0.2 N)"
finish
