#!/usr/bin/env bash
# Updates per second of the GPT-2 learner on 1 and 2 MPI ranks, one thread per
# rank, in one run (docs/distributed.md): the tiny GPT-2 (random weights, the
# shipped recipe's shape) and, given a folder, GPT-2 small (k = 1), each
# update 8 episodes on 8 slots as in the paper. Prints each run's per-update
# seconds (from the learner's "update N" lines, the first one, which builds
# the prompt caches, left out when there are more), updates/s, the speed-up
# and the parallel efficiency speed-up / ranks, then the machine's uptime.
# usage: bench/dist_scaling.sh SQUAWK [SMALL_DIR [SMALL_UPDATES]]   (from the source root)
set -eu
sq=${1:?usage: bench/dist_scaling.sh SQUAWK [SMALL_DIR [SMALL_UPDATES]]}
small=${2:-}
small_updates=${3:-1}
export OPENBLAS_NUM_THREADS=1 OMP_NUM_THREADS=1
tmp=$(mktemp -d)
trap 'rm -rf "$tmp"' EXIT

# seconds per update of one run: model flags..., then ranks, updates
per_update() {
  local ranks=$1 updates=$2; shift 2
  mpirun --oversubscribe --allow-run-as-root -np "$ranks" -x OPENBLAS_NUM_THREADS -x OMP_NUM_THREADS \
    "$sq" train scenarios/horizontal_cr.lua --policy gpt2 --precision fp32 "$@" --episodes $((updates * 8)) \
    --episodes-per-update 8 --envs 8 --eval-every $((updates * 8)) --eval-episodes 2 --out "$tmp/run$ranks" --force \
    2>/dev/null | awk -v n="$updates" '/^update [0-9]+:/ { u++; s = $NF; sub(/s$/, "", s); if (n == 1 || u > 1) { t += $(NF-1); k++ } }
      END { if (k) printf "%.3f\n", t / k }'
}

row() {
  local name=$1 updates=$2; shift 2
  local t1 t2
  t1=$(per_update 1 "$updates" "$@")
  t2=$(per_update 2 "$updates" "$@")
  awk -v name="$name" -v t1="$t1" -v t2="$t2" 'BEGIN {
    printf "%-28s %10.3f %10.3f %10.4f %10.4f %8.2f %9.0f %%\n", name, t1, t2, 1 / t1, 1 / t2, t1 / t2, 100 * t1 / t2 / 2 }'
}

printf "%-28s %10s %10s %10s %10s %8s %10s\n" "GPT-2, 8 episodes/update" "s/upd 1r" "s/upd 2r" "upd/s 1r" "upd/s 2r" \
  "speed-up" "efficiency"
row "tiny (k = 2)" 6
[ -n "$small" ] && row "small (k = 1)" "$small_updates" --model "$small"
echo "uptime: $(uptime)"
