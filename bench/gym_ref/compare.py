#!/usr/bin/python3
"""Step-by-step agreement of squawk's Lua environments with BlueSky-Gym's own
environment code running on the real BlueSky.

    /usr/bin/python3 bench/gym_ref/compare.py [--env descent] [--episodes 30] [--seed 0]
        [--steps N] [--gym-src DIR] [--squawk build/squawk] [--json-out FILE]

BlueSky-Gym side: the environment's Python file (bluesky_gym/envs/<env>.py)
from --gym-src ($BSGYM_SRC: a bluesky-gym checkout or bare git dir), run on
the BlueSky tree that ../shared/bluesky_ref/setup.sh made ($BSREF_PREFIX,
default ~/.cache/squawk-bsref) with BlueSky's default settings. Where the
`gymnasium` package is missing a minimal stand-in for gymnasium.Env and
gymnasium.spaces.Box/Dict is used (the env only declares spaces with them),
and pygame (rendering only) is stubbed. Episodes draw their start from numpy's
global generator (and Python's `random`) seeded with --seed; actions come from
a separate generator: episode k uses a random policy U(-1, 1) per component
when k % 3 == 0, the action 0 when k % 3 == 1 and -1 when k % 3 == 2 (the
descent's crash branch; full left turn and slowing down in the sector and
the merge). An episode ends at termination, truncation or the registration's
max_episode_steps (or --steps, a quick check).

squawk side: the recorded draws (every random number a reset draws, in
order: np.random.randint, or np.random.uniform/normal, or random.uniform) and actions are replayed through the Lua
environment (bench/gym_ref/replay.lua) with the same OpenAP data
($BSREF_PREFIX/openap/openap/data). Observations are compared component by
component after gymnasium's flattening (keys sorted), with rewards,
termination and truncation, and the maximum differences printed (also in physical units).

Exit status: 0 when every difference is within the tolerances below, 1 when
one is not, 77 (skip) when the reference is absent (ctest's gym_ref_* tests
run it briefly where it is there; CI has no reference and skips them).
"""
import argparse
import importlib.util
import json
import os
import random
import subprocess
import sys
import tempfile
import time
import types
from pathlib import Path

ROOT = Path(__file__).resolve().parents[2]
PREFIX = Path(os.environ.get('BSREF_PREFIX', Path(os.environ.get('XDG_CACHE_HOME', Path.home() / '.cache')) / 'squawk-bsref'))
SKIP = 77

# Per environment: the Python source, its class, the Lua file, the flattened
# observation's components with the scale back to physical units, and the
# tolerances (in observation units) the agreement is held to.
ENVS = {
    'descent': dict(
        gym_file='bluesky_gym/envs/descent_env.py', cls='DescentEnv', lua='envs/descent.lua',
        fields=[('altitude', 1, 3000, 'm'), ('runway_distance', 1, 200, 'km'),
                ('target_altitude', 1, 3000, 'm'), ('vz', 1, 5, 'm/s')],
        tolerance=dict(obs=1e-9, reward=1e-9),
    ),
    'vertical_cr': dict(
        gym_file='bluesky_gym/envs/vertical_cr_env.py', cls='VerticalCREnv', lua='envs/vertical_cr.lua',
        fields=[('altitude', 1, 3000, 'm'), ('altitude_difference', 5, 3000, 'm'),
                ('cos_difference_pos', 5, 1, ''), ('intruder_distance', 5, 200, 'km'),
                ('runway_distance', 1, 200, 'km'), ('sin_difference_pos', 5, 1, ''),
                ('target_altitude', 1, 3000, 'm'), ('vz', 1, 5, 'm/s'),
                ('x_difference_speed', 5, 150, 'm/s'), ('y_difference_speed', 5, 150, 'm/s'),
                ('z_difference_speed', 5, 1, 'm/s')],
        tolerance=dict(obs=1e-9, reward=1e-9),
    ),
}

# Horizontal single-aircraft environments: actions of more than one number,
# their own episode limits, and (StaticObstacle) polygons drawn with
# np.random.uniform, recorded and replayed like the randint draws.
ENVS.update({
    'plan_waypoint': dict(
        gym_file='bluesky_gym/envs/plan_waypoint_env.py', cls='PlanWaypointEnv', lua='envs/plan_waypoint.lua',
        fields=[('cos_difference', 5, 1, ''), ('sin_difference', 5, 1, ''),
                ('waypoint_distance', 5, 75, 'km'), ('waypoint_reached', 5, 1, '')],
        tolerance=dict(obs=1e-9, reward=1e-9),
    ),
    'static_obstacle': dict(
        gym_file='bluesky_gym/envs/static_obstacle_env.py', cls='StaticObstacleEnv', lua='envs/static_obstacle.lua',
        fields=[('cos_difference_restricted_area_pos', 10, 1, ''), ('destination_waypoint_cos_drift', 1, 1, ''),
                ('destination_waypoint_distance', 1, 170, 'km'), ('destination_waypoint_sin_drift', 1, 1, ''),
                ('restricted_area_distance', 10, 170, 'km'), ('restricted_area_radius', 10, 50, 'NM'),
                ('sin_difference_restricted_area_pos', 10, 1, '')],
        tolerance=dict(obs=1e-9, reward=1e-9),
        action_size=2, max_episode_steps=100, draws=('randint', 'uniform'),
    ),
})


def plan_waypoint_unaimed(obs):
    """The cos/sin components (0-9) of PlanWaypoint's unreached waypoints
    that sit on the aircraft (drawn 0 km away; less than 1 mm off): their
    bearing is the direction of a rounding error, and the aircraft's position
    after an episode carried over agrees only to ~1e-15 deg."""
    dist, reached = obs[10:15], obs[15:20]
    return [i for w in range(5) if dist[w] * 75 < 1e-6 and not reached[w] for i in (w, 5 + w)]


ENVS['plan_waypoint'].update(unaimed=plan_waypoint_unaimed,
                             unaimed_note='cos/sin of a waypoint drawn 0 km away, on the aircraft')

# SectorCREnv-v0 and MergeEnv-v0: two actions (heading, speed), draws from
# numpy's uniform/normal (sector) and Python's random.uniform (merge), and
# episodes that can also end by truncation (the sector's agent leaving it).
ENVS.update({
    'sector_cr': dict(
        gym_file='bluesky_gym/envs/sector_cr_env.py', cls='SectorCREnv', lua='envs/sector_cr.lua',
        fields=[('airspeed', 1, 6, 'm/s'), ('cos(drift)', 1, 1, ''), ('cos(track)', 4, 1, ''),
                ('distances', 4, 15000, 'm'), ('sin(drift)', 1, 1, ''), ('sin(track)', 4, 1, ''),
                ('vx_r', 4, 32, 'm/s'), ('vy_r', 4, 66, 'm/s'), ('x_r', 4, 13000, 'm'), ('y_r', 4, 13000, 'm')],
        draws=('uniform', 'normal'),
        action_size=2, max_episode_steps=200,
        tolerance=dict(obs=1e-9, reward=1e-9),
    ),
    'merge': dict(
        gym_file='bluesky_gym/envs/merge_env.py', cls='MergeEnv', lua='envs/merge.lua',
        fields=[('airspeed', 1, 1, 'm/s'), ('cos(drift)', 1, 1, ''), ('cos(track)', 5, 1, ''),
                ('distances', 5, 250, 'NM'), ('faf_reached', 1, 1, ''), ('sin(drift)', 1, 1, ''),
                ('sin(track)', 5, 1, ''), ('vx_r', 5, 150, 'm/s'), ('vy_r', 5, 150, 'm/s'),
                ('waypoint_dist', 1, 250, 'NM'), ('x_r', 5, 1e6, 'm'), ('y_r', 5, 1e6, 'm')],
        draws=(), python_draws=('uniform',),
        action_size=2, max_episode_steps=50,
        # BlueSky's compiled kwikdist_matrix takes equal-length vectors: given the
        # ownship's scalar position (merge_env.py:194) it returns one distance and
        # reset fails; the env runs on BlueSky's default Python geo functions.
        python_geo=True,
        tolerance=dict(obs=1e-9, reward=1e-9),
    ),
})


def skip(msg):
    print(f'compare.py: skipped: {msg}')
    sys.exit(SKIP)


def gym_source(src: str, rel: str) -> tuple[str, str]:
    """The text of `rel` in a checkout or bare git dir, and the commit (or '?')."""
    p = Path(src)
    if (p / rel).is_file():
        return (p / rel).read_text(), '?'
    try:
        text = subprocess.run(['git', '--git-dir', str(p), 'show', f'HEAD:{rel}'], check=True,
                              capture_output=True, text=True).stdout
        commit = subprocess.run(['git', '--git-dir', str(p), 'rev-parse', 'HEAD'], check=True,
                                capture_output=True, text=True).stdout.strip()
        return text, commit
    except (subprocess.CalledProcessError, FileNotFoundError):
        skip(f'no {rel} in {src} (a bluesky-gym checkout or git dir)')


def install_stand_ins():
    try:
        import gymnasium  # noqa: F401
    except ImportError:
        gym = types.ModuleType('gymnasium')
        spaces = types.ModuleType('gymnasium.spaces')

        class Box:
            def __init__(self, low, high, shape=None, dtype=None):
                self.low, self.high, self.shape, self.dtype = low, high, shape, dtype

        class Dict:
            def __init__(self, d):
                self.spaces = dict(sorted(d.items()))  # gymnasium sorts a plain dict's keys

        class Env:
            def reset(self, seed=None, options=None):
                return None

        spaces.Box, spaces.Dict = Box, Dict
        gym.Env, gym.spaces = Env, spaces
        sys.modules['gymnasium'], sys.modules['gymnasium.spaces'] = gym, spaces
    if 'pygame' not in sys.modules:
        try:
            import pygame  # noqa: F401
        except ImportError:
            sys.modules['pygame'] = types.ModuleType('pygame')


def install_gym_common(gym_src):
    """bluesky_gym.envs.common.functions from the same source (the envs import
    it; the package's own __init__ would import gymnasium's registry)."""
    rel = 'bluesky_gym/envs/common/functions.py'
    text, _ = gym_source(gym_src, rel)
    for name in ('bluesky_gym', 'bluesky_gym.envs', 'bluesky_gym.envs.common'):
        pkg = types.ModuleType(name)
        pkg.__path__ = []
        sys.modules.setdefault(name, pkg)
    mod = types.ModuleType('bluesky_gym.envs.common.functions')
    exec(compile(text, rel, 'exec'), mod.__dict__)
    sys.modules[mod.__name__] = mod
    sys.modules['bluesky_gym.envs.common'].functions = mod


def run_reference(spec, source, episodes, seed, gym_src, steps=None):
    """Episodes of BlueSky-Gym's env: per episode the start, actions, flat
    observations (reset's first), rewards and termination flags."""
    import numpy as np
    sys.path[:0] = [str(PREFIX / 'bluesky'), str(PREFIX / 'openap')]
    install_stand_ins()
    install_gym_common(gym_src)
    import bluesky as bs
    bs.init(mode='sim', detached=True, workdir=str(PREFIX / 'workdir'))
    if spec.get('python_geo'):  # BlueSky's default (settings prefer_compiled = False)
        from bluesky.tools.geo import _geo
        for name in ('kwikdist', 'kwikdist_matrix', 'kwikqdrdist', 'kwikqdrdist_matrix'):
            setattr(bs.tools.geo, name, getattr(_geo, name))
    with tempfile.TemporaryDirectory() as tmp:
        f = Path(tmp) / Path(spec['gym_file']).name
        f.write_text(source)
        mod_spec = importlib.util.spec_from_file_location('bsgym_env', f)
        mod = importlib.util.module_from_spec(mod_spec)
        mod_spec.loader.exec_module(mod)
    env = getattr(mod, spec['cls'])()
    keys = [f[0] for f in spec['fields']]
    flat = lambda o: [float(v) for k in keys for v in np.asarray(o[k], dtype=float).reshape(-1)]
    # every random number reset draws, in order: the episode's draws (spec
    # 'draws': np.random functions, default randint; 'python_draws': functions
    # of Python's random)
    draws, recording = [], [False]
    sources = [(np.random, f) for f in spec.get('draws', ('randint',))] + \
        [(random, f) for f in spec.get('python_draws', ())]
    for module, fname in sources:

        def recorder(*a, _f=getattr(module, fname), **kw):
            v = _f(*a, **kw)
            if recording[0]:
                draws.append(v.item() if hasattr(v, 'item') else v)
            return v
        setattr(module, fname, recorder)
    np.random.seed(seed)
    random.seed(seed)
    act_rng = np.random.RandomState(seed + 1)
    n_act = spec.get('action_size', 1)
    # the registration's max_episode_steps, or fewer (--steps)
    max_steps = min(steps or 10**9, spec.get('max_episode_steps', 300))
    out = []
    for k in range(episodes):
        draws.clear()
        recording[0] = True
        obs, _ = env.reset()
        recording[0] = False
        ep = dict(draws=list(draws), obs=[flat(obs)], rewards=[], terminated=[], truncated=[], actions=[])
        for _ in range(max_steps):
            a = act_rng.uniform(-1, 1, size=n_act) if k % 3 == 0 else np.full(n_act, 0.0 if k % 3 == 1 else -1.0)
            t0 = time.perf_counter()
            obs, r, term, trunc, _ = env.step(a)
            ep['step_s'] = ep.get('step_s', 0.0) + time.perf_counter() - t0
            ep['actions'].append([float(v) for v in a])
            ep['obs'].append(flat(obs))
            ep['rewards'].append(float(r))
            ep['terminated'].append(bool(term))
            ep['truncated'].append(bool(trunc))
            if term or trunc:
                break
        out.append(ep)
    return out


def run_squawk(spec, ref, squawk):
    with tempfile.TemporaryDirectory() as tmp:
        trace = Path(tmp) / 'trace.txt'
        with open(trace, 'w') as f:
            for k, ep in enumerate(ref):
                f.write(f'episode {k} draws=' + ','.join(repr(v) for v in ep['draws']) + '\n')
                for a in ep['actions']:
                    a = a if isinstance(a, list) else [a]  # a --reference file from before 2-D actions
                    f.write('action ' + ' '.join(repr(v) for v in a) + '\n')
        cmd = [squawk, 'run', str(ROOT / 'bench/gym_ref/replay.lua'), str(ROOT / spec['lua']), str(trace),
               '--allow-read', tmp, '--openap', str(PREFIX / 'openap/openap/data')]
        res = subprocess.run(cmd, capture_output=True, text=True)
    if res.returncode != 0:
        sys.exit(f'compare.py: {" ".join(cmd)} failed:\n{res.stderr}')
    got, timing = {}, None
    for line in res.stdout.splitlines():
        if line.startswith('time '):  # CPU seconds in the Lua env's step(), and the steps
            t = line.split()
            timing = (float(t[1]), int(t[3]))
        if not line.startswith('obs '):
            continue
        head, tail = line.split(' | ')
        parts = head.split()
        k, step = int(parts[1]), int(parts[2])
        t = tail.split()
        got[(k, step)] = ([float(v) for v in parts[3:]], float(t[1]), t[3] == 'true', t[5] == 'true')
    return got, timing


def main():
    ap = argparse.ArgumentParser(description=__doc__.split('\n')[0])
    ap.add_argument('--env', default='descent', choices=sorted(ENVS))
    ap.add_argument('--episodes', type=int, default=30)
    ap.add_argument('--seed', type=int, default=0)
    ap.add_argument('--steps', type=int, help='cut each episode after this many steps (a quick check)')
    ap.add_argument('--gym-src', default=os.environ.get('BSGYM_SRC', str(ROOT.parent / 'shared' / 'bluesky-gym')))
    ap.add_argument('--squawk', default=os.environ.get('SQUAWK', str(ROOT / 'build' / 'squawk')))
    ap.add_argument('--reference', type=Path,
                    help='reuse the BlueSky-Gym episodes in this JSON file when it exists, else record them there')
    ap.add_argument('--json-out', type=Path)
    a = ap.parse_args()
    spec = ENVS[a.env]
    if not (a.reference and a.reference.exists()) and not (PREFIX / 'bluesky' / 'bluesky' / '__init__.py').exists():
        skip(f'no BlueSky tree at {PREFIX} (run ../shared/bluesky_ref/setup.sh)')
    reused = bool(a.reference and a.reference.exists())
    if reused:
        saved = json.loads(a.reference.read_text())
        ref, commit = saved['episodes'], saved['commit']
    else:
        source, commit = gym_source(a.gym_src, spec['gym_file'])
        ref = run_reference(spec, source, a.episodes, a.seed, a.gym_src, a.steps)
        if a.reference:
            a.reference.write_text(json.dumps(dict(env=a.env, seed=a.seed, commit=commit, episodes=ref)))
    if not Path(a.squawk).exists():
        skip(f'no squawk binary at {a.squawk}')
    got, timing = run_squawk(spec, ref, a.squawk)

    # component index -> field
    owner = [f for f in spec['fields'] for _ in range(f[1])]
    worst = {f[0]: (0.0, None) for f in spec['fields']}
    worst_r, length_mismatch, term_mismatch, steps, skipped = (0.0, None), [], [], 0, 0
    for k, ep in enumerate(ref):
        n_ref = len(ep['rewards'])
        n_got = max(s for (kk, s) in got if kk == k)
        if n_got != n_ref:
            length_mismatch.append((k, n_ref, n_got))
        for s in range(min(n_ref, n_got) + 1):
            obs, r, term, trunc = got[(k, s)]
            unaimed = spec.get('unaimed', lambda o: [])(ep['obs'][s])
            skipped += len(unaimed)
            for i, f in enumerate(owner):
                if i in unaimed:
                    continue
                d = abs(obs[i] - ep['obs'][s][i])
                if d > worst[f[0]][0]:
                    worst[f[0]] = (d, (k, s))
            if s == 0:
                continue
            steps += 1
            d = abs(r - ep['rewards'][s - 1])
            if d > worst_r[0]:
                worst_r = (d, (k, s))
            if term != ep['terminated'][s - 1] or trunc != ep.get('truncated', [False] * s)[s - 1]:
                term_mismatch.append((k, s))
    tol = spec['tolerance']
    ok = not length_mismatch and not term_mismatch and worst_r[0] <= tol['reward']
    print(f'{spec["cls"]} ({spec["gym_file"]} @ {commit[:7]}) vs {spec["lua"]}: {len(ref)} episodes, '
          f'{steps} steps, seed {a.seed}')
    print('| quantity | max abs difference | in units | at (episode, step) | tolerance |')
    print('|---|---|---|---|---|')
    for n, _, scale, unit in spec['fields']:
        d, where = worst[n]
        ok = ok and d <= tol['obs']
        print(f'| {n} | {d:.3g} | {d * scale:.3g} {unit} | {where} | {tol["obs"]:g} |')
    print(f'| reward | {worst_r[0]:.3g} | | {worst_r[1]} | {tol["reward"]:g} |')
    print(f'episode lengths differing: {length_mismatch or "none"}; termination or truncation differing: {term_mismatch or "none"}')
    if skipped:
        print(f'not compared: {skipped} components without a defined direction ({spec["unaimed_note"]})')
    lengths = [len(ep['rewards']) for ep in ref]
    print(f'reference episode lengths: min {min(lengths)}, max {max(lengths)}; BlueSky-Gym '
          f'{sum(lengths) / sum(ep["step_s"] for ep in ref):.1f} env steps/s (step() only, '
          f'{"the recorded run" if reused else "this run"})')
    if timing:
        print(f'squawk {spec["lua"]} on the same episodes: {timing[1] / timing[0]:.0f} env steps/s '
              f'(step() only, CPU time)')
    if a.json_out:
        a.json_out.write_text(json.dumps(dict(reference=ref, worst=worst, reward=worst_r), indent=1))
    print('within tolerance' if ok else 'OUTSIDE TOLERANCE')
    sys.exit(0 if ok else 1)


if __name__ == '__main__':
    main()
