#!/usr/bin/env python3
"""The project's own motion-capture clips (BVH), with the traits real ones have.

  python3 scripts/make_clips.py OUT_DIR

writes a walk, a run, a head turn, a jump, a jerky dance and a walk with a cut, in the units,
up axes, facings, rotation orders, channel layouts and joint names that the field's files come
in (see KINDS below). The same walk is written in centimetres, metres and Z-up inches, so that
the reader's inference can be checked to give one motion. BVH has no comments: each file's traits
are in KINDS below.
"""
import math
import os
import sys

# ---- rotations as 3x3 row-major lists -------------------------------------------------------


def mat_mul(a, b):
    return [[sum(a[i][k] * b[k][j] for k in range(3)) for j in range(3)] for i in range(3)]


def mat_vec(a, v):
    return [sum(a[i][k] * v[k] for k in range(3)) for i in range(3)]


def transpose(a):
    return [[a[j][i] for j in range(3)] for i in range(3)]


def rot(axis, degrees):
    c, s = math.cos(math.radians(degrees)), math.sin(math.radians(degrees))
    if axis == 0:
        return [[1, 0, 0], [0, c, -s], [0, s, c]]
    if axis == 1:
        return [[c, 0, s], [0, 1, 0], [-s, 0, c]]
    return [[c, -s, 0], [s, c, 0], [0, 0, 1]]


def rx(d):
    return rot(0, d)


def ry(d):
    return rot(1, d)


def rz(d):
    return rot(2, d)


def chain(*ms):
    out = [[1, 0, 0], [0, 1, 0], [0, 0, 1]]
    for m in ms:
        out = mat_mul(out, m)
    return out


def euler(m, order):
    """Angles (degrees) a, b, c with m = R_order[0](a) R_order[1](b) R_order[2](c)."""
    i, j, k = ("XYZ".index(order[0]), "XYZ".index(order[1]), "XYZ".index(order[2]))
    s = 1.0 if (i, j, k) in ((0, 1, 2), (1, 2, 0), (2, 0, 1)) else -1.0
    b = math.asin(max(-1.0, min(1.0, s * m[i][k])))
    a = math.atan2(-s * m[j][k], m[k][k])
    c = math.atan2(-s * m[i][j], m[i][i])
    angles = [math.degrees(a), math.degrees(b), math.degrees(c)]
    back = chain(rot(i, angles[0]), rot(j, angles[1]), rot(k, angles[2]))
    assert max(abs(back[r][q] - m[r][q]) for r in range(3) for q in range(3)) < 1e-9, order
    return angles


# ---- the skeleton: metres, y up, facing +z, the character's left +x ------------------------
# (name, parent, offset, end site or None)
SKELETON = [
    ("Hips", None, (0, 0.95, 0), None),
    ("Spine", "Hips", (0, 0.10, 0), None),
    ("Chest", "Spine", (0, 0.15, 0), None),
    ("Neck", "Chest", (0, 0.20, 0), None),
    ("Head", "Neck", (0, 0.10, 0), (0, 0.15, 0)),
    ("LeftShoulder", "Chest", (0.05, 0.15, 0), None),
    ("LeftArm", "LeftShoulder", (0.13, 0, 0), None),
    ("LeftForeArm", "LeftArm", (0.28, 0, 0), (0.25, 0, 0)),
    ("RightShoulder", "Chest", (-0.05, 0.15, 0), None),
    ("RightArm", "RightShoulder", (-0.13, 0, 0), None),
    ("RightForeArm", "RightArm", (-0.28, 0, 0), (-0.25, 0, 0)),
    ("LeftUpLeg", "Hips", (0.09, -0.05, 0), None),
    ("LeftLeg", "LeftUpLeg", (0, -0.42, 0), None),
    ("LeftFoot", "LeftLeg", (0, -0.42, 0), (0, -0.05, 0.12)),
    ("RightUpLeg", "Hips", (-0.09, -0.05, 0), None),
    ("RightLeg", "RightUpLeg", (0, -0.42, 0), None),
    ("RightFoot", "RightLeg", (0, -0.42, 0), (0, -0.05, 0.12)),
]

# The names other tools give the same joints.
NAMES = {
    "plain": {},
    "mixamo": {n: "mixamorig:" + n for n, *_ in SKELETON} | {
        "Spine": "mixamorig:Spine1", "Chest": "mixamorig:Spine2"},
    "bandai": {"LeftShoulder": "Shoulder_L", "LeftArm": "UpperArm_L", "LeftForeArm": "LowerArm_L",
               "RightShoulder": "Shoulder_R", "RightArm": "UpperArm_R",
               "RightForeArm": "LowerArm_R", "LeftUpLeg": "UpperLeg_L", "LeftLeg": "LowerLeg_L",
               "LeftFoot": "Foot_L", "RightUpLeg": "UpperLeg_R", "RightLeg": "LowerLeg_R",
               "RightFoot": "Foot_R"},
    "cmu": {"Spine": "lowerback", "Chest": "Chest2", "Neck": "Neck", "LeftShoulder": "LeftCollar",
            "LeftArm": "LeftShoulder", "LeftForeArm": "LeftElbow", "RightShoulder": "RightCollar",
            "RightArm": "RightShoulder", "RightForeArm": "RightElbow", "LeftUpLeg": "LHipJoint",
            "LeftLeg": "LeftKnee", "LeftFoot": "LeftAnkle", "RightUpLeg": "RHipJoint",
            "RightLeg": "RightKnee", "RightFoot": "RightAnkle"},
}


def smooth(t, a, b):
    if t <= a:
        return 0.0
    if t >= b:
        return 1.0
    x = (t - a) / (b - a)
    return x * x * (3 - 2 * x)


def arms_down(pose, swing):
    pose["LeftArm"] = chain(rz(-75), rx(swing))
    pose["RightArm"] = chain(rz(75), rx(-swing))


def gait(t, speed, cycle_hz, bob, leg, lean):
    phi = 2 * math.pi * cycle_hz * t
    hips = (0.02 * math.sin(phi), 0.95 - bob + bob * math.cos(2 * phi), speed * t)
    pose = {"Hips": ry(6 * math.sin(phi)), "Spine": ry(-3 * math.sin(phi)),
            "Chest": chain(rx(lean), ry(-5 * math.sin(phi))),
            "Neck": rx(-lean / 2 + 2 * math.sin(2 * phi)),
            "Head": chain(rx(-lean / 2 - 2 * math.sin(2 * phi)), ry(-2 * math.sin(phi))),
            "LeftUpLeg": rx(-leg * math.sin(phi)), "RightUpLeg": rx(leg * math.sin(phi)),
            "LeftLeg": rx(max(0.0, 1.5 * leg * math.sin(phi + 1.2))),
            "RightLeg": rx(max(0.0, 1.5 * leg * math.sin(phi + 1.2 + math.pi)))}
    arms_down(pose, 0.8 * leg * math.sin(phi))
    return hips, pose


def walk(t):
    return gait(t, 1.4, 0.9, 0.025, 25, 0)


def run(t):
    return gait(t, 4.5, 1.4, 0.05, 45, 12)


def turn(t):
    # The head turns 80 degrees to its left and back; the chest and the hips stay.
    a = 80 * (smooth(t, 1.0, 1.6) - smooth(t, 3.0, 3.6))
    pose = {"Neck": ry(0.4 * a), "Head": ry(0.6 * a), "Chest": rx(1.5 * math.sin(2 * math.pi * 0.3 * t))}
    arms_down(pose, 0)
    return (0, 0.95, 0), pose


def jump(t):
    # Stand, crouch 15 cm, push off (4 g over the crouch's depth), fly 0.45 m above standing,
    # land (4 g again, the knees taking the crouch's depth), recover.
    g, crouch, stand = 9.81, 0.15, 0.95
    v0 = math.sqrt(2 * g * (0.45 + crouch))
    push = 2 * crouch / v0  # the push's time at constant acceleration from rest to v0
    flight = 2 * v0 / g
    t_push, t_land = 1.0, 1.0 + push + flight
    if t < t_push:
        y = stand - crouch * smooth(t, 0.6, t_push)
        bend = smooth(t, 0.6, t_push)
    elif t < t_push + push:
        s = t - t_push
        y = stand - crouch + 0.5 * (v0 / push) * s * s
        bend = 1 - s / push
    elif t < t_land:
        s = t - t_push - push
        y = stand + v0 * s - 0.5 * g * s * s
        bend = 0.0
    elif t < t_land + push:
        s = t - t_land
        y = stand - v0 * s + 0.5 * (v0 / push) * s * s
        bend = s / push
    else:
        y = stand - crouch * (1 - smooth(t, t_land + push, t_land + push + 0.8))
        bend = 1 - smooth(t, t_land + push, t_land + push + 0.8)
    pose = {"LeftUpLeg": rx(-40 * bend), "RightUpLeg": rx(-40 * bend), "LeftLeg": rx(70 * bend),
            "RightLeg": rx(70 * bend), "Chest": rx(15 * bend)}
    arms_down(pose, -30 * bend)
    return (0, y, 0), pose


def dance(t):
    # Video-captured dance: the hips bounce with kinks, the chest sways, the head pops (30 degree
    # snaps in 0.1 s, every half second, left and right: the crown's jerk about 1,500 m/s^3).
    beat = t * 2.0
    k = math.floor(beat)
    target = 15 if k % 2 == 0 else -15
    before = 0 if k == 0 else -target
    yaw = before + (target - before) * smooth(beat - k, 0.0, 0.2)
    hips = (0.08 * math.sin(2 * math.pi * 0.5 * t), 0.95 - 0.05 * abs(math.sin(2 * math.pi * t)), 0)
    pose = {"Hips": ry(15 * math.sin(2 * math.pi * 0.5 * t)),
            "Chest": chain(ry(20 * math.sin(2 * math.pi * t)), rz(8 * math.sin(4 * math.pi * t))),
            "Neck": rx(10 * math.sin(6 * math.pi * t)), "Head": ry(yaw),
            "LeftUpLeg": rx(-20 * abs(math.sin(2 * math.pi * t))),
            "RightUpLeg": rx(-20 * abs(math.sin(2 * math.pi * t + 1)))}
    arms_down(pose, 40 * math.sin(4 * math.pi * t))
    return hips, pose


def cut(t):
    # A walk with a second take spliced on at 2 s: 2 m to the side and turned 90 degrees.
    hips, pose = walk(t)
    if t >= 2.0:
        hips = (hips[0] + 2.0, hips[1], hips[2])
        pose["Hips"] = mat_mul(ry(90), pose.get("Hips", ry(0)))
    return hips, pose


# ---- writing --------------------------------------------------------------------------------
UP = {"y": [[1, 0, 0], [0, 1, 0], [0, 0, 1]], "z": rx(90)}  # y-up world into the file's axes
FACING = {"+z": 0, "+x": 90, "-z": 180, "-x": -90}  # yaw (about y) of the character
CYCLE = ["ZXY", "XYZ", "YZX", "ZYX", "XZY", "YXZ"]


def write(path, motion, seconds, fps=30, unit=0.01, up="y", facing="+z", orders="ZXY",
          six=False, names="plain", frame_time_text=None):
    """unit: metres per file unit. orders: one order, "cycle" (each joint the next of CYCLE) or
    a list cycled through."""
    to_file = mat_mul(UP[up], ry(FACING[facing]))
    back = transpose(to_file)
    rename = NAMES[names]
    index = {n: i for i, (n, *_) in enumerate(SKELETON)}
    order_of = {}
    for i, (n, *_) in enumerate(SKELETON):
        order_of[n] = CYCLE[i % 6] if orders == "cycle" else (
            orders[i % len(orders)] if isinstance(orders, list) else orders)

    def vec(v):
        w = mat_vec(to_file, v)
        return " ".join("%.6f" % (x / unit) for x in w)

    lines = ["HIERARCHY"]

    def joint(n, depth):
        name, parent, offset, end = SKELETON[index[n]]
        pad = "\t" * depth
        lines.append(pad + ("ROOT " if parent is None else "JOINT ") + rename.get(name, name))
        lines.append(pad + "{")
        lines.append(pad + "\tOFFSET " + vec(offset))
        rot_channels = " ".join(a + "rotation" for a in order_of[n])
        if parent is None or six:
            lines.append(pad + "\tCHANNELS 6 Xposition Yposition Zposition " + rot_channels)
        else:
            lines.append(pad + "\tCHANNELS 3 " + rot_channels)
        for child, (cn, cp, *_) in enumerate(SKELETON):
            if cp == n:
                joint(cn, depth + 1)
        if end is not None:
            lines.extend([pad + "\tEnd Site", pad + "\t{", pad + "\t\tOFFSET " + vec(end), pad + "\t}"])
        lines.append(pad + "}")

    joint("Hips", 0)
    frames = int(round(seconds * fps)) + 1
    lines.append("MOTION")
    lines.append("Frames: %d" % frames)
    lines.append("Frame Time: " + (frame_time_text or "%.7f" % (1.0 / fps)))
    for f in range(frames):
        hips, pose = motion(f / fps)
        values = []
        for name, parent, offset, end in SKELETON:
            r = pose.get(name, rx(0))
            local = mat_mul(mat_mul(to_file, r), back)
            if parent is None:
                values.append(vec(hips))
            elif six:
                values.append(vec(offset))
            values.append(" ".join("%.6f" % a for a in euler(local, order_of[name])))
        lines.append(" ".join(values))
    with open(path, "w", newline="\r\n" if names == "mixamo" else "\n") as f:
        f.write("\n".join(lines) + "\n")


KINDS = {
    # name: (motion, seconds, options)
    "walk_cm.bvh": (walk, 9, {}),
    "walk_m.bvh": (walk, 9, {"unit": 1.0}),
    "walk_zup_inch.bvh": (walk, 9, {"unit": 0.0254, "up": "z", "orders": "XYZ"}),
    "run_6ch.bvh": (run, 6, {"unit": 1.0, "six": True, "orders": "YXZ", "names": "mixamo",
                             "facing": "+x"}),
    "turn_mixed.bvh": (turn, 5, {"orders": "cycle", "facing": "-z", "names": "bandai"}),
    "jump.bvh": (jump, 3, {"names": "bandai"}),
    "dance_zup.bvh": (dance, 6, {"fps": 60, "unit": 0.056444, "up": "z", "orders": ["ZYX", "ZXY"],
                                 "names": "cmu", "frame_time_text": ".01666667"}),
    "cut.bvh": (cut, 4, {}),
}


def main():
    out = sys.argv[1] if len(sys.argv) > 1 else "clips"
    os.makedirs(out, exist_ok=True)
    for name, (motion, seconds, options) in KINDS.items():
        write(os.path.join(out, name), motion, seconds, **options)


if __name__ == "__main__":
    main()
