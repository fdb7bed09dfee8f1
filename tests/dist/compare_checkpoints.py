#!/usr/bin/env python3
"""Compares two squawk checkpoints (rl/checkpoint_file.h: magic line, JSON
header line, float32 arrays): the headers must agree except for wall_s, and
the arrays within --tol (largest absolute difference over the largest
magnitude). Prints "bit-identical" or the largest difference; exit 1 when
they differ beyond --tol."""
import argparse
import array
import json
import sys


def load(path):
    data = open(path, "rb").read()
    magic_end = data.index(b"\n")
    header_end = data.index(b"\n", magic_end + 1)
    header = json.loads(data[magic_end + 1:header_end])
    header.pop("wall_s", None)
    floats = array.array("f")
    floats.frombytes(data[header_end + 1:])
    if sys.byteorder != "little":
        floats.byteswap()
    return data[:magic_end], header, floats


def main():
    ap = argparse.ArgumentParser()
    ap.add_argument("a")
    ap.add_argument("b")
    ap.add_argument("--tol", type=float, default=1e-4)
    args = ap.parse_args()
    ma, ha, xa = load(args.a)
    mb, hb, xb = load(args.b)
    if ma != mb or ha != hb or len(xa) != len(xb):
        print(f"{args.a} and {args.b}: different kinds, headers or sizes:\n{ha}\n{hb}")
        return 1
    if xa.tobytes() == xb.tobytes():
        print(f"bit-identical: {len(xa)} floats")
        return 0
    diff = max(abs(a - b) for a, b in zip(xa, xb))
    scale = max(abs(a) for a in xa) or 1.0
    differing = sum(a != b for a, b in zip(xa, xb))
    print(f"largest difference {diff:.3g} ({diff / scale:.3g} of the largest magnitude {scale:.3g}); "
          f"{differing} of {len(xa)} floats differ")
    return 0 if diff / scale <= args.tol else 1


if __name__ == "__main__":
    sys.exit(main())
