#!/usr/bin/env bash
# SIGTERM to mpirun (what `kill` or a scheduler's job step does) during a run on 2 processes:
# in 3 of 6 trials summary.json stayed "running" (mpirun kills the processes before they reach
# their next poll). Clean outcome: summary.json "interrupted", written as soon as the signal
# arrives. EXAMPLE: a case that runs for more than the 8 s before the signal.
source "$(dirname "$0")/lib.sh"
E=${EXAMPLE:?path to a case that runs longer than 8 s, e.g. examples/indentation/indentation.toml}
export OMPI_ALLOW_RUN_AS_ROOT=1 OMPI_ALLOW_RUN_AS_ROOT_CONFIRM=1 OMP_NUM_THREADS=1
for trial in 1 2 3; do
  mpirun --allow-run-as-root --oversubscribe -np 2 "$T" run "$E" -o "$work/out$trial" >/dev/null 2>&1 &
  m=$!
  sleep 8
  kill -TERM $m
  wait $m
  rc=$?
  [ "$rc" -ne 0 ] || fail "trial $trial: mpirun exit code 0 after SIGTERM"
  expect_status "trial $trial (mpirun rc $rc)" "$work/out$trial/summary.json" interrupted
done
finish
