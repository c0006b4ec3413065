#!/usr/bin/env bash
# SIGTERM to mpirun (what `kill` or a scheduler's job step does) during a run on 2 processes:
# in 3 of 6 trials summary.json stayed "running" (mpirun kills the processes before they reach
# their next poll). Clean outcome: summary.json "interrupted", written as soon as the signal
# arrives. The signal comes 2 s after the run is under way (its summary.json says "running"),
# however long the start takes (a sanitized build starts MPI slowly). EXAMPLE: a case that runs
# for more than those 2 s.
source "$(dirname "$0")/lib.sh"
E=${EXAMPLE:?path to a case that runs longer than 2 s once started, e.g. examples/indentation/indentation.toml}
export OMPI_ALLOW_RUN_AS_ROOT=1 OMPI_ALLOW_RUN_AS_ROOT_CONFIRM=1 OMP_NUM_THREADS=1
for trial in 1 2 3; do
  mpirun --allow-run-as-root --oversubscribe -np 2 "$T" run "$E" -o "$work/out$trial" >/dev/null 2>&1 &
  m=$!
  for _ in $(seq 600); do # up to 5 min for the start
    grep -q '"status": "running"' "$work/out$trial/summary.json" 2>/dev/null && break
    sleep 0.5
  done
  sleep 2
  kill -TERM $m
  wait $m
  rc=$?
  [ "$rc" -ne 0 ] || fail "trial $trial: mpirun exit code 0 after SIGTERM"
  expect_status "trial $trial (mpirun rc $rc)" "$work/out$trial/summary.json" interrupted
done
finish
