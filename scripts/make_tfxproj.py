"""A TressFX project of the project's own making, as AMD's exporters write one: a groom exported by
csmhair (--export-hair, a .hair in metres, y up, face +z) cut by where each root is into a front,
two sides and a back, and a tail of 40 strands hanging from a tie just behind the head, tied at both
ends; then as DirectX has it: left-handed (z turned, the face toward -z), in centimetres, the head
1.5 m up. Writes DIR/ours.tfxproj with its pieces (TressFX 3.0 binaries, the tail 4.0 with its ends
pinned), a .tfxsim a piece, follow hairs a guide and a collision sphere about the head.

  /usr/bin/python3 scripts/make_tfxproj.py GROOM.hair DIR"""
import os
import struct
import sys

import numpy as np

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
import hair_file  # noqa: E402

POINTS = 16  # vertices a strand, as AMD's exporters resample them


def to_file(p):
    """Head frame (metres, right-handed, face +z) to the files' (centimetres, face -z, 1.5 m up)."""
    q = np.asarray(p, dtype=np.float64) * 100.0
    return np.stack([q[..., 0], q[..., 1] + 150.0, -q[..., 2]], axis=-1)


def resample(points, n=POINTS):
    seg = np.linalg.norm(np.diff(points, axis=0), axis=1)
    arc = np.concatenate([[0.0], np.cumsum(seg)])
    at = np.linspace(0.0, arc[-1], n)
    return np.stack([np.interp(at, arc, points[:, k]) for k in range(3)], axis=1)


def write_tfx3(path, strands):
    header = bytearray(296)
    struct.pack_into("<fII", header, 0, 3.0, len(strands), POINTS)
    struct.pack_into("<I", header, 144, 296)
    body = np.concatenate(strands).astype("<f4").tobytes()
    open(path, "wb").write(bytes(header) + body)


def write_tfx4_tied(path, strands):
    header = bytearray(160)
    struct.pack_into("<fIII", header, 0, 4.0, len(strands), POINTS, 160)
    rows = []
    for s in strands:
        w = np.ones((POINTS, 1))
        w[0] = w[-1] = 0.0  # inverse mass 0: the root and the tip pinned
        rows.append(np.hstack([s, w]))
    open(path, "wb").write(bytes(header) + np.concatenate(rows).astype("<f4").tobytes())


def main():
    groom, out = sys.argv[1], sys.argv[2]
    os.makedirs(out, exist_ok=True)
    xyz, first = hair_file.read(groom)
    pieces = {"front_top": [], "side_left": [], "side_right": [], "back": [], "tail": []}
    for s in range(len(first) - 1):
        pts = xyz[first[s]:first[s + 1]].astype(np.float64)
        root = pts[0]
        name = ("front_top" if root[2] > 0.04 else "back" if root[2] < -0.03 else
                "side_left" if root[0] > 0.0 else "side_right")
        pieces[name].append(to_file(resample(pts)))
        if name == "back" and len(pieces["tail"]) < 40:
            tie = np.array([0.3 * root[0], 0.0, -0.115])
            k = np.arange(POINTS)[:, None] / (POINTS - 1)
            tail = tie + k * np.array([0.0, -0.24, -0.05])
            pieces["tail"].append(to_file(tail))
    lines = ["version 3.0", "project_name ours", "# made by scripts/make_tfxproj.py"]
    follow = {"front_top": "2 0.4 1", "side_left": "2 0.4 1", "side_right": "2 0.4 1",
              "back": "3 0.5 1", "tail": "4 0.3 0.5"}
    for name, strands in pieces.items():
        (write_tfx4_tied if name == "tail" else write_tfx3)(os.path.join(out, name + ".tfx"),
                                                           strands)
        open(os.path.join(out, name + ".tfxsim"), "w").write(
            "version 3.0\ndamping 0.06\nstiffnessForLocalShapeMatching 0.9\n"
            "stiffnessForGlobalShapeMatching 0.2\nglobalShapeMatchingEffectiveRange 0.3\n")
        lines.append(f"{name}.tfx {follow[name]} {name}.tfxsim {name}")
        print(f"{name}.tfx: {len(strands)} strands")
    lines.append("collision_sphere 0 150 0 10")
    open(os.path.join(out, "ours.tfxproj"), "w").write("\r\n".join(lines) + "\r\n")


if __name__ == "__main__":
    main()
