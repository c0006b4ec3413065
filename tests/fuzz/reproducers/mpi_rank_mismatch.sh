#!/usr/bin/env bash
# Processes that read different models (--refine-mesh on one of them through an MPMD launch,
# another case file as a stale per-host copy would be, `check` on one and `run` on the other)
# hung or crashed (MPI_ERR_TRUNCATE). Clean outcome: exit 2 and one error line saying that the
# processes disagree, in every variant, well within the timeout.
source "$(dirname "$0")/lib.sh"
export OMPI_ALLOW_RUN_AS_ROOT=1 OMPI_ALLOW_RUN_AS_ROOT_CONFIRM=1 OMP_NUM_THREADS=1
c="$here/compress_through_bottom_everts.toml"
m="mpirun --allow-run-as-root --oversubscribe"
timeout 60 $m -np 1 "$T" run "$c" -o "$work/a" : -np 1 "$T" run "$c" -o "$work/a" --refine-mesh 1 >/dev/null 2>"$work/err"
expect_code "--refine-mesh on process 1" 2 $?
expect_error_line "--refine-mesh on process 1" "$work/err" "disagree"
timeout 60 $m -np 1 "$T" run "$c" -o "$work/b" : -np 1 "$T" run "$here/contact_coarse_slave_20pct_soft.toml" -o "$work/b" >/dev/null 2>"$work/err"
expect_code "another case on process 1" 2 $?
expect_error_line "another case on process 1" "$work/err" "disagree"
timeout 60 $m -np 1 "$T" check "$c" : -np 1 "$T" run "$c" -o "$work/c" >/dev/null 2>"$work/err"
expect_code "check on 0, run on 1" 2 $?
expect_error_line "check on 0, run on 1" "$work/err" "disagree"
finish
