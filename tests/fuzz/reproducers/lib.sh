# SPDX-License-Identifier: MIT
# Shared checks of the reproducer scripts: each script runs trifem ($TRIFEM) on an input that once
# broke it and fails (exit 1, with the reason) unless the documented clean outcome holds.
set -u
T=${TRIFEM:?set TRIFEM to the trifem executable}
here=$(cd "$(dirname "$0")" && pwd)
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
failures=0

fail() {
  echo "FAIL: $*" >&2
  failures=$((failures + 1))
}

# expect_code WHAT EXPECTED ACTUAL
expect_code() {
  [ "$3" -eq "$2" ] || fail "$1: exit code $3, expected $2"
}

# expect_error_line WHAT STDERR_FILE PATTERN...: exactly one line starting "error:", holding every
# pattern (grep -F), and no control characters but newlines in the whole of stderr
expect_error_line() {
  local what=$1 err=$2
  shift 2
  local n
  n=$(grep -c '^error' "$err" || true)
  [ "$n" -eq 1 ] || fail "$what: $n error lines in stderr, expected 1: $(head -c 600 "$err")"
  for p in "$@"; do
    grep '^error' "$err" | grep -qF -- "$p" || fail "$what: the error line does not say '$p': $(grep '^error' "$err" | head -c 600)"
  done
  if LC_ALL=C grep -q "$(printf '[\001-\010\013-\037\177]')" "$err"; then
    fail "$what: control characters in stderr"
  fi
}

# expect_status WHAT SUMMARY STATUS: summary.json says "status": STATUS
expect_status() {
  grep -q "\"status\": \"$3\"" "$2" 2>/dev/null || fail "$1: summary.json status is not $3: $(grep '"status"' "$2" 2>/dev/null)"
}

finish() {
  [ "$failures" -eq 0 ] && echo "clean outcome" && exit 0
  exit 1
}
