#!/usr/bin/env bash
# A run whose stdout reader goes away (`trifem run ... | head -c 1`, a dead tee or logger) died of
# SIGPIPE at the next progress line: rc 141, summary.json left "running". Clean outcome: the run
# goes on without its console (exit 0), its log in run.log, summary "completed".
source "$(dirname "$0")/lib.sh"
"$T" run "$here/contact_coarse_slave_20pct_soft.toml" -o "$work/out" | head -c 1 >/dev/null
expect_code "run" 0 "${PIPESTATUS[0]}"
expect_status "run" "$work/out/summary.json" completed
[ "$(wc -l <"$work/out/history.csv")" -ge 3 ] || fail "history.csv lacks the steps"
finish
