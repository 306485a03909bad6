"""A groom as a data set ships it beside its head: a groom exported by csmhair (--export-hair, a
.hair in the head frame: metres, y up, face +z) taken back into the head mesh's own frame by the
inverse of the fit the scene said it made of head.mesh ("units mm; up +z; facing -y; moved by
(x, y, z) m"), written as USC-HairSalon .data (int32 strands, then per strand int32 points and
float32 xyz), so that loading it with that head.mesh shows whether the groom is kept where the file
put it.

  /usr/bin/python3 scripts/groom_beside_head.py GROOM.hair OUT.data METRES_PER_UNIT UP FACING TX TY TZ
  e.g. ... grown.hair beside.data 0.001 +z -y -0.002 0.004 0.068"""
import os
import struct
import sys

import numpy as np

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
import hair_file  # noqa: E402


def axis(name):
    v = np.zeros(3)
    v["xyz".index(name[1])] = 1.0 if name[0] == "+" else -1.0
    return v


def main():
    src, out, scale, up, facing = sys.argv[1:6]
    t = np.array([float(v) for v in sys.argv[6:9]])
    # The fit: head = R (scale file) + t, R's rows the file's axes that became x, y and z.
    y, z = axis(up), axis(facing)
    rotation = np.stack([np.cross(y, z), y, z])
    xyz, first = hair_file.read(src)
    file_xyz = ((xyz.astype(np.float64) - t) @ rotation) / float(scale)
    with open(out, "wb") as f:
        f.write(struct.pack("<i", len(first) - 1))
        for s in range(len(first) - 1):
            f.write(struct.pack("<i", int(first[s + 1] - first[s])))
            f.write(file_xyz[first[s]:first[s + 1]].astype("<f4").tobytes())
    print(f"{out}: {len(first) - 1} strands, {len(xyz)} points")


if __name__ == "__main__":
    main()
