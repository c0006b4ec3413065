#!/usr/bin/env bash
# SPDX-License-Identifier: MIT
# usage: TRIFEM=... bash expect.sh MODE FILE CODE [PATTERN...]
# Runs `trifem check FILE` (MODE check) or `trifem run FILE` (MODE run, also checked) and requires
# exit code CODE; for CODE != 0, one "error:" line naming FILE and holding every PATTERN, and no
# control characters on stderr; for CODE 0 with patterns, a "warning:" line holding them; a failed
# run keeps a summary that says so, and no run writes a non-finite number into history.csv.
source "$(dirname "$0")/lib.sh"
mode=$1 file=$here/$2 code=$3
shift 3
"$T" check "$file" >"$work/out" 2>"$work/err"
rc=$?
if [ "$mode" = check ]; then
  expect_code "check $(basename "$file")" "$code" "$rc"
  if [ "$code" -ne 0 ]; then
    expect_error_line "check" "$work/err" "$(basename "$file")" "$@"
  else
    for p in "$@"; do
      cat "$work/out" "$work/err" | grep '^warning' | grep -qF -- "$p" || fail "check: no warning says '$p'"
    done
  fi
else
  expect_code "check $(basename "$file")" 0 "$rc"
  "$T" run "$file" -o "$work/run" >"$work/out" 2>"$work/err"
  rc=$?
  expect_code "run $(basename "$file")" "$code" "$rc"
  if [ "$code" -ne 0 ]; then
    expect_error_line "run" "$work/err" "$(basename "$file")" "$@"
    [ "$code" -eq 3 ] && expect_status "run" "$work/run/summary.json" failed
  fi
  if [ -f "$work/run/history.csv" ] && grep -qiE 'nan|inf' "$work/run/history.csv"; then
    fail "run: non-finite values in history.csv"
  fi
fi
finish
