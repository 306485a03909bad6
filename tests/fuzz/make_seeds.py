#!/usr/bin/env python3
"""Writes the hand-made seeds of tests/fuzz/corpus/ (presets, cyHair, TressFX, OBJ). The shipped
presets/*.json are seeds too: scripts/fuzz.sh adds them to the preset target's corpus.
Run from anywhere: python3 tests/fuzz/make_seeds.py"""
import math
import os
import struct

here = os.path.dirname(os.path.abspath(__file__))


def out(target, name, data):
    d = os.path.join(here, "corpus", target)
    os.makedirs(d, exist_ok=True)
    with open(os.path.join(d, name), "wb" if isinstance(data, bytes) else "w") as f:
        f.write(data)


def strands(count, points, curl=0.0, scale=1.0):
    """Strands rising from a cap of a 10-unit sphere, then hanging down."""
    out = []
    for s in range(count):
        a = 2 * math.pi * s / count
        root = (10 * math.cos(a) * 0.5, 10 * 0.85, 10 * math.sin(a) * 0.5)
        pts = []
        for i in range(points):
            t = i / max(1, points - 1)
            pts.append(((root[0] * (1 + 0.3 * t) + curl * math.cos(7 * t)) * scale,
                        (root[1] - 20 * t * t) * scale,
                        (root[2] * (1 + 0.3 * t) + curl * math.sin(7 * t)) * scale))
        out.append(pts)
    return out


def cyhair(ss, segments_array=True, thickness=False, transparency=False, colors=False,
           default_segments=0):
    arrays = 2 | (1 if segments_array else 0) | (4 if thickness else 0) | \
        (8 if transparency else 0) | (16 if colors else 0)
    npts = sum(len(s) for s in ss)
    head = b"HAIR" + struct.pack("<IIII", len(ss), npts, arrays, default_segments)
    head += struct.pack("<fffff", 0.1, 0.0, 0.5, 0.4, 0.3)
    head += b"fuzz seed".ljust(88, b"\0")
    assert len(head) == 128
    body = b""
    if segments_array:
        body += b"".join(struct.pack("<H", len(s) - 1) for s in ss)
    body += b"".join(struct.pack("<fff", *p) for s in ss for p in s)
    if thickness:
        body += b"".join(struct.pack("<f", 0.01 + 0.001 * i) for s in ss for i, _ in enumerate(s))
    if transparency:
        body += b"".join(struct.pack("<f", 0.2) for s in ss for _ in s)
    if colors:
        body += b"".join(struct.pack("<fff", 0.5, 0.3, 0.1) for s in ss for _ in s)
    return head + body


def lay_out(arrays, at):
    """The arrays after a header of `at` bytes, each 8-byte aligned as TressFX asks; an empty one
    is absent (offset 0). Returns the body and the offsets."""
    body, offsets = b"", []
    for a in arrays:
        if not a:
            offsets.append(0)
            continue
        pad = (-at) % 8
        body += b"\0" * pad
        at += pad
        offsets.append(at)
        body += a
        at += len(a)
    return body, offsets


def tressfx(ss, strand_uv=False, vertex_uv=False, thickness=False, colors=False):
    n, per = len(ss), len(ss[0])
    arrays = [struct.pack("<ffff", *p, 0.0 if i < 2 else 1.0) for s in ss
              for i, p in enumerate(s)]
    layout = [b"".join(arrays)]
    layout.append(b"".join(struct.pack("<ff", 0.5, 0.5) for _ in ss) if strand_uv else b"")
    layout.append(b"".join(struct.pack("<ff", 0.1, 0.9) for s in ss for _ in s)
                  if vertex_uv else b"")
    layout.append(b"".join(struct.pack("<f", 0.02) for _ in ss) if thickness else b"")
    layout.append(b"".join(struct.pack("<ffff", 0.6, 0.4, 0.2, 1.0) for s in ss for _ in s)
                  if colors else b"")
    body, offsets = lay_out(layout, 160)
    head = struct.pack("<fII", 4.0, n, per) + struct.pack("<5I", *offsets)
    head = head.ljust(160, b"\0")
    return head + body


def tressfx3(ss, thickness=False, colors=False, guides=False, both_ends=0):
    """TressFX 3.x: a 296-byte header (TressFXFileObject), float3 positions."""
    n, per = len(ss), len(ss[0])
    layout = [b"".join(struct.pack("<fff", *p) for s in ss for p in s)]
    layout.append(b"".join(struct.pack("<f", 0.02) for _ in ss) if thickness else b"")
    layout.append(b"")  # strand texture coordinates
    layout.append(b"".join(struct.pack("<ffff", 0.6, 0.4, 0.2, 1.0) for s in ss for _ in s)
                  if colors else b"")
    layout.append(b"".join(struct.pack("<I", 0) for _ in ss) if guides else b"")
    body, offsets = lay_out(layout, 296)
    offsets.append(0)  # per-vertex texture coordinates
    head = struct.pack("<fIIII", 3.0, n, per, 4, both_ends) + b"\0" * 124
    head += struct.pack("<6I", *offsets)
    head = head.ljust(296, b"\0")
    return head + body


def tressfx_text(ss, version=True):
    """TressFX 1.x (no version line) or 2.x text."""
    t = ("version 2.0\nscale 1.0\nrotation 0 0 0\ntranslation 0 0 0\nbothEndsImmovable 0\n"
         "maxNumVerticesInStrand 64\nnumFollowHairsPerGuideHair 4\n"
         "maxRadiusAroundGuideHair 0.5\n") if version else ""
    t += "numStrands %d\nis sorted 1\n" % len(ss)
    for i, s in enumerate(ss):
        t += "strand %d numVerts %d texcoord 0.000000 0.500000\n" % (i, len(s))
        t += "".join("%.6f %.6f %.6f\n" % p for p in s)
    return t


def curves(ss, edges=True):
    """OBJ curves: Blender's one `l` an edge, or one `l` a strand."""
    text = "# Blender v3.4.1 OBJ File: ''\no ParticleSystem\n"
    text += "".join("v %.6f %.6f %.6f\n" % p for s in ss for p in s)
    at = 1
    for s in ss:
        ids = list(range(at, at + len(s)))
        at += len(s)
        if edges:
            text += "".join("l %d %d\n" % (a, b) for a, b in zip(ids, ids[1:]))
        else:
            text += "l " + " ".join(map(str, ids)) + "\n"
    return text


def research(reader, payload):
    """A seed of the research target: its first byte picks the reader."""
    return bytes([reader]) + (payload if isinstance(payload, bytes) else payload.encode())


def strand_arrays(ss, floats):
    data = struct.pack("<i", len(ss))
    for s in ss:
        data += struct.pack("<i", len(s))
        for p in s:
            data += struct.pack("<3f", *p) + struct.pack("<f", 0.5) * (floats - 3)
    return data


def ply_strands(ss, fmt="ascii", edges=False):
    npts = sum(len(s) for s in ss)
    head = "ply\nformat %s 1.0\nelement vertex %d\nproperty float z\nproperty float y\n" \
        "property float x\nproperty uchar red\nproperty uchar green\nproperty uchar blue\n" % \
        (fmt, npts)
    if edges:
        nedges = sum(len(s) - 1 for s in ss)
        head += "element edge %d\nproperty int vertex1\nproperty int vertex2\n" % nedges
    else:
        head += "element strand %d\nproperty ushort nsegs\n" % len(ss)
    head += "end_header\n"
    pts = [p for s in ss for p in s]
    if fmt == "ascii":
        body = "".join("%g %g %g 100 50 25\n" % (p[2], p[1], p[0]) for p in pts)
        if edges:
            first = 0
            for s in ss:
                body += "".join("%d %d\n" % (first + i, first + i + 1) for i in range(len(s) - 1))
                first += len(s)
        else:
            body += "".join("%d\n" % (len(s) - 1) for s in ss)
        return (head + body).encode()
    e = "<" if fmt == "binary_little_endian" else ">"
    body = b"".join(struct.pack(e + "3f3B", p[2], p[1], p[0], 100, 50, 25) for p in pts)
    body += b"".join(struct.pack(e + "H", len(s) - 1) for s in ss)
    return head.encode() + body


def ply_mesh(vertices, faces, fmt="ascii"):
    head = "ply\nformat %s 1.0\nelement vertex %d\nproperty float x\nproperty float y\n" \
        "property float z\nelement face %d\nproperty list uchar int vertex_indices\n" \
        "end_header\n" % (fmt, len(vertices), len(faces))
    if fmt == "ascii":
        body = "".join("%g %g %g\n" % v for v in vertices)
        body += "".join("%d %s\n" % (len(f), " ".join(str(i - 1) for i in f)) for f in faces)
        return (head + body).encode()
    body = b"".join(struct.pack("<3f", *v) for v in vertices)
    body += b"".join(struct.pack("<B%di" % len(f), len(f), *[i - 1 for i in f]) for f in faces)
    return head.encode() + body


def obj(vertices, faces, extra=""):
    text = "# fuzz seed\n" + extra
    text += "".join("v %.5f %.5f %.5f\n" % v for v in vertices)
    text += "".join("f " + " ".join(str(i) for i in f) + "\n" for f in faces)
    return text


def main():
    out("preset", "empty_object.json", "{}\n")
    out("preset", "small_volume.json",
        '{"hairstyle": {"strands": 4, "length_max": 0.1, "length_min": 0.05, '
        '"curl_radius": 0.01, "parting": "left", "fringe": true},\n'
        ' "collision": {"mode": "volume+strands", "head_shape": "spheres"},\n'
        ' "head": {"motion": "nod", "fit_spheres": false},\n'
        ' "sim": {"stiffness_model": "paper", "dftl": 0.5},\n'
        ' "wind": {"strength": 3.0}}\n')
    out("preset", "fitted_spheres.json",
        '{"hairstyle.strands": 3, "head.fit_spheres": true, "collision.head_shape": "sdf",\n'
        ' "hairstyle.particles_per_strand": 6, "hairstyle.file": ""}\n')
    out("preset", "bad_key.json", '{"hairstyle": {"strand": 10}, "sim": {"dt": 2}}\n')
    out("preset", "file_names.json",
        '{"hairstyle": {"file": "groom.hair"}, "head": {"mesh": "head.obj"}}\n')

    out("cyhair", "segments.hair", cyhair(strands(3, 5)))
    out("cyhair", "default_segments.hair",
        cyhair(strands(2, 4), segments_array=False, default_segments=3))
    out("cyhair", "all_arrays.hair",
        cyhair(strands(3, 4, curl=1.0), thickness=True, transparency=True, colors=True))
    out("cyhair", "long_strand.hair", cyhair(strands(2, 40, curl=2.0)))
    out("cyhair", "metres.hair", cyhair(strands(2, 6, scale=0.01)))
    out("cyhair", "truncated.hair", cyhair(strands(2, 3))[:150])

    out("tressfx", "positions.tfx", tressfx(strands(3, 4)))
    out("tressfx", "all_arrays.tfx",
        tressfx(strands(2, 4, curl=1.0), strand_uv=True, vertex_uv=True, thickness=True,
                colors=True))
    out("tressfx", "long_strands.tfx", tressfx(strands(2, 32, curl=2.0)))
    out("tressfx", "truncated.tfx", tressfx(strands(2, 4))[:200])
    out("tressfx", "v3_positions.tfx", tressfx3(strands(3, 4)))
    out("tressfx", "v3_all_arrays.tfx",
        tressfx3(strands(2, 16, curl=1.0), thickness=True, colors=True, guides=True))
    out("tressfx", "v3_both_ends.tfx", tressfx3(strands(2, 4), both_ends=1))
    out("tressfx", "v2_text.tfx", tressfx_text(strands(3, 5)))
    out("tressfx", "v1_text.tfx", tressfx_text(strands(2, 4, curl=1.0), version=False))

    out("curves", "edges.obj", curves(strands(3, 5)))
    out("curves", "polylines.obj", curves(strands(3, 6, curl=1.0), edges=False))
    out("curves", "with_head.obj",
        curves(strands(2, 4)) + "v 0 0 0\nv 1 0 0\nv 0 1 0\nf -3 -2 -1\n")
    out("curves", "branch.obj", curves(strands(2, 4)) + "l 2 7\n")

    out("research", "salon.data", research(0, strand_arrays(strands(3, 5), 3)))
    out("research", "bald_root.data", research(0, strand_arrays([[(0, 0, 0)]] + strands(2, 4), 3)))
    out("research", "ct2hair.bin", research(1, strand_arrays(strands(2, 6, curl=1.0), 7)))
    out("research", "truncated.data", research(0, strand_arrays(strands(2, 4), 3)[:40]))
    out("research", "strands_ascii.ply", research(2, ply_strands(strands(3, 4))))
    out("research", "strands_edges.ply", research(2, ply_strands(strands(2, 5), edges=True)))
    out("research", "strands_le.ply",
        research(2, ply_strands(strands(2, 4), "binary_little_endian")))
    out("research", "strands_be.ply", research(2, ply_strands(strands(2, 4), "binary_big_endian")))

    r = 0.1
    tet = [(r, r, r), (r, -r, -r), (-r, r, -r), (-r, -r, r)]
    out("research", "head_ascii.ply",
        research(3, ply_mesh(tet, [(1, 2, 3), (1, 4, 2), (1, 3, 4), (2, 4, 3)])))
    out("research", "head_open.ply",
        research(3, ply_mesh(tet, [(1, 2, 3), (1, 4, 2), (1, 3, 4)], "binary_little_endian")))
    out("obj", "tetrahedron.obj", obj(tet, [(1, 2, 3), (1, 4, 2), (1, 3, 4), (2, 4, 3)]))
    cube = [(x * r, y * r, z * r) for x in (-1, 1) for y in (-1, 1) for z in (-1, 1)]
    quads = [(1, 2, 4, 3), (5, 7, 8, 6), (1, 5, 6, 2), (3, 4, 8, 7), (1, 3, 7, 5), (2, 6, 8, 4)]
    out("obj", "cube_quads.obj", obj(cube, quads, "o cube\nvn 0 1 0\nvt 0 0\n"))
    out("obj", "cube_slashes.obj",
        obj(cube, [tuple("%d/1/1" % i for i in q) for q in quads], "vn 0 1 0\nvt 0 0\n"))
    out("obj", "cube_negative.obj",
        obj(cube, [tuple(i - 9 for i in q) for q in quads]))
    octa = [(r, 0, 0), (-r, 0, 0), (0, r, 0), (0, -r, 0), (0, 0, r), (0, 0, -r)]
    of = [(1, 3, 5), (3, 2, 5), (2, 4, 5), (4, 1, 5), (3, 1, 6), (2, 3, 6), (4, 2, 6), (1, 4, 6)]
    out("obj", "octahedron_inward.obj", obj(octa, [f[::-1] for f in of]))
    out("obj", "open.obj", obj(tet, [(1, 2, 3), (1, 4, 2), (1, 3, 4)]))
    out("obj", "bad_index.obj", obj(tet, [(1, 2, 3), (1, 4, 2), (1, 3, 4), (2, 4, 9)]))


if __name__ == "__main__":
    main()
