#!/usr/bin/env bash
# `--refine-mesh 6` on the command line skipped the model-size check that `[mesh] refine = 6` in
# the file gets, and built the 1e9-cell model until memory ran out. Clean outcome: exit 2 with the
# model-size message for both (memory capped at 4 GiB so that a regression cannot take the machine).
source "$(dirname "$0")/lib.sh"
sed 's/^divisions = \[2, 2, 2\]/divisions = [16, 16, 16]/' "$here/compress_through_bottom_everts.toml" >"$work/box16.toml"
{ printf '[mesh]\nrefine = 6\n'; cat "$work/box16.toml"; } >"$work/box16_refine6.toml"
"$T" check "$work/box16_refine6.toml" >/dev/null 2>"$work/err"
expect_code "[mesh] refine = 6" 2 $?
expect_error_line "[mesh] refine = 6" "$work/err" "box16_refine6.toml" "equations"
# (a sanitized build reserves terabytes of address space: it runs without the cap)
cap="ulimit -v 4194304"
(eval "$cap"; "$T" --version >/dev/null 2>&1) || cap=":"
(eval "$cap"; "$T" check "$work/box16.toml" --refine-mesh 6 >/dev/null 2>"$work/err")
expect_code "--refine-mesh 6" 2 $?
expect_error_line "--refine-mesh 6" "$work/err" "box16.toml" "equations" "--refine-mesh 6"
finish
