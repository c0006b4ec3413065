#!/usr/bin/env bash
# A 100 kB case file with one dotted key 50 000 levels deep (a.a.a... = 1) made `trifem check` die
# with SIGSEGV (rc 139). Clean outcome: exit 2 with one error line naming the file.
source "$(dirname "$0")/lib.sh"
{ printf 'a'; printf '.a%.0s' $(seq 50000); printf ' = 1\n'; } >"$work/deep.toml"
"$T" check "$work/deep.toml" >/dev/null 2>"$work/err"
expect_code "check" 2 $?
expect_error_line "check" "$work/err" "deep.toml"
finish
