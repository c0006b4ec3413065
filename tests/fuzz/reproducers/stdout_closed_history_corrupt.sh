#!/usr/bin/env bash
# With stdout and stderr closed (cron/daemon style), history.csv was opened as descriptor 1 and
# the progress log was written into it (exit 0). Clean outcome: exit 0, history.csv is a header
# and numeric rows only, the log is in run.log.
source "$(dirname "$0")/lib.sh"
"$T" run "$here/contact_coarse_slave_20pct_soft.toml" -o "$work/out" >&- 2>&-
expect_code "run" 0 $?
h="$work/out/history.csv"
[ "$(wc -l <"$h")" -ge 3 ] || fail "history.csv has fewer than 3 lines"
tail -n +2 "$h" | grep -qvE '^[-+0-9.eE,]+$' && fail "history.csv holds a line that is not numeric: $(tail -n +2 "$h" | grep -vE '^[-+0-9.eE,]+$' | head -1)"
grep -q "completed" "$work/out/run.log" || fail "run.log lacks the end of the run"
expect_status "run" "$work/out/summary.json" completed
finish
