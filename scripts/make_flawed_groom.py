#!/usr/bin/env python3
"""Writes a TressFX 4.x groom with the flaws of a real one, for the import benchmark
(docs/BENCHMARKS.md, "Grooms from other tools"): 2,228 strands x 32 points in metres, lengths
4 mm to 30 cm with a median of 8 cm, one strand 7.5 um long, and one whose 31 segments are each
shorter than a micrometre. Deterministic.
  python3 scripts/make_flawed_groom.py OUT.tfx"""
import math
import random
import struct
import sys

STRANDS, POINTS = 2228, 32


def main():
    out = sys.argv[1] if len(sys.argv) > 1 else "flawed.tfx"
    rnd = random.Random(38)
    golden = 2.399963229728653
    positions = []
    for s in range(STRANDS):
        # Roots on the upper cap of a 10 cm sphere; strand lengths log-normal about 8 cm.
        z = 1.0 - 0.95 * (s + 0.5) / STRANDS
        r = math.sqrt(1.0 - z * z)
        n = (r * math.cos(golden * s), z, r * math.sin(golden * s))
        length = min(0.30, max(0.004, 0.08 * math.exp(rnd.gauss(0.0, 0.7))))
        if s == 100:
            length = 7.5e-6
        root = tuple(0.1 * c for c in n)
        pts = []
        for i in range(POINTS):
            t = i / (POINTS - 1)
            if s == 200:  # 31 segments under a micrometre
                t *= 30e-6 / length
            # Out along the normal, then down.
            d = (n[0] * (1 - t), n[1] * (1 - t) - t, n[2] * (1 - t))
            k = math.sqrt(sum(c * c for c in d)) or 1.0
            pts.append(tuple(root[j] + length * t * d[j] / k for j in range(3)))
        positions += pts
    header = struct.pack("<fII", 4.0, STRANDS, POINTS)
    header += struct.pack("<5I", 160, 0, 0, 0, 0)
    header = header.ljust(160, b"\0")
    body = b"".join(struct.pack("<ffff", *p, 0.0 if i % POINTS < 2 else 1.0)
                    for i, p in enumerate(positions))
    with open(out, "wb") as f:
        f.write(header + body)
    print("%s: %d strands x %d points" % (out, STRANDS, POINTS))


if __name__ == "__main__":
    main()
