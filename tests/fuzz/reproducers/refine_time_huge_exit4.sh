#!/usr/bin/env bash
# `--refine-time 2000` made dt underflow to 0: check passed and run ended with exit 4 'internal
# error: bad step settings'. Clean outcome: exit 2 naming the option, for check and run.
source "$(dirname "$0")/lib.sh"
c="$here/compress_through_bottom_everts.toml"
"$T" check "$c" --refine-time 2000 >/dev/null 2>"$work/err"
expect_code "check" 2 $?
expect_error_line "check" "$work/err" "compress_through_bottom_everts.toml" "--refine-time 2000"
"$T" -q run "$c" --refine-time 2000 -o "$work/out" >/dev/null 2>"$work/err"
expect_code "run" 2 $?
expect_error_line "run" "$work/err" "compress_through_bottom_everts.toml" "--refine-time 2000"
[ -e "$work/out" ] && fail "run: an invalid case created its output directory"
finish
