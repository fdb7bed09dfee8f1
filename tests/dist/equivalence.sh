#!/usr/bin/env bash
# Same science at any number of ranks (docs/distributed.md): the same seed and
# batch trained on 1 process and on 2 MPI ranks give the same parameters
# within float round-off and the same training and validation figures, for
# the MLP (improved, ppo with shuffled minibatches, vine) and the tiny GPT-2;
# a 2-rank job repeats bit for bit, one process gives the same bits with 3 or
# 8 slots; `squawk eval` gives the same figures on 1 and 2 ranks.
# usage: tests/dist/equivalence.sh SQUAWK (from the source root)
# Exit 77 (skipped) when mpirun is absent or squawk was built without MPI.
set -u
sq=${1:?usage: tests/dist/equivalence.sh SQUAWK}
if ! command -v mpirun >/dev/null; then
  echo "skipped: mpirun is absent (tools/setup installs openmpi-bin and libopenmpi-dev)"
  exit 77
fi
export OPENBLAS_NUM_THREADS=1 OMP_NUM_THREADS=1  # one core per rank on a small machine
# Containers without ptrace rights (CI) cannot use Open MPI's cross-memory copy.
export OMPI_MCA_btl_vader_single_copy_mechanism=none
# Under AddressSanitizer the ranks run without the leak check: Open MPI's own
# allocations outlive MPI_Finalize in plugins it has unloaded by then, so they
# cannot be suppressed by name (single-process runs keep the check).
mpi_env=(env "ASAN_OPTIONS=${ASAN_OPTIONS:+$ASAN_OPTIONS:}detect_leaks=0")
mpi=("${mpi_env[@]}" mpirun --oversubscribe --allow-run-as-root -np 2 -x OPENBLAS_NUM_THREADS -x OMP_NUM_THREADS)
tmp=$(mktemp -d)
trap 'rm -rf "$tmp"' EXIT
here=$(dirname "$0")
pass=0 fails=0
ok() { echo "ok   $1"; pass=$((pass + 1)); }
bad() { echo "FAIL $1"; fails=$((fails + 1)); }

probe=$("${mpi[@]}" "$sq" train scenarios/horizontal_cr.lua --episodes 2 --episodes-per-update 2 --eval-every 2 \
        --eval-episodes 2 --out "$tmp/probe" 2>&1)
case $probe in
  *"built without MPI"*) echo "skipped: $sq was built without MPI"; exit 77 ;;
  *"data-parallel on 2 ranks"*) ;;
  *) echo "FAIL 2-rank probe run:"; echo "$probe"; exit 1 ;;
esac

# log.csv without its wall-clock column (3rd).
# The log's figures (every column but wall_s) agree: equal, or within one unit of the fourth decimal the log
# prints (a value that float round-off moves across a rounding boundary prints one unit apart).
same_figures() {
  python3 - "$1" "$2" <<'PY'
import csv, sys
a, b = (list(csv.reader(open(p))) for p in sys.argv[1:3])
def close(x, y):
    try:
        return abs(float(x) - float(y)) <= 1.5e-4
    except ValueError:
        return x == y
ok = len(a) == len(b) and all(len(r) == len(s) and all(close(x, y) for k, (x, y) in enumerate(zip(r, s))
                                                      if a[0][k] != "wall_s") for r, s in zip(a, b))
sys.exit(0 if ok else 1)
PY
}

# name, then the train arguments
same() {
  local name=$1; shift
  "$sq" train "$@" --quiet --out "$tmp/$name.1" >"$tmp/$name.1.out" 2>&1 || { bad "$name: 1 process"; cat "$tmp/$name.1.out"; return; }
  "${mpi[@]}" "$sq" train "$@" --quiet --out "$tmp/$name.2" >"$tmp/$name.2.out" 2>&1 ||
    { bad "$name: 2 ranks"; cat "$tmp/$name.2.out"; return; }
  local d
  if d=$(python3 "$here/compare_checkpoints.py" "$tmp/$name.1/checkpoint.ckpt" "$tmp/$name.2/checkpoint.ckpt"); then
    ok "$name: 1 process and 2 ranks: $d"
  else
    bad "$name: parameters differ: $d"
  fi
  if same_figures "$tmp/$name.1/log.csv" "$tmp/$name.2/log.csv"; then
    ok "$name: the same log figures: $(tail -1 "$tmp/$name.2/log.csv")"
  else
    bad "$name: log figures differ"; cat "$tmp/$name.1/log.csv" "$tmp/$name.2/log.csv"
  fi
}

mlp=(scenarios/horizontal_cr.lua --episodes 48 --episodes-per-update 16 --envs 8 --eval-every 48 --eval-episodes 16)
same mlp_improved "${mlp[@]}"
same mlp_ppo "${mlp[@]}" --estimator ppo --epochs 2 --minibatches 3
same mlp_vine "${mlp[@]}" --estimator vine --epochs 2
same gpt2_tiny scenarios/horizontal_cr.lua --policy gpt2 --precision fp32 --episodes 4 --episodes-per-update 2 \
  --envs 2 --eval-every 4 --eval-episodes 2

# 3 ranks, 2 episodes per update: rank 0 plays none and must still follow
# every step (the GPT-2 policy drops its prefix cache when its parameters change).
g3=(train scenarios/horizontal_cr.lua --policy gpt2 --precision fp32 --episodes 6 --episodes-per-update 2 --envs 2
    --eval-every 6 --eval-episodes 2 --estimator ppo --epochs 2 --minibatches 2 --quiet)
"$sq" "${g3[@]}" --out "$tmp/g3.1" >/dev/null 2>&1
"${mpi_env[@]}" mpirun --oversubscribe --allow-run-as-root -np 3 -x OPENBLAS_NUM_THREADS -x OMP_NUM_THREADS "$sq" "${g3[@]}" --out "$tmp/g3.3" >/dev/null 2>&1
if d=$(python3 "$here/compare_checkpoints.py" "$tmp/g3.1/checkpoint.ckpt" "$tmp/g3.3/checkpoint.ckpt"); then
  ok "gpt2_tiny ppo, 3 ranks, one with no episodes: $d"
else
  bad "gpt2_tiny ppo on 3 ranks: $d"
fi

# A job repeats bit for bit at a fixed rank count; one process gives the same
# bits whatever its number of slots (per-episode streams, batch in episode order).
"${mpi[@]}" "$sq" train "${mlp[@]}" --estimator ppo --epochs 2 --minibatches 3 --quiet --out "$tmp/again.2" >/dev/null 2>&1
d=$(python3 "$here/compare_checkpoints.py" "$tmp/mlp_ppo.2/checkpoint.ckpt" "$tmp/again.2/checkpoint.ckpt")
case $d in bit-identical*) ok "2 ranks twice: $d" ;; *) bad "2 ranks twice: $d" ;; esac
"$sq" train "${mlp[@]}" --estimator ppo --epochs 2 --minibatches 3 --envs 3 --quiet --out "$tmp/envs3" >/dev/null 2>&1
d=$(python3 "$here/compare_checkpoints.py" "$tmp/mlp_ppo.1/checkpoint.ckpt" "$tmp/envs3/checkpoint.ckpt")
case $d in bit-identical*) ok "1 process, --envs 8 and 3: $d" ;; *) bad "--envs 8 and 3: $d" ;; esac

# eval: the same JSON figures, wall time aside.
ev=(eval scenarios/horizontal_cr.lua --checkpoint "$tmp/mlp_improved.1/policy.ckpt" --episodes 40 --envs 8 --json)
one=$("$sq" "${ev[@]}" 2>/dev/null | sed 's/"wall_s":[0-9.e+-]*,\?//')
two=$("${mpi[@]}" "$sq" "${ev[@]}" 2>/dev/null | sed 's/"wall_s":[0-9.e+-]*,\?//')
if [ -n "$one" ] && [ "$one" = "$two" ]; then ok "eval: 1 process and 2 ranks print the same figures"; else bad "eval differs:"; echo "$one"; echo "$two"; fi

echo "dist equivalence: $pass passed, $fails failed"
[ "$fails" -eq 0 ]
