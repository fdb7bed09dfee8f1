#!/usr/bin/python3
"""Step time of the real BlueSky and of squawk on the same whole-world scenarios.

For each aircraft count N: scenarios/whole_world.lua writes N airborne flights
(seed 1, no later commands; ASAS ON, 5 NM / 1000 ft / 300 s, detection every
1 s); BlueSky (through ../shared/bluesky_ref/run_bluesky.py, OpenAP, compiled
CD) and `squawk scn` (OpenAP from $SQUAWK_OPENAP when set) each run it to T0
and to T0 + S seconds (squawk to T0 + 20 S); the difference of their wall-clock times over S is the
cost of a simulated second, without start-up and loading. Prints the ratio.
Wall-clock times: run on an otherwise idle machine.

Usage: bench/bluesky_side_by_side.py [--squawk build/squawk] [--navdata DIR]
                                     [--counts 100 1000 5000] [--seconds 10 5 2]
Needs BlueSky set up by ../shared/bluesky_ref/setup.sh ($BSREF_PREFIX, default
~/.cache/squawk-bsref).
"""
import argparse
import json
import os
import subprocess
import tempfile
import time
from pathlib import Path

ROOT = Path(__file__).resolve().parent.parent
REF = ROOT.parent / 'shared' / 'bluesky_ref' / 'run_bluesky.py'


def squawk_wall(sq, scn, nav, until):
    t0 = time.perf_counter()
    subprocess.run([sq, 'scn', scn, '--navdata', nav, '--until', str(until)], capture_output=True, check=True)
    return time.perf_counter() - t0


def bluesky_wall(scn, until, tmp):
    out = Path(tmp) / 'bs.json'
    subprocess.run(['/usr/bin/python3', str(REF), '--scn', scn, '--times', str(until), '-o', str(out)],
                   capture_output=True, text=True, check=True)
    data = json.loads(out.read_text())
    meta = data.get('meta', data)
    return float(meta['wall_s'])


def main():
    ap = argparse.ArgumentParser(description=__doc__.split('\n')[0])
    ap.add_argument('--squawk', default=str(ROOT / 'build' / 'squawk'))
    ap.add_argument('--navdata', default=str(ROOT.parent / 'shared' / 'bluesky' / 'navdata'))
    ap.add_argument('--counts', type=int, nargs='+', default=[100, 1000, 5000])
    ap.add_argument('--seconds', type=float, nargs='+', default=[10, 5, 2],
                    help='simulated seconds timed per count (one value per count)')
    ap.add_argument('--t0', type=float, default=1.0, help='sim time reached before timing starts')
    a = ap.parse_args()
    secs = a.seconds if len(a.seconds) == len(a.counts) else [a.seconds[0]] * len(a.counts)
    print(f'BlueSky (OpenAP, compiled CD) and squawk ({"OpenAP " + os.environ["SQUAWK_OPENAP"] if os.environ.get("SQUAWK_OPENAP") else "class performance model"}), '
          'whole-world traffic, dt 0.05 s, CD every 1 s; wall-clock s per simulated s')
    print(f'{"aircraft":>8} {"sim s":>6} {"BlueSky":>10} {"squawk":>10} {"ratio":>8}')
    with tempfile.TemporaryDirectory() as tmp:
        for n, s in zip(a.counts, secs):
            name = f'ww_{n}.scn'
            subprocess.run([a.squawk, 'run', str(ROOT / 'scenarios' / 'whole_world.lua'), str(n), '0', name, 'quiet',
                            '--navdata', a.navdata, '--out', tmp, '--seed', '1'], check=True)
            scn = str(Path(tmp) / name)
            bs = (bluesky_wall(scn, a.t0 + s, tmp) - bluesky_wall(scn, a.t0, tmp)) / s
            s_sq = 20 * s
            sq = (squawk_wall(a.squawk, scn, a.navdata, a.t0 + s_sq) - squawk_wall(a.squawk, scn, a.navdata, a.t0)) / s_sq
            print(f'{n:>8} {s:>6g} {bs:>10.4f} {sq:>10.5f} {bs / max(sq, 1e-9):>7.0f}x', flush=True)


if __name__ == '__main__':
    main()
