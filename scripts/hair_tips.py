#!/usr/bin/env python3
"""Distances between the strand tips of two cyHair files with the same strands, in mm:
prints "mean / median / max / RMS" (sim/groom/cyhair.h has the format)."""
import math
import struct
import sys


def tips(path):
    data = open(path, "rb").read()
    count, points, arrays, default_segments = struct.unpack_from("<4I", data, 4)
    offset = 128
    segments = [default_segments] * count
    if arrays & 1:
        segments = list(struct.unpack_from(f"<{count}H", data, offset))
        offset += 2 * count
    xyz = struct.unpack_from(f"<{3 * points}f", data, offset)
    out, end = [], 0
    for s in segments:
        end += s + 1
        out.append(xyz[3 * (end - 1):3 * end])
    return out


a, b = tips(sys.argv[1]), tips(sys.argv[2])
if len(a) != len(b):
    sys.exit(f"{sys.argv[1]} has {len(a)} strands, {sys.argv[2]} has {len(b)}")
d = sorted(1000.0 * math.dist(p, q) for p, q in zip(a, b))
rms = math.sqrt(sum(x * x for x in d) / len(d))
print(f"{sum(d) / len(d):.1f} / {d[len(d) // 2]:.1f} / {d[-1]:.0f} / {rms:.1f}")
