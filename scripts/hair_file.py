"""A cyHair file as --export-hair writes it, for the benchmark scripts: read(path) gives the points
(float32, one row each, metres) and the strands' first points (strand s: first[s] to first[s + 1])."""
import struct

import numpy as np


def read(path):
    data = open(path, "rb").read()
    hairs, points, flags = struct.unpack_from("<III", data, 4)
    off = 128
    if flags & 1:
        segs = np.frombuffer(data, "<u2", hairs, off) + 1
        off += 2 * hairs
    else:
        segs = np.full(hairs, struct.unpack_from("<I", data, 16)[0] + 1)
    xyz = np.frombuffer(data, "<f4", 3 * points, off).reshape(-1, 3)
    first = np.concatenate([[0], np.cumsum(segs.astype(np.int64))]).astype(np.int64)
    return xyz, first
