#!/usr/bin/env bash
# CLI behaviour of the foundation: exit codes, sandbox messages, error
# locations, the instruction cap, seeded randomness, `squawk test` totals.
# usage: tests/cli.sh path/to/squawk   (run from the repo root)
set -u
sq=${1:?usage: tests/cli.sh SQUAWK_BINARY}
d=tests/data/cli
source "$(dirname "$0")/expect.sh"

expect "help"            0 "subcommands:" -- "$sq" --help
expect "version"         0 "^squawk [0-9]+\.[0-9]+\.[0-9]+" -- "$sq" --version
expect "help run"        0 "usage: squawk run" -- "$sq" help run
expect "no subcommand"   2 "" -- "$sq"
expect "unknown sub"     2 "unknown subcommand 'frobnicate'" -- "$sq" frobnicate
expect "unknown flag"    2 "unknown flag '--bogus'" -- "$sq" test --bogus
expect "missing file"    2 "missing FILE.lua" -- "$sq" run
expect "bad seed"        2 "--seed expects an integer" -- "$sq" run "$d/args.lua" --seed x
expect "args"            0 "^2	a	b$" -- "$sq" run "$d/args.lua" a b
# more arguments than Lua's guaranteed stack slots (they are also passed as `...`)
expect "many args"       0 "^200	1	2$" -- "$sq" run "$d/args.lua" $(seq 1 200)
expect "sandbox"         1 "os.execute is not allowed in the sandbox; run squawk with --unsafe" -- "$sq" run "$d/execute.lua"
expect "unsafe"          0 "^executed$" -- "$sq" run "$d/execute.lua" --unsafe
expect "module line"     1 "mod.lua:7: value too large: 6" -- "$sq" run "$d/module/main.lua"
# Lua errors: `file:line: message` everywhere; the traceback only with --verbose.
[ "$("$sq" run "$d/module/main.lua" 2>&1 | wc -l)" -eq 1 ] && { echo "ok   no traceback by default"; pass=$((pass + 1)); } || { echo "FAIL traceback shown without --verbose"; fails=$((fails + 1)); }
expect "--verbose traceback" 1 "in function 'mod.run'" -- "$sq" run --verbose "$d/module/main.lua"
expect "eval lua error"  1 "^squawk: .*module/mod.lua:7: value too large: 6$" -- "$sq" eval "$d/module/main.lua" --policy zero
expect "runaway"         1 "stopped: the script ran .* Lua instructions" -- "$sq" run "$d/runaway.lua"
expect "test totals"     1 "^1 passed, 1 failed$" -- "$sq" test "$d/pass_fail"
expect "test location"   1 "fail.lua:1: check failed: got 4, want 5 \(arithmetic\)" -- "$sq" test "$d/pass_fail"
# Environments written in Lua (envs/): episodes from the command line.
expect "env run random"  0 "terminated +5 of 5; truncated 0" -- "$sq" env run envs/descent.lua --policy random --episodes 5
expect "env run crash"   0 "mean length +[0-9]\.[0-9]+ steps" -- "$sq" env run envs/descent.lua --policy constant:-1 --episodes 3
expect "env run json"    0 '"env": "DescentEnv-v0", "policy": "zero", "episodes": 2' -- "$sq" env run envs/descent.lua --policy zero --episodes 2 --json
expect "env bad policy"  2 "constant:2: action 1 is outside \[-1, 1\]" -- "$sq" env run envs/descent.lua --policy constant:2
expect "env run sector"  0 "terminated +0 of 3; truncated 3" -- "$sq" env run envs/sector_cr.lua --policy zero --episodes 3
expect "env run merge"   0 '"env": "MergeEnv-v0", "policy": "random", "episodes": 2' -- "$sq" env run envs/merge.lua --episodes 2 --json
expect "env multi"       1 "field 'parallel' = true: a multi-agent environment" -- "$sq" env run envs/sector_multi.lua
expect "env no file"     1 "no environment file 'envs/nope.lua'" -- "$sq" env run envs/nope.lua
# An MLP trained on a Lua environment (squawk train --env) and evaluated by env
# run: sign.lua pays -6 an episode to random actions, 0 to the best policy.
gt=$(mktemp -d)
expect "train env"       0 "done: 960 episodes" -- "$sq" train --env tests/data/gym/sign.lua --out "$gt/sign" --episodes 960 --eval-every 320
expect "train env log"   0 "^960,60," -- cat "$gt/sign/log.csv"
expect "env run mlp"     0 '"policy": "mlp:.*sign/policy.ckpt", "episodes": 40, "seed": 0, "mean_reward": (0|-0\.[0-9]+),' -- "$sq" env run tests/data/gym/sign.lua --policy "mlp:$gt/sign/policy.ckpt" --episodes 40 --json
expect "env run mlp greedy" 0 '"mean_reward": 0, "std_reward": 0' -- "$sq" env run tests/data/gym/sign.lua --policy "mlp:$gt/sign/policy.ckpt" --greedy --episodes 40 --json
expect "env mlp mismatch" 1 "reads 1 observation numbers; DescentEnv-v0 gives 4" -- "$sq" env run envs/descent.lua --policy "mlp:$gt/sign/policy.ckpt"
expect "env greedy alone" 2 "--greedy goes with --policy mlp:CKPT" -- "$sq" env run envs/descent.lua --greedy
expect "train env vine"  2 "on --env use \"improved\"" -- "$sq" train --env tests/data/gym/sign.lua --out "$gt/vine" --estimator vine
# --gaussian: a Gaussian head over a one-component Box (sign.lua's best action is the sign itself).
expect "train env gaussian" 0 "a Gaussian head over the continuous action" -- "$sq" train --env tests/data/gym/sign.lua --out "$gt/gauss" --gaussian --estimator ppo --episodes 640 --eval-every 320
expect "env run gaussian greedy" 0 '"mean_reward": (0|-0\.[0-4][0-9]*),' -- "$sq" env run tests/data/gym/sign.lua --policy "mlp:$gt/gauss/policy.ckpt" --greedy --episodes 40 --json
expect "env gaussian 2-d" 1 "a Gaussian policy of 1 action component; StaticObstacleEnv-v0 takes 2" -- "$sq" env run envs/static_obstacle.lua --policy "mlp:$gt/gauss/policy.ckpt"
# A diagonal Gaussian over a two-component Box (sign2.lua: best (s1, 5 + 5 s2) on [-1, 1] x [0, 10]).
expect "train gaussian 2-d" 0 "a Gaussian head over the continuous action \(2 components\)" -- "$sq" train --env tests/data/gym/sign2.lua --out "$gt/g2" --gaussian --estimator ppo --episodes 640 --eval-every 320
expect "env run gaussian 2-d greedy" 0 '"mean_reward": (0|-0\.[0-9]+),.*"action_shares": \[\[0\.[45][0-9]*, 0(\.0[0-9]*)?, 0\.[45][0-9]*\], \[0\.[45][0-9]*, 0(\.0[0-9]*)?, 0\.[45][0-9]*\]\]' -- "$sq" env run tests/data/gym/sign2.lua --policy "mlp:$gt/g2/policy.ckpt" --greedy --episodes 40 --json
# --obs-norm: the checkpoint keeps the statistics, and env run reads through them.
expect "train obs-norm" 0 "observations normalised" -- "$sq" train --env tests/data/gym/sign2.lua --out "$gt/norm" --gaussian --obs-norm 20 --estimator ppo --episodes 640 --eval-every 320
expect "env run obs-norm" 0 '"mean_reward": (0|-0\.[0-9]+),' -- "$sq" env run tests/data/gym/sign2.lua --policy "mlp:$gt/norm/policy.ckpt" --greedy --episodes 40 --json
expect "obs-norm alone" 2 "--obs-norm and --log-std shape the policy of a --env ENV.lua run" -- "$sq" train scenarios/horizontal_cr.lua --out "$gt/x" --obs-norm 10
expect "log-std grid" 2 "--log-std -1: the Gaussian head's initial log sigma, in \[-5, 2\], with --gaussian" -- "$sq" train --env tests/data/gym/sign.lua --out "$gt/ls" --log-std -1
# --update-log: one row per update in updates.csv (sign.lua's 640 episodes, 16 an update: 40 rows), and the same log.csv as without it (but its wall times).
expect "train update-log" 0 "done: 640 episodes" -- "$sq" train --env tests/data/gym/sign.lua --out "$gt/ul" --gaussian --estimator ppo --episodes 640 --eval-every 320 --update-log
expect "update-log rows" 0 "^41 episodes,mean_return,entropy,grad_norm,value_loss,advantage_sd,clip_fraction 640,-?[0-9.e-]+,-?[0-9.e-]+(,[0-9.e-]+){3},(0|0\.[0-9]+|1)$" -- bash -c "echo \$(wc -l < '$gt/ul/updates.csv') \$(head -1 '$gt/ul/updates.csv') \$(tail -1 '$gt/ul/updates.csv')"
expect "update-log observes" 0 "" -- bash -c "cmp <(cut -d, -f1,2,4- '$gt/gauss/log.csv') <(cut -d, -f1,2,4- '$gt/ul/log.csv')"
expect "update-log needs env" 2 "--update-log writes the updates of a --env ENV.lua run" -- "$sq" train scenarios/horizontal_cr.lua --out "$gt/x" --update-log
# bench/gym_paired.lua: a rule against itself (the env and the rule each require their own "descent"), an MLP against a rule.
expect "paired lua rule" 0 "mean \+0\.000, standard error 0\.000; A better in 0, equal in 3, worse in 0" -- "$sq" run bench/gym_paired.lua envs/vertical_cr.lua script:envs/policies/vertical_cr.lua script:envs/policies/vertical_cr.lua 3 0
expect "paired lua mlp" 0 "over 20 paired episodes: mean \+[01]\.[0-9]+, .*A better in [1-9][0-9]*," -- "$sq" run bench/gym_paired.lua tests/data/gym/sign.lua "mlp:$gt/ul/policy.ckpt" script:tests/data/gym/sign_half.lua 20 0 --allow-read "$gt:tests/data/gym"
# bench/gym_imitation_probe.lua: the greedy MLP flies the sign (+-1), so it is 0.5 from sign_half.lua's half sign at every
# decision; sign_late.lua answers from the step before, which a fresh instance lacks in 3 of every 4 decisions.
expect "probe error" 0 "rule states, \|clone - rule\| \(80 decisions\): component 1: mean 0\.(4[5-9][0-9]|500)," -- "$sq" run bench/gym_imitation_probe.lua tests/data/gym/sign.lua "mlp:$gt/ul/policy.ckpt" script:tests/data/gym/sign_half.lua 20 0 trace=3 --allow-read "$gt:tests/data/gym"
expect "probe replay" 0 "replay: a fresh rule answers 60 of 80 rule-state observations differently \(0\.750\)" -- "$sq" run bench/gym_imitation_probe.lua tests/data/gym/sign.lua "mlp:$gt/ul/policy.ckpt" script:tests/data/gym/sign_late.lua 20 0 noise= --allow-read "$gt:tests/data/gym"
# bench/gym_profile.lua: one policy's success, return split into its intrusion part and the rest, length (env run's figures for the same 6 episodes), where the intruder-steps fall and the action shares.
expect "profile rule" 0 "success 83\.3 %, mean return -3\.606 \(sd 4\.21\), intrusion part -1\.667, the rest -1\.939, mean length 70\.2" -- "$sq" run bench/gym_profile.lua envs/sector_cr.lua script:envs/policies/sector_cr.lua 6 0
expect "profile steps" 0 "^intruder-steps an episode by step: 1-1 0\.00, 2-10 1\.17, 11-30 0\.50, 31-60 0\.00" -- "$sq" run bench/gym_profile.lua envs/sector_cr.lua script:envs/policies/sector_cr.lua 6 0
expect "profile shares" 0 "^action shares \(lower/middle/upper third\): 0\.20/0\.62/0\.18; 0\.00/1\.00/0\.00$" -- "$sq" run bench/gym_profile.lua envs/sector_cr.lua script:envs/policies/sector_cr.lua 6 0
# --init CKPT: a run that starts from a trained policy (sign.lua: 4 steps an episode, so 2000 greedy episodes are 8000 steps) and keeps it.
expect "train init" 0 "value baseline fitted to the starting policy's returns \(8000 steps\)" -- "$sq" train --env tests/data/gym/sign.lua --out "$gt/init" --init "$gt/gauss/policy.ckpt" --gaussian --estimator ppo --episodes 320 --eval-every 320
expect "env run init greedy" 0 '"mean_reward": (0|-0\.[0-4][0-9]*),' -- "$sq" env run tests/data/gym/sign.lua --policy "mlp:$gt/init/policy.ckpt" --greedy --episodes 40 --json
# --init with --clone-log-std -3: the starting policy's log sigma (entropy -3 + 1.419 at the first update, as after cloning).
expect "train init log-std" 0 "done: 64 episodes" -- "$sq" train --env tests/data/gym/sign.lua --out "$gt/ils" --init "$gt/gauss/policy.ckpt" --gaussian --clone-log-std -3 --estimator ppo --episodes 64 --eval-every 0 --update-log
expect "init log-std entropy" 0 "^16,[-0-9.e]+,-1\.58" -- sed -n 2p "$gt/ils/updates.csv"
expect "init no hidden" 2 "--init CKPT starts from the checkpoint's policy: no --hidden beside it" -- "$sq" train --env tests/data/gym/sign.lua --out "$gt/i2" --init "$gt/gauss/policy.ckpt" --gaussian --hidden 8
expect "init head" 1 "its policy's head \(gaussian, 1 components\) is not this run's \(5 grid classes\)" -- "$sq" train --env tests/data/gym/sign.lua --out "$gt/i3" --init "$gt/gauss/policy.ckpt"
expect "init obs size" 1 "its policy reads 1 observation numbers; DescentEnv-v0 gives 4" -- "$sq" train --env envs/descent.lua --out "$gt/i4" --init "$gt/gauss/policy.ckpt" --gaussian
expect "init multi-agent" 2 "--init starts single-agent files from a checkpoint; envs/sector_multi.lua is multi-agent" -- "$sq" train --env envs/sector_multi.lua --out "$gt/i6" --init "$gt/gauss/policy.ckpt"
expect "init scenario" 2 "--init CKPT starts a --env ENV.lua or a --policy gpt2 run" -- "$sq" train scenarios/horizontal_cr.lua --out "$gt/i5" --init "$gt/gauss/policy.ckpt"
# bench/gym_sector_close.lua: the same 6 episodes' intruder-steps by distance (1.67 an episode, as the profile's count).
expect "sector close" 0 "1\.67 intruder-steps an episode; under 2 NM 0\.00, 2-4 NM 0\.67, 4-4\.8 NM 0\.83, 4\.8-5 NM 0\.17; relative speed under 30 m/s 0\.00" -- "$sq" run bench/gym_sector_close.lua script:envs/policies/sector_cr.lua 6 0
# --imitate: behaviour cloning of a Lua rule (sign_half.lua: half the sign, -1 an episode), then the learner.
# The greedy clone acts within 0.025 of the rule, so its episodes score -0.90 to -1.10 (-1.038 on AMD EPYC).
expect "train env imitate" 0 "round 1 \(student flew\), epoch 9: 3200 decisions, held-out agreement 1\.000" -- "$sq" train --env tests/data/gym/sign.lua --out "$gt/imit" --gaussian --obs-norm 20 --imitate tests/data/gym/sign_half.lua --imitate-episodes 400 --imitate-rounds 2 --imitate-epochs 10 --imitate-lr 1e-2 --estimator ppo --episodes 64 --eval-every 0
expect "env run cloned" 0 '"mean_reward": -(1\.0|0\.9)[0-9]*, "std_reward"' -- "$sq" env run tests/data/gym/sign.lua --policy "mlp:$gt/imit/cloned.ckpt" --greedy --episodes 40 --json
# --imitate-means: two components, the second held at its top; log sigma held, every component labelled.
expect "train env imitate means" 0 "round 1 \(student flew\), epoch 9: 3200 decisions, held-out agreement 1\.000" -- "$sq" train --env tests/data/gym/sign2.lua --out "$gt/imit2" --gaussian --log-std -1 --imitate tests/data/gym/sign2_half.lua --imitate-means --imitate-episodes 400 --imitate-rounds 2 --imitate-epochs 10 --imitate-lr 1e-2 --estimator ppo --episodes 64 --eval-every 0
# --imitate-permute 2:0: sign2.lua's two signs shown in random order, so the rule's half first sign cannot be told apart.
expect "train env imitate permute" 0 "round 1 \(student flew\), epoch 9: 3200 decisions, held-out agreement 0\.[0-8]" -- "$sq" train --env tests/data/gym/sign2.lua --out "$gt/imit3" --gaussian --log-std -1 --imitate tests/data/gym/sign2_half.lua --imitate-means --imitate-permute 2:0 --imitate-episodes 400 --imitate-rounds 2 --imitate-epochs 10 --imitate-lr 1e-2 --estimator ppo --episodes 64 --eval-every 0
expect "imitate permute outside" 2 "--imitate-permute: slot layout '10:0,40': block 40..49 lies outside the observation's 43 numbers" -- "$sq" train --env envs/static_obstacle.lua --out "$gt/imp" --imitate envs/policies/static_obstacle.lua --imitate-permute 10:0,40
expect "imitate permute alone" 2 "--imitate-permute sets --imitate POLICY.lua's cloning" -- "$sq" train --env tests/data/gym/sign.lua --out "$gt/imq" --imitate-permute 2:0
expect "imitate means grid" 2 "--imitate-means holds the Gaussian head's log sigma: add --gaussian" -- "$sq" train --env tests/data/gym/sign.lua --out "$gt/imv" --imitate tests/data/gym/sign_half.lua --imitate-means
expect "imitate saturate grid" 2 "--imitate-saturate moves the Gaussian head's labels: add --gaussian" -- "$sq" train --env tests/data/gym/sign.lua --out "$gt/ims" --imitate tests/data/gym/sign_half.lua --imitate-saturate 1.2
expect "imitate saturate range" 2 "--imitate-saturate must lie in \[1, 3\]" -- "$sq" train --env tests/data/gym/sign.lua --out "$gt/ims" --gaussian --imitate tests/data/gym/sign_half.lua --imitate-saturate 0.9
# --clone-log-std: the clone is fine-tuned from log sigma -3 (entropy -3 + 1.419 at the first update).
expect "train clone-log-std" 0 "done: 64 episodes" -- "$sq" train --env tests/data/gym/sign.lua --out "$gt/cls" --gaussian --imitate tests/data/gym/sign_half.lua --imitate-episodes 100 --imitate-rounds 1 --clone-log-std -3 --estimator ppo --episodes 64 --eval-every 0 --update-log
expect "clone-log-std entropy" 0 "^16,[-0-9.e]+,-1\.58" -- sed -n 2p "$gt/cls/updates.csv"
expect "clone-log-std alone" 2 "--clone-log-std -1: the cloned Gaussian head's log sigma, in \[-5, 2\], with --gaussian and --imitate or --init" -- "$sq" train --env tests/data/gym/sign.lua --out "$gt/cl" --gaussian --clone-log-std -1
expect "imitate needs env" 2 "--imitate POLICY.lua clones a rule of a --env ENV.lua run" -- "$sq" train scenarios/horizontal_cr.lua --out "$gt/imx" --imitate tests/data/gym/sign_half.lua
expect "imitate flags alone" 2 "--imitate-epochs sets --imitate POLICY.lua's cloning" -- "$sq" train --env tests/data/gym/sign.lua --out "$gt/imy" --imitate-epochs 3
expect "imitate multi-agent" 2 "--imitate clones a single-agent rule; envs/sector_multi.lua is multi-agent" -- "$sq" train --env envs/sector_multi.lua --out "$gt/imz" --imitate tests/data/gym/sign_half.lua
expect "imitate wrong env" 1 "sign_half.lua" -- "$sq" train --env envs/descent.lua --out "$gt/imw" --gaussian --imitate tests/data/gym/sign_half.lua
expect "train gaussian levels" 2 "--gaussian acts on the continuous Box: no --levels grid beside it" -- "$sq" train --env tests/data/gym/sign.lua --out "$gt/g3" --gaussian --levels 3
expect "train gaussian multi" 2 "--gaussian trains single-agent files; envs/sector_multi.lua is multi-agent" -- "$sq" train --env envs/sector_multi.lua --out "$gt/g4" --gaussian
expect "train levels 0"   2 "--levels 0: expected at least 2 per component" -- "$sq" train --env tests/data/gym/sign.lua --out "$gt/l0" --levels 0
expect "train levels alone" 2 "--levels, --gaussian and --hidden shape the policy of a --env ENV.lua run" -- "$sq" train scenarios/horizontal_cr.lua --out "$gt/x" --levels 3
# One MLP shared by every agent of the multi-agent sector: 3 agents, each
# agent's trajectory an episode (12 = 4 sector episodes), then evaluated
# beside "do nothing" and MVP by bench/sector_multi_eval.lua.
expect "train multi"     0 "sector episodes played in training: 4$" -- "$sq" train --env envs/sector_multi.lua --agents 3 --out "$gt/multi" --episodes 12 --episodes-per-update 6 --eval-every 12 --eval-episodes 6 --envs 2
expect "train multi log" 0 "^12,2," -- cat "$gt/multi/log.csv"
expect "multi eval mlp"  0 "^\| 20 \| MLP \| [0-9.]+ \|" -- "$sq" run bench/sector_multi_eval.lua 1 0 "$gt/multi/policy.ckpt" --max-instructions 0 --allow-read "$gt"
expect "multi eval mismatch" 1 "sign/policy.ckpt: the policy reads 1 observation numbers; SectorMultiCR-v0 gives 31" -- "$sq" run bench/sector_multi_eval.lua 1 0 "$gt/sign/policy.ckpt" --max-instructions 0 --allow-read "$gt"
expect "train multi split" 2 "--episodes-per-update 16: the learner's episodes are agent trajectories, 3 per sector episode" -- "$sq" train --env envs/sector_multi.lua --agents 3 --out "$gt/split" --episodes-per-update 16
expect "train agents single" 2 "--agents sets the agents of a multi-agent file; envs/descent.lua is single-agent" -- "$sq" train --env envs/descent.lua --agents 3 --out "$gt/single"
expect "train agents alone" 2 "--agents sets the agents of a multi-agent --env" -- "$sq" train scenarios/horizontal_cr.lua --out "$gt/x" --agents 3
rm -rf "$gt"
expect "env plan waypoint" 0 "observation 20 numbers, action 1 in \[-1, 1\], at most 300 steps" -- "$sq" env run envs/plan_waypoint.lua --policy random --episodes 2
expect "env run horizontal" 0 "terminated +1000 of 1000; truncated 0" -- "$sq" env run envs/horizontal_cr.lua --policy random --episodes 1000
expect "eval env file"   0 "scenario +envs/horizontal_cr_gym.lua \(gym rules" -- "$sq" eval envs/horizontal_cr_gym.lua --policy zero --episodes 20
expect "env static obstacle" 0 "observation 43 numbers, action 2 in \[-1, 1\], at most 100 steps" -- "$sq" env run envs/static_obstacle.lua --policy random --episodes 5
tmp=$(mktemp -d)
expect "demo"            0 "translator HDG KL001" -- "$sq" demo --record "$tmp/ep.jsonl" --svg "$tmp/ep.svg"
expect "demo summary"    0 "waypoint reached +yes" -- "$sq" demo --quiet
expect "demo gpt2"       0 "advisories the translator could not turn into a command: 0" -- "$sq" demo --policy gpt2 --quiet
expect "demo bad policy" 2 "expected mlp or gpt2" -- "$sq" demo --policy nope
expect "gpt2 bench help"  0 "squawk gpt2 bench" -- "$sq" gpt2 bench --help
# --precision: the default is printed at start; bf16 where it is not native
# (ONEDNN_MAX_CPU_ISA hides the bf16 instructions from oneDNN) runs fp32 with a notice.
expect "gpt2 precision default" 0 "^precision: (bf16 products with fp32 accumulation, .*|fp32) \(the fastest here" -- "$sq" gpt2 logits tiny "hi"
expect "gpt2 precision fp32" 0 "^precision: fp32 \(--precision\)" -- "$sq" gpt2 logits tiny "hi" --precision fp32
expect "gpt2 no native bf16" 0 "^precision: fp32; bf16 was asked for, but this CPU or build has no native bf16" -- env ONEDNN_MAX_CPU_ISA=AVX512_CORE "$sq" gpt2 logits tiny "hi" --precision bf16
expect "gpt2 bad precision" 2 "--precision: precision 'fp16' is neither bf16 nor fp32" -- "$sq" train scenarios/horizontal_cr.lua --policy gpt2 --out "$(mktemp -d)" --precision fp16
# Both learners take the same learner flags, checked the same way.
expect "train gpt2 gamma"   2 "train gamma must lie in" -- "$sq" train scenarios/horizontal_cr.lua --policy gpt2 --out "$(mktemp -d)" --gamma 2
expect "train mlp gamma"    2 "train gamma must lie in" -- "$sq" train scenarios/horizontal_cr.lua --out "$(mktemp -d)" --gamma 2
# Self-supervised pretraining writes a model folder that the policy fine-tunes
# with the embeddings trainable; the held-out loss falls within a few steps.
pt="$tmp/pretrained"
expect "gpt2 pretrain"   0 "wrote $pt" -- "$sq" gpt2 pretrain scenarios/horizontal_cr.lua "$pt" --episodes 8 --steps 6 --log-every 3 --holdout 16
awk -F, 'NR == 2 { a = $5 } NR == 3 { b = $5 } END { exit !(NR == 3 && b < a) }' "$pt/pretrain.csv" && { echo "ok   pretrain held-out loss falls"; pass=$((pass + 1)); } || { echo "FAIL pretrain loss"; fails=$((fails + 1)); }
expect "pretrain refuses a model" 2 "pretrain: $pt already holds model.safetensors, pretrain.csv: --force replaces it" -- "$sq" gpt2 pretrain scenarios/horizontal_cr.lua "$pt" --episodes 8 --steps 6
expect "pretrain bad steps" 2 "--steps expects a positive integer" -- "$sq" gpt2 pretrain scenarios/horizontal_cr.lua "$pt" --steps 0
# With --readout a linear probe also reads the observation from the last token: two more columns, and its held-out error falls
expect "pretrain readout" 0 "read-out mse" -- "$sq" gpt2 pretrain scenarios/horizontal_cr.lua "$tmp/pt_ro" --episodes 8 --steps 12 --log-every 6 --batch 8 --holdout 16 --readout 1
awk -F, 'NR == 1 { h = $7 } NR == 2 { a = $7 } NR == 3 { b = $7 } END { exit !(NR == 3 && h == "holdout_readout" && b < a) }' "$tmp/pt_ro/pretrain.csv" && { echo "ok   pretrain read-out error falls"; pass=$((pass + 1)); } || { echo "FAIL pretrain read-out"; fails=$((fails + 1)); }
expect "pretrain bad readout" 2 "--readout expects a weight in \[0, 1000\]" -- "$sq" gpt2 pretrain scenarios/horizontal_cr.lua "$pt" --readout -1
# Imitation (a labelled experiment): the pretrained model clones the shipped mirror MLP; eval reads the result
expect "gpt2 imitate"    0 "epoch 2: held-out agreement" -- "$sq" gpt2 imitate scenarios/horizontal_cr.lua "$pt/imitate.ckpt" --model "$pt" --mirror --train-embeddings --blocks 2 --episodes 4 --epochs 2 --batch 8 --holdout 2 --envs 4
expect "imitate refuses a checkpoint" 2 "imitate: $pt/imitate.ckpt exists: --force replaces it" -- "$sq" gpt2 imitate scenarios/horizontal_cr.lua "$pt/imitate.ckpt" --model "$pt"
expect "eval imitation"  0 "mirror-symmetric" -- "$sq" eval scenarios/horizontal_cr.lua --policy gpt2 --checkpoint "$pt/imitate.ckpt" --episodes 2
expect "imitate bad teacher" 1 "nope.ckpt" -- "$sq" gpt2 imitate scenarios/horizontal_cr.lua "$pt/x.ckpt" --model "$pt" --teacher "$tmp/nope.ckpt"
expect "imitate no out"  2 "imitate expects SCENARIO.lua OUT.ckpt" -- "$sq" gpt2 imitate scenarios/horizontal_cr.lua
expect "train pretrained" 0 "done: 8 episodes" -- "$sq" train scenarios/horizontal_cr.lua --policy gpt2 --model "$pt" --train-embeddings --blocks 2 --lr 1e-3 --episodes 8 --episodes-per-update 8 --envs 8 --eval-every 8 --eval-episodes 4 --out "$pt/run"
expect "train gpt2 stop-at" 0 "16 episodes, stopping at 8" -- "$sq" train scenarios/horizontal_cr.lua --policy gpt2 --model "$pt" --train-embeddings --blocks 2 --episodes 16 --stop-at 8 --episodes-per-update 8 --envs 8 --eval-every 8 --eval-episodes 4 --out "$pt/stop"
awk -F, 'END { exit $1 != 8 }' "$pt/stop/log.csv" && { echo "ok   gpt2 stop-at ends at 8"; pass=$((pass + 1)); } || { echo "FAIL gpt2 stop-at: log ends at $(tail -1 "$pt/stop/log.csv")"; fails=$((fails + 1)); }
# squawk.rl.train is the same learner: the stop-at run above, as a Lua call,
# gives the log's row (but the wall time) and a checkpoint with the same arrays.
cat > "$tmp/rl_stop.lua" <<LUA
squawk.rl.train{scenario = "scenarios/horizontal_cr.lua", policy = "gpt2", model = "$pt", train_embeddings = true,
  blocks = 2, episodes = 16, stop_at = 8, episodes_per_update = 8, envs = 8, eval_every = 8, eval_episodes = 4,
  save = squawk.out_dir .. "/a.ckpt",
  on_update = function(u)
    local e = u.eval
    print(string.format("%d,%d,%.4f,%.4f,%.4f,%.4f,%.4f,%.4f,%.4f", u.episodes, u.update, u.mean_return,
      u.success_rate, u.entropy, u.grad_norm, e.success_rate, e.mean_reward, e.std_reward))
  end}
LUA
mkdir -p "$tmp/rl_stop"
lua_row=$("$sq" run "$tmp/rl_stop.lua" --allow-read "$pt" --out "$tmp/rl_stop" 2>/dev/null)
[ -n "$lua_row" ] && [ "$lua_row" = "$(tail -1 "$pt/stop/log.csv" | cut -d, -f1,2,4-)" ] \
  && cmp -s <(tail -n +3 "$pt/stop/checkpoint.ckpt") <(tail -n +3 "$tmp/rl_stop/a.ckpt") \
  && { echo "ok   squawk.rl.train repeats squawk train"; pass=$((pass + 1)); } \
  || { echo "FAIL squawk.rl.train: '$lua_row' against '$(tail -1 "$pt/stop/log.csv")'"; fails=$((fails + 1)); }
# Training evaluates on the validation episodes (eval seed 2024 + 1000003), never
# on those `squawk eval` reads: the default run's log equals one with that seed
# named, but for the wall time, and not one on the evaluation seed.
expect "train gpt2 validation seed" 0 "done: 8 episodes" -- "$sq" train scenarios/horizontal_cr.lua --policy gpt2 --model "$pt" --train-embeddings --blocks 2 --lr 1e-3 --episodes 8 --episodes-per-update 8 --envs 8 --eval-every 8 --eval-episodes 4 --validation-seed 1002027 --out "$pt/val"
expect "train gpt2 on eval seed" 0 "done: 8 episodes" -- "$sq" train scenarios/horizontal_cr.lua --policy gpt2 --model "$pt" --train-embeddings --blocks 2 --lr 1e-3 --episodes 8 --episodes-per-update 8 --envs 8 --eval-every 8 --eval-episodes 4 --validation-seed 2024 --out "$pt/evalseed"
no_wall() { cut -d, -f1,2,4- "$1"; }
[ "$(no_wall "$pt/run/log.csv")" = "$(no_wall "$pt/val/log.csv")" ] && [ "$(no_wall "$pt/run/log.csv")" != "$(no_wall "$pt/evalseed/log.csv")" ] \
  && { echo "ok   gpt2 training evaluates on the validation seed"; pass=$((pass + 1)); } \
  || { echo "FAIL gpt2 training evaluation seed: $(tail -1 "$pt/run/log.csv") / $(tail -1 "$pt/val/log.csv") / $(tail -1 "$pt/evalseed/log.csv")"; fails=$((fails + 1)); }
expect "bad validation seed" 2 "--validation-seed: expected a seed >= 0, got -1" -- "$sq" train scenarios/horizontal_cr.lua --policy gpt2 --model "$pt" --validation-seed -1 --out "$pt/badval"
expect "eval lookahead"  0 "success" -- "$sq" eval scenarios/horizontal_cr.lua --policy lookahead --episodes 20
out=$("$sq" eval scenarios/horizontal_cr_gym.lua --policy mlp --episodes 2 2>&1)
[ "$(grep -c "was trained on" <<<"$out")" -eq 1 ] && { echo "ok   eval warning said once"; pass=$((pass + 1)); } || { echo "FAIL eval warning count: $out"; fails=$((fails + 1)); }
expect "lookahead gym"   2 "plans under the paper rules only" -- "$sq" eval scenarios/horizontal_cr_gym.lua --policy lookahead --episodes 2
expect "rollout no head" 2 "zero has no discrete action head" -- "$sq" eval scenarios/horizontal_cr.lua --policy rollout:zero --episodes 2
expect "vine gaussian"   2 "needs a discrete action head" -- "$sq" train scenarios/horizontal_cr_gym.lua --policy mlp --estimator vine --episodes 8 --out "$tmp/vine"
# --mirror: both learners; the checkpoint remembers it, eval names it, a
# resume that disagrees and a scenario whose ownship slows are refused.
mir="$tmp/mirror"
expect "train mlp mirror"  0 "done: 64 episodes" -- "$sq" train scenarios/horizontal_cr.lua --mirror --episodes 64 --eval-every 64 --eval-episodes 4 --out "$mir/mlp"
expect "eval mirror"       0 "mirror-symmetric" -- "$sq" eval scenarios/horizontal_cr.lua --policy mlp --checkpoint "$mir/mlp/policy.ckpt" --episodes 2
expect "resume contradicts" 2 "--resume: --episodes 128 contradicts the run's --episodes 64; .*run.json" -- "$sq" train scenarios/horizontal_cr.lua --episodes 128 --eval-every 64 --eval-episodes 4 --out "$mir/mlp" --resume
expect "mirror gym"        2 "--mirror: mirror symmetry needs a constant ownship speed, but speed_cap 89" -- "$sq" train scenarios/horizontal_cr_gym.lua --mirror --episodes 8 --out "$mir/gym"
expect "train gpt2 mirror" 0 "done: 8 episodes" -- "$sq" train scenarios/horizontal_cr.lua --policy gpt2 --model "$pt" --mirror --train-embeddings --blocks 2 --episodes 8 --episodes-per-update 8 --envs 8 --eval-every 8 --eval-episodes 4 --out "$mir/gpt2"
expect "eval gpt2 mirror"  0 "head action, mirror-symmetric" -- "$sq" eval scenarios/horizontal_cr.lua --policy gpt2 --checkpoint "$mir/gpt2/checkpoint.ckpt" --episodes 2
expect "table3 gpt2 mirror" 0 "^RL Fine-Tuned GPT-2, mirror-symmetric \\(beyond the paper\\),[01]\\." -- "$sq" table3 scenarios/horizontal_cr.lua --episodes 2
expect "table3 mirror ckpt" 1 "mirror-symmetric \\(beyond the paper\\): cannot open 'no/such.ckpt'" -- "$sq" table3 scenarios/horizontal_cr.lua --episodes 2 --gpt2-mirror-checkpoint no/such.ckpt
# --init: a new run starts from a checkpoint's policy (a step of 1e-12 leaves
# its evaluation unchanged), counts from zero and may add the mirror.
expect "train gpt2 init" 0 "\\(from $pt/run/checkpoint.ckpt\\)" -- "$sq" train scenarios/horizontal_cr.lua --policy gpt2 --init "$pt/run/checkpoint.ckpt" --lr 1e-12 --seed 3 --episodes 8 --episodes-per-update 8 --envs 8 --eval-every 8 --eval-episodes 4 --out "$pt/init"
before=$("$sq" eval scenarios/horizontal_cr.lua --policy gpt2 --checkpoint "$pt/run/checkpoint.ckpt" --episodes 4 | grep -A1 "mean episode reward")
after=$("$sq" eval scenarios/horizontal_cr.lua --policy gpt2 --checkpoint "$pt/init/checkpoint.ckpt" --episodes 4 | grep -A1 "mean episode reward")
[ -n "$before" ] && [ "$before" = "$after" ] && awk -F, 'NR == 2 { exit $1 != 8 }' "$pt/init/log.csv" && { echo "ok   init carries the policy, counts from zero"; pass=$((pass + 1)); } || { echo "FAIL init: '$before' vs '$after'"; fails=$((fails + 1)); }
expect "train gpt2 init mirror" 0 "done: 8 episodes" -- "$sq" train scenarios/horizontal_cr.lua --policy gpt2 --init "$pt/run/checkpoint.ckpt" --mirror --seed 3 --episodes 8 --episodes-per-update 8 --envs 8 --eval-every 8 --eval-episodes 4 --out "$mir/init"
expect "eval gpt2 init mirror" 0 "head action, mirror-symmetric" -- "$sq" eval scenarios/horizontal_cr.lua --policy gpt2 --checkpoint "$mir/init/checkpoint.ckpt" --episodes 2
expect "init missing" 1 "no/such.ckpt" -- "$sq" train scenarios/horizontal_cr.lua --policy gpt2 --init no/such.ckpt --episodes 8 --out "$pt/bad_init"
expect "eval pretrained" 0 "most frequent" -- "$sq" eval scenarios/horizontal_cr.lua --policy gpt2 --checkpoint "$pt/run/checkpoint.ckpt" --episodes 2
expect "embeddings need every block" 1 "needs all 2 blocks trainable" -- "$sq" train scenarios/horizontal_cr.lua --policy gpt2 --train-embeddings --blocks 1 --episodes 8 --out "$pt/bad"
expect "render"          0 "wrote" -- "$sq" render "$tmp/ep.jsonl" --out "$tmp/r.svg"
grep -q "<circle" "$tmp/r.svg" && grep -q "<circle" "$tmp/ep.svg" && { echo "ok   svg has circles"; pass=$((pass + 1)); } || { echo "FAIL svg"; fails=$((fails + 1)); }
printf 'episodes,eval_success_rate,eval_mean_reward\n1000,0.5,-1\n2000,0.8,-0.5\n' > "$tmp/log.csv"
expect "plot"            0 "wrote" -- "$sq" plot "$tmp"
expect "render scenario" 0 "wrote" -- "$sq" render scenarios/horizontal_cr.lua --seed 4 --out "$tmp/s.svg"
expect "render bad file" 1 "episode line 1" -- "$sq" render "$tmp/log.csv" --out "$tmp/x.svg"
expect "render shipped episode" 0 "wrote" -- "$sq" render docs/demo_episode.jsonl --frame 7 --out "$tmp/docs7.svg"
expect "render seed title" 0 "wrote" -- "$sq" render scenarios/horizontal_cr.lua --seed 3 --out "$tmp/s3.svg"
grep -q ">horizontal_cr.lua, seed 3: start of its evaluation episode<" "$tmp/s3.svg" && { echo "ok   seed in the title"; pass=$((pass + 1)); } || { echo "FAIL seed title"; fails=$((fails + 1)); }
expect "render frame 999" 2 "numbered 0 to [0-9]+" -- "$sq" render "$tmp/ep.jsonl" --frame 999 --out "$tmp/x.svg"
expect "render frame -3"  2 "frame -3 does not exist" -- "$sq" render "$tmp/ep.jsonl" --frame -3 --out "$tmp/x.svg"
expect "render frame 3"   0 "wrote" -- "$sq" render "$tmp/ep.jsonl" --frame 3 --size 400 --out "$tmp/f3.svg"
grep -q ">closest [0-9.]* NM<" "$tmp/f3.svg" && { echo "ok   closest approach marked"; pass=$((pass + 1)); } || { echo "FAIL closest approach"; fails=$((fails + 1)); }
expect "render scn"      0 "wrote" -- "$sq" render scenarios/demo_conflict.scn --at 5 --out "$tmp/scn.svg"
grep -q ">KL204<" "$tmp/scn.svg" && grep -q ">AF123<" "$tmp/scn.svg" && grep -q "#dc143c" "$tmp/scn.svg" && { echo "ok   scn traffic drawn, conflict red"; pass=$((pass + 1)); } || { echo "FAIL scn traffic"; fails=$((fails + 1)); }
expect "render scn --at" 2 "--at expects seconds" -- "$sq" render scenarios/demo_conflict.scn --at -1 --out "$tmp/x.svg"
expect "render lua --at" 2 "--at applies to a .scn" -- "$sq" render scenarios/horizontal_cr.lua --at 5 --out "$tmp/x.svg"
printf 'episodes,success_rate,mean_reward\n500,0.6,-2\n1500,0.9,-0.5\n' > "$tmp/b.csv"
expect "plot two files"  0 "wrote" -- "$sq" plot "$tmp/log.csv" "$tmp/b.csv" --out "$tmp/two.svg"
[ "$(grep -c "<polyline" "$tmp/two.svg")" -eq 4 ] && { echo "ok   one line per file per panel"; pass=$((pass + 1)); } || { echo "FAIL plot two files"; fails=$((fails + 1)); }
expect "plot missing"    1 "no CSV file or run folder" -- "$sq" plot "$tmp/log.csv" "$tmp/nope.csv" --out "$tmp/x.svg"
rm -rf "$tmp"
# One translation path: an error() at the top of scripts/translate/graph.lua
# reaches every entry point that translates.
home=$(mktemp -d)
cp -r scripts prompts scenarios models "$home"/
sed -i '1i error("one path check")' "$home/scripts/translate/graph.lua"
printf 'return squawk.translate.run("KL204 climb FL300")\n' > "$home/run.lua"
h=(env SQUAWK_HOME="$home" "$sq")
expect "one path: translate" 1 "one path check" -- "${h[@]}" translate "KL204 climb FL300"
expect "one path: eval"      1 "one path check" -- "${h[@]}" eval-translate tests/data/translate_heldout.tsv
expect "one path: tsv"       1 "one path check" -- "${h[@]}" translate --tsv tests/data/translate_heldout.tsv
expect "one path: demo"      1 "one path check" -- "${h[@]}" demo --quiet
expect "one path: run"       1 "one path check" -- "${h[@]}" run "$home/run.lua"
expect "one path: repl"      1 "one path check" -- "${h[@]}" repl
nav=$(printf '!CRE KL1 A320 52 4 90 FL200 250\n' | "$sq" repl scenarios/demo_conflict.scn --navdata /nonexistent 2>&1)
grep -q "cannot open '/nonexistent/airports.dat'.*only !TrafScript works" <<<"$nav" && grep -q "ok: CRE KL1" <<<"$nav" &&
  { echo "ok   repl without navdata"; pass=$((pass + 1)); } || { echo "FAIL repl without navdata: $nav"; fails=$((fails + 1)); }
# The REPL still starts without its translator: one line says why, ! TrafScript runs.
broken=$(printf '!CRE KL1 A320 52 4 90 FL200 250\n!KL1 ALT FL300\nKL1 climb FL310\n' | "${h[@]}" repl scenarios/demo_conflict.scn 2>&1)
grep -q "the translator did not load (.*graph.lua:1: one path check); only !TrafScript works" <<<"$broken" &&
  grep -q "ok: KL1 ALT FL300" <<<"$broken" && grep -q "English needs the translator" <<<"$broken" &&
  [ "$(grep -c "stack traceback" <<<"$broken")" -eq 0 ] && { echo "ok   repl without its translator"; pass=$((pass + 1)); } ||
  { echo "FAIL repl without its translator: $broken"; fails=$((fails + 1)); }
rm -rf "$home"
expect "translate"       0 "^ALT KL204 FL300$" -- "$sq" translate "KL204 climb FL300" --setup "CRE KL204 A320 52 4 90 FL250 280"
expect "translate asks"  0 "What altitude should KL204" -- "$sq" translate "KL204 descend" --setup "CRE KL204 A320 52 4 90 FL250 280"
expect "translate names what is not simulated" 0 "squawk does not simulate transponder codes" -- "$sq" translate "KL204 squawk 7700" --setup "CRE KL204 A320 52 4 90 FL250 280"
expect "translate --jsonl carries the note" 0 '"note":"squawk does not simulate transponder codes' -- "$sq" translate "KL204 squawk 7700 and descend FL100" --setup "CRE KL204 A320 52 4 90 FL250 280" --jsonl
expect "eval right/asked/wrong" 0 "overall +76 +[0-9]+ +[0-9]+ +[0-9]+" -- "$sq" eval-translate tests/data/translate_heldout.tsv
a=$("$sq" run "$d/random.lua" --seed 11)
b=$("$sq" run "$d/random.lua" --seed 11)
c=$("$sq" run "$d/random.lua" --seed 12)
if [ -n "$a" ] && [ "$a" = "$b" ] && [ "$a" != "$c" ]; then echo "ok   seeded random"; pass=$((pass + 1));
else echo "FAIL seeded random: '$a' / '$b' / '$c'"; fails=$((fails + 1)); fi

# Ctrl-C during training: checkpoint saved, exit 130, --resume gives the
# parameters of an uninterrupted run.
sig=$(mktemp -d)
"$sq" train scenarios/horizontal_cr.lua --out "$sig/a" --episodes 4000 --eval-every 500 --eval-episodes 20 >"$sig/a.log" 2>&1 &
tpid=$!
for _ in $(seq 600); do [ -f "$sig/a/checkpoint.ckpt" ] && break; sleep 0.1; done  # after the first evaluation
kill -INT "$tpid"
wait "$tpid"
trc=$?
"$sq" train scenarios/horizontal_cr.lua --out "$sig/a" --episodes 4000 --eval-every 500 --eval-episodes 20 --resume >/dev/null 2>&1
"$sq" train scenarios/horizontal_cr.lua --out "$sig/b" --episodes 4000 --eval-every 500 --eval-episodes 20 >/dev/null 2>&1
if [ "$trc" -eq 130 ] && grep -q "interrupted:" "$sig/a.log" &&
   cmp -s <(tail -n +3 "$sig/a/policy.ckpt") <(tail -n +3 "$sig/b/policy.ckpt"); then
  echo "ok   train SIGINT + resume"; pass=$((pass + 1))
else echo "FAIL train SIGINT + resume: rc=$trc, $(cat "$sig/a.log")"; fails=$((fails + 1)); fi
# The resumed log has the uninterrupted run's rows, none twice (wall time aside).
if cmp -s <(cut -d, -f1,2,4- "$sig/a/log.csv") <(cut -d, -f1,2,4- "$sig/b/log.csv") &&
   [ "$(wc -l < "$sig/b/log.csv")" -eq 9 ]; then
  echo "ok   resumed log"; pass=$((pass + 1))
else echo "FAIL resumed log: $(cat "$sig/a/log.csv")"; fails=$((fails + 1)); fi
expect "resume other seed" 2 "--resume: --seed 9 was not given when the run started" -- \
  "$sq" train scenarios/horizontal_cr.lua --out "$sig/b" --episodes 4000 --seed 9 --resume
# --stop-at ends a run early (at the end of the update that reaches it: 32 x 64)
# on the same schedules: resumed, it matches the
# uninterrupted run too.
"$sq" train scenarios/horizontal_cr.lua --out "$sig/s" --episodes 4000 --eval-every 500 --eval-episodes 20 --stop-at 2000 >"$sig/s.log" 2>&1
src=$?
"$sq" train scenarios/horizontal_cr.lua --out "$sig/s" --episodes 4000 --eval-every 500 --eval-episodes 20 --resume >/dev/null 2>&1
if [ "$src" -eq 0 ] && grep -q "4000 episodes, stopping at 2000" "$sig/s.log" && grep -q "^done: 2048 episodes" "$sig/s.log" &&
   cmp -s <(tail -n +3 "$sig/s/policy.ckpt") <(tail -n +3 "$sig/b/policy.ckpt"); then
  echo "ok   train --stop-at + resume"; pass=$((pass + 1))
else echo "FAIL train --stop-at + resume: rc=$src, $(cat "$sig/s.log")"; fails=$((fails + 1)); fi
expect "stop-at range" 2 "train --stop-at 9: expected 1..8 \\(--episodes\\)" -- "$sq" train scenarios/horizontal_cr.lua --out "$sig/r" --episodes 8 --stop-at 9
rm -rf "$sig"

# Nothing is overwritten by accident: a folder that holds a run is refused
# unless --resume or --force; --resume takes the run's settings from DIR/run.json
# (no scenario, no flags needed) and refuses a flag that contradicts them.
ow=$(mktemp -d)
"$sq" train scenarios/horizontal_cr.lua --out "$ow/m" --episodes 256 --eval-every 128 --eval-episodes 4 --stop-at 128 --quiet
rows=$(wc -l < "$ow/m/log.csv")
expect "train refuses a run folder" 2 "--out $ow/m already holds a run \(checkpoint.ckpt, log.csv, best.ckpt, policy.ckpt\): --resume continues it, --force" -- \
  "$sq" train scenarios/horizontal_cr.lua --out "$ow/m" --episodes 64
[ "$(wc -l < "$ow/m/log.csv")" -eq "$rows" ] && { echo "ok   refused run keeps its log"; pass=$((pass + 1)); } || { echo "FAIL refused run changed its log"; fails=$((fails + 1)); }
expect "gpt2 refuses a run folder" 2 "already holds a run" -- "$sq" train scenarios/horizontal_cr.lua --policy gpt2 --out "$ow/m" --episodes 8
expect "resume contradicting lr" 2 "--resume: --lr 0.1 was not given when the run started" -- "$sq" train --out "$ow/m" --resume --lr 0.1
expect "resume other scenario" 2 "--resume: scenario scenarios/horizontal_cr_gym.lua is not the run's" -- "$sq" train scenarios/horizontal_cr_gym.lua --out "$ow/m" --resume
expect "resume and force" 2 "--resume and --force contradict" -- "$sq" train --out "$ow/m" --resume --force
expect "resume from run.json" 0 "^done: 256 episodes" -- "$sq" train --out "$ow/m" --resume
"$sq" train scenarios/horizontal_cr.lua --out "$ow/full" --episodes 256 --eval-every 128 --eval-episodes 4 --quiet
cmp -s <(tail -n +3 "$ow/m/policy.ckpt") <(tail -n +3 "$ow/full/policy.ckpt") && { echo "ok   bare --resume = the uninterrupted run"; pass=$((pass + 1)); } || { echo "FAIL bare --resume differs"; fails=$((fails + 1)); }
# --override: a recipe's next stage continues the checkpoint with new flags.
"$sq" train scenarios/horizontal_cr.lua --out "$ow/v" --episodes 256 --eval-every 128 --eval-episodes 4 --stop-at 128 --quiet
expect "resume --override" 0 "^done: 256 episodes" -- "$sq" train scenarios/horizontal_cr.lua --out "$ow/v" --episodes 256 --eval-every 128 --eval-episodes 4 --lr 1e-4 --resume --override
grep -q '"--lr": "1e-4"' "$ow/v/run.json" && ! cmp -s <(tail -n +3 "$ow/v/policy.ckpt") <(tail -n +3 "$ow/full/policy.ckpt") &&
  { echo "ok   --override trains on with the new flags, run.json records them"; pass=$((pass + 1)); } || { echo "FAIL --override: $(cat "$ow/v/run.json")"; fails=$((fails + 1)); }
expect "override needs resume" 2 "--override goes with --resume" -- "$sq" train scenarios/horizontal_cr.lua --out "$ow/o" --override
expect "train --force" 0 "^done: 64 episodes" -- "$sq" train scenarios/horizontal_cr.lua --out "$ow/m" --episodes 64 --eval-every 64 --eval-episodes 4 --force
[ "$(wc -l < "$ow/m/log.csv")" -eq 2 ] && grep -q '"--episodes": "64"' "$ow/m/run.json" && { echo "ok   --force starts over"; pass=$((pass + 1)); } || { echo "FAIL --force"; fails=$((fails + 1)); }
# render, plot and table3 --csv replace their own output, nothing else.
expect "render refuses a log" 2 "$ow/m/log.csv exists and is not a file this command wrote; --force replaces it" -- "$sq" render docs/demo_episode.jsonl --out "$ow/m/log.csv"
expect "plot refuses a log"   2 "log.csv exists and is not a file this command wrote" -- "$sq" plot "$ow/m" --out "$ow/m/log.csv"
expect "table3 refuses a log" 2 "--csv: .*log.csv exists and is not a file this command wrote" -- "$sq" table3 scenarios/horizontal_cr.lua --csv "$ow/m/log.csv"
expect "render twice"   0 "wrote" -- "$sq" render docs/demo_episode.jsonl --out "$ow/e.svg"
expect "render again"   0 "wrote" -- "$sq" render docs/demo_episode.jsonl --out "$ow/e.svg"
printf 'notes\n' > "$ow/notes.svg"
expect "render --force" 0 "wrote" -- "$sq" render docs/demo_episode.jsonl --out "$ow/notes.svg" --force
expect "plot into a folder" 2 "is a folder; expected a file name" -- "$sq" plot "$ow/m" --out "$ow/m"
rm -rf "$ow"

# Errors name the place and the fix: a .scn typo fails at file:line with the
# closest command; display-only BlueSky commands stay a listed skip; a Lua
# conflict-resolution scenario or a folder given where a .scn belongs says so.
sc=$(mktemp -d)
printf '# a typo\n00:00:00.00>CRE KL204 B744 52 4 90 FL200 250\n00:00:00.00>PAN 52 4\n00:00:05.00>ATL KL204 FL300\n' > "$sc/typo.scn"
expect "scn typo" 1 "t=5 s: .*typo.scn:4: ATL KL204 FL300: unknown command or aircraft 'ATL' - did you mean ALT\\?" -- "$sq" scn "$sc/typo.scn"
expect "scn display skip" 1 "^ +1  PAN$" -- "$sq" scn "$sc/typo.scn"
printf '00:00:00.00>CRE KL204 B744 52 4 90 FL200 250\n00:00:10.00>KL204 ALT FL9X\n' > "$sc/late.scn"
expect "scn runtime failure line" 1 "t=10 s: .*late.scn:2: KL204 ALT FL9X: " -- "$sq" scn "$sc/late.scn"
expect "scn lua scenario" 2 "horizontal_cr.lua is a Lua conflict-resolution scenario: .squawk train., .squawk eval. and .squawk table3. take it" -- "$sq" scn scenarios/horizontal_cr.lua
expect "repl lua scenario" 1 "horizontal_cr.lua is a Lua conflict-resolution scenario" -- "$sq" repl scenarios/horizontal_cr.lua
expect "scn folder" 2 "docs is a folder; expected one FILE.scn \(.squawk scn docs --conformance. runs every .scn under it\)" -- "$sq" scn docs
cp scenarios/demo_conflict.scn "$sc/"  # beside typo.scn and late.scn: three .scn files
printf 'not a scenario\n' > "$sc/README.md"
expect "conformance reads .scn only" 0 "^\| 3 \| 3 \| 3 \|" -- "$sq" scn "$sc" --conformance
rm -rf "$sc"

# LLM configuration errors name the variable and what is wrong; single and
# multi modes refuse without a server in translate as in eval-translate.
nollm=(env -u SQUAWK_LLM_URL -u SQUAWK_LLM_MODEL -u SQUAWK_LLM_API "$sq")
expect "translate multi no server" 1 "--mode multi needs an LLM server: set SQUAWK_LLM_URL" -- "${nollm[@]}" translate "KL204 climb FL300" --mode multi
expect "eval-translate single no server" 1 "--mode single needs an LLM server: set SQUAWK_LLM_URL" -- "${nollm[@]}" eval-translate tests/data/translate_heldout.tsv --mode single
expect "llm no model" 2 "LLM at http://127.0.0.1:9: no model named: set SQUAWK_LLM_MODEL" -- env -u SQUAWK_LLM_MODEL -u SQUAWK_LLM_API SQUAWK_LLM_URL=http://127.0.0.1:9 "$sq" llm chat hi
expect "translate no model" 1 "SQUAWK_LLM_\\*: LLM at http://127.0.0.1:9: no model named" -- env -u SQUAWK_LLM_MODEL -u SQUAWK_LLM_API SQUAWK_LLM_URL=http://127.0.0.1:9 "$sq" translate "KL204 climb FL300" --mode single
expect "llm no server" 2 "no LLM server named: set SQUAWK_LLM_URL" -- "${nollm[@]}" llm chat hi
expect "llm unreachable" 1 "Couldn't connect to server" -- env -u SQUAWK_LLM_API SQUAWK_LLM_URL=http://127.0.0.1:9 SQUAWK_LLM_MODEL=m "$sq" llm chat hi --timeout 5
once=$("$sq" translate "KLM one two three, climb flight level three five zero" 2>/dev/null)
[ -z "$once" ] && { echo "ok   a translation failure is said once (stderr)"; pass=$((pass + 1)); } || { echo "FAIL translate failure on stdout too: $once"; fails=$((fails + 1)); }

# `help CMD` documents every flag the parser of CMD accepts (the parser lists
# them when it meets an unknown one), and every flag on its usage lines parses;
# `--help` names all eight gpt2 actions and says train is not MLP-only.
parsed() { "$sq" "$@" --zz-unknown 2>&1 | grep -o "known: [^(]*" | head -1 | sed 's/known: //' | tr ' ' '\n' | grep -- '^--' | sort -u; }
documented() { "$sq" help "$1" | grep -oE -- '--[a-z][a-z0-9-]*' | sort -u; }
usage_flags() { "$sq" help "$1" | sed '/^$/q' | grep -oE -- '--[a-z][a-z0-9-]*' | sort -u; }
help_check() {  # HELPNAME PARSER-ARGV...; the union of the given parsers against one help text
  local name=$1; shift
  local p="" undocumented unparsed
  while [ $# -gt 0 ]; do p+=$(parsed $1 | tr '\n' ' ')" "; shift; done
  p=$(tr ' ' '\n' <<<"$p" | grep -- '^--' | sort -u)
  undocumented=$(comm -23 <(echo "$p") <(documented "$name") | tr '\n' ' ')
  unparsed=$(comm -13 <(echo "$p") <(usage_flags "$name") | tr '\n' ' ')
  if [ -n "$p" ] && [ -z "${undocumented// }" ] && [ -z "${unparsed// }" ]; then echo "ok   help $name matches the parser"; pass=$((pass + 1))
  else echo "FAIL help $name: parsed but not in help: [$undocumented]; in usage but not parsed: [$unparsed]"; fails=$((fails + 1)); fi
}
for c in demo test render plot repl serve scn commands translate eval-translate eval table3 llm rag; do help_check $c $c; done
help_check train train "train --policy gpt2"
help_check gpt2 "gpt2 info" "gpt2 pretrain" "gpt2 imitate"
expect "help lists gpt2 actions" 0 "gpt2 info\|generate\|logits\|bench\|init\|train-bpe\|pretrain\|imitate" -- "$sq" --help
expect "help train both learners" 0 "train a conflict-resolution policy \(MLP, or --policy gpt2\)" -- "$sq" --help
expect "help train files" 0 "the MLP learner also writes best.ckpt" -- "$sq" help train

finish
