#!/usr/bin/python3
"""Share of aircraft within 1 km and 200 ft of BlueSky at 900 s, from the JSON
that ../shared/bluesky_ref/compare.py writes (--json-out).

    share.py RESULT.json...
"""
import json
import sys


def share(path, t_s=900.0, pos_m=1000.0, alt_ft=200.0):
    results = json.load(open(path))
    n = ok = files = 0
    for r in results:
        if 'error' in r:
            continue
        for t in r['times']:
            if t['t'] != t_s or t.get('note') or not t.get('aircraft'):
                continue
            files += 1
            for a in t['aircraft']:
                n += 1
                ok += abs(a['pos_m']) <= pos_m and abs(a['alt_ft']) <= alt_ft
    return ok, n, files


if __name__ == '__main__':
    if len(sys.argv) < 2:
        sys.exit(__doc__)
    for path in sys.argv[1:]:
        ok, n, files = share(path)
        print(f'{path}: {ok}/{n} aircraft within 1 km and 200 ft at 900 s '
              f'({100 * ok / max(n, 1):.1f} %), {files} files with aircraft in common')
