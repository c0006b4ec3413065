#!/usr/bin/env bash
# run.log could not be opened (a directory of that name in the output directory): exit 4
# 'internal error', summary.json left "running". Clean outcome: exit 3 with one error line naming
# run.log, summary "failed".
source "$(dirname "$0")/lib.sh"
mkdir -p "$work/out/run.log/keep"
"$T" run "$here/contact_coarse_slave_20pct_soft.toml" -o "$work/out" >/dev/null 2>"$work/err"
expect_code "run" 3 $?
expect_error_line "run" "$work/err" "run.log"
expect_status "run" "$work/out/summary.json" failed
finish
