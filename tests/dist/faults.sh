#!/usr/bin/env bash
# Faults of a data-parallel job (docs/distributed.md): a rank killed with
# SIGKILL ends the whole job within seconds with a message naming it, and the
# last complete checkpoint stays intact; --resume continues on another number
# of ranks (1, then 2); Ctrl-C on mpirun stops every rank at the same batch,
# saves the checkpoint and says how to continue, as for one process.
# usage: tests/dist/faults.sh SQUAWK (from the source root)
# Exit 77 (skipped) when mpirun is absent or squawk was built without MPI.
set -u
sq=${1:?usage: tests/dist/faults.sh SQUAWK}
if ! command -v mpirun >/dev/null; then
  echo "skipped: mpirun is absent (tools/setup installs openmpi-bin and libopenmpi-dev)"
  exit 77
fi
export OPENBLAS_NUM_THREADS=1 OMP_NUM_THREADS=1
# Containers without ptrace rights (CI) cannot use Open MPI's cross-memory copy.
export OMPI_MCA_btl_vader_single_copy_mechanism=none
# Under AddressSanitizer the ranks run without the leak check: Open MPI's own
# allocations outlive MPI_Finalize in plugins it has unloaded by then, so they
# cannot be suppressed by name (single-process runs keep the check).
mpi_env=(env "ASAN_OPTIONS=${ASAN_OPTIONS:+$ASAN_OPTIONS:}detect_leaks=0")
mpi=("${mpi_env[@]}" mpirun --oversubscribe --allow-run-as-root -np 2 -x OPENBLAS_NUM_THREADS -x OMP_NUM_THREADS)
tmp=$(mktemp -d)
trap 'rm -rf "$tmp"' EXIT
pass=0 fails=0
ok() { echo "ok   $1"; pass=$((pass + 1)); }
bad() { echo "FAIL $1"; fails=$((fails + 1)); }
run=(train scenarios/horizontal_cr.lua --episodes 10000000 --episodes-per-update 16 --envs 8 --eval-every 256
     --eval-episodes 8 --out "$tmp/run")
# The episodes a checkpoint holds (its JSON header line).
episodes() { sed -n 2p "$1" | grep -o '"episodes":[0-9]*' | cut -d: -f2; }
# Waits up to $2 s for file $1 to exist.
wait_for() { for _ in $(seq $(($2 * 10))); do [ -e "$1" ] && return 0; sleep 0.1; done; return 1; }
# Waits up to 60 s for the run's checkpoint to hold more than $1 episodes
# (the run is then past its set-up, in its training loop).
wait_past() {
  for _ in $(seq 600); do [ "$(episodes "$tmp/run/checkpoint.ckpt")" -gt "$1" ] 2>/dev/null && return 0; sleep 0.1; done
  return 1
}

# 1. SIGKILL of rank 1.
"${mpi[@]}" "$sq" "${run[@]}" >"$tmp/kill.out" 2>&1 &
job=$!
if ! wait_for "$tmp/run/checkpoint.ckpt" 60; then bad "no checkpoint within 60 s"; cat "$tmp/kill.out"; exit 1; fi
sleep 1
if grep -q "built without MPI" "$tmp/kill.out"; then echo "skipped: $sq was built without MPI"; exit 77; fi
victim=$(pgrep -P "$job" -f "squawk train" | tail -1)
t0=$(date +%s%N)
kill -9 "$victim"
for _ in $(seq 100); do kill -0 "$job" 2>/dev/null || break; sleep 0.1; done
wait "$job"; rc=$?
took=$((($(date +%s%N) - t0) / 1000000))  # [ms]
if [ "$rc" -ne 0 ] && grep -q "exited on signal 9" "$tmp/kill.out" && [ "$took" -lt 10000 ]; then
  ok "a killed rank ends the job in $took ms (exit $rc): $(grep -m1 'exited on signal 9' "$tmp/kill.out")"
else
  bad "killed rank: exit $rc after $took ms"; cat "$tmp/kill.out"
fi
before=$(episodes "$tmp/run/checkpoint.ckpt")
[ -n "$before" ] && ok "the checkpoint is intact after the kill: $before episodes" || bad "checkpoint unreadable"

# 2. --resume on 1 process, interrupted by Ctrl-C.
"$sq" "${run[@]}" --resume >"$tmp/one.out" 2>&1 &
one=$!
wait_past "$before"
kill -INT "$one"
wait "$one"; rc=$?
mid=$(episodes "$tmp/run/checkpoint.ckpt")
if [ "$rc" -eq 130 ] && grep -q "(resumed)" "$tmp/one.out" && grep -q "^interrupted: " "$tmp/one.out" && [ "$mid" -gt "$before" ]; then
  ok "--resume on 1 process continues from $before to $mid episodes"
else
  bad "resume on 1 process: exit $rc, $before -> $mid episodes"; cat "$tmp/one.out"
fi

# 3. --resume on 2 ranks, Ctrl-C on mpirun.
"${mpi[@]}" "$sq" "${run[@]}" --resume >"$tmp/two.out" 2>&1 &
two=$!
wait_past "$mid"
kill -INT "$two"
wait "$two"; rc=$?
after=$(episodes "$tmp/run/checkpoint.ckpt")
if grep -q "data-parallel on 2 ranks" "$tmp/two.out" && grep -q "^interrupted: .*after $after episodes" "$tmp/two.out" &&
   [ "$after" -gt "$mid" ]; then
  ok "--resume on 2 ranks continues from $mid; Ctrl-C on mpirun saves $after episodes: $(grep '^interrupted' "$tmp/two.out")"
else
  bad "resume on 2 ranks / Ctrl-C: exit $rc, $mid -> $after episodes"; cat "$tmp/two.out"
fi

echo "dist faults: $pass passed, $fails failed"
[ "$fails" -eq 0 ]
