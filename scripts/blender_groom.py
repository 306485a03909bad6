"""Makes a groom in Blender the way an artist would, in batch mode, and writes it as an OBJ of
edge chains (one chain a strand, root first) in metres with y up, for `csmhair GROOM.obj`:
hair particles on the top of a head-sized sphere, let fall under gravity with hair dynamics,
converted to a mesh of edges and exported.
  blender -b --factory-startup --python scripts/blender_groom.py -- OUT.obj
      [--strands N] [--length M] [--seed S] [--frames F] [--comb W] [--legacy]
Made with Debian 12's Blender 3.4; the same seed gives the same file."""
import argparse
import os
import sys
import time

import bpy

args = argparse.ArgumentParser(prog="blender_groom.py")
args.add_argument("out")
args.add_argument("--strands", type=int, default=1500)
args.add_argument("--length", type=float, default=0.2, help="hair length, metres")
args.add_argument("--seed", type=int, default=1)
args.add_argument("--frames", type=int, default=40, help="frames of hair dynamics (24 a second)")
args.add_argument("--comb", type=float, default=6.0, help="the wind that sweeps hair back")
args.add_argument("--legacy", action="store_true", help="use the legacy Python OBJ exporter")
args = args.parse_args(sys.argv[sys.argv.index("--") + 1:] if "--" in sys.argv else [])
start = time.time()

# An empty scene: the factory startup has a cube, a camera and a light.
for o in list(bpy.data.objects):
    bpy.data.objects.remove(o, do_unlink=True)

# The head: a sphere of radius 0.1 m. Blender is z up with the front towards -y. An ico sphere,
# not a UV sphere: on a UV sphere, Blender 3.4 puts hair roots on different faces from one
# run to the next with the same seed; on the ico sphere's triangles it repeats itself.
bpy.ops.mesh.primitive_ico_sphere_add(radius=0.1, subdivisions=4)
head = bpy.context.active_object

# The scalp as a vertex group that weights the root density: everything above a hairline
# that is high at the forehead and the temples (-y; the normal's z above 0.68 half way to the
# front), above the ears on the sides (0.3) and just below the equator at the back (-0.1), with
# a soft edge of 0.15 in the normal's z. The sphere has no face: hair grown lower at the front
# would fall through the face of the head it is simulated on.
scalp = head.vertex_groups.new(name="scalp")
for v in head.data.vertices:
    n = v.co.normalized()
    hairline = 0.3 - 0.4 * n.y if n.y > -0.2 else 0.38 + (-0.2 - n.y)  # steeper at the temples
    weight = min(1.0, max(0.0, (n.z - hairline) / 0.15))
    if weight > 0.0:
        scalp.add([v.index], weight, "REPLACE")

hair = head.modifiers.new("Hair", "PARTICLE_SYSTEM")
psys = hair.particle_system
psys.seed = args.seed
psys.vertex_group_density = scalp.name
s = psys.settings
s.type = "HAIR"
s.count = args.strands
s.hair_length = args.length
s.hair_step = 12  # keys a strand, what the dynamics moves
# The mesh conversion samples the strand's path with 2^display_step segments, not hair_step.
s.display_step = 4
s.child_type = "NONE"  # parent strands only: children would be converted as strands too
s.emit_from = "FACE"
s.distribution = "RAND"
# Faces taken in turn along the scalp's weight, not drawn at random: drawn, 3.4 gives some
# strands the same root as the strand three before.
s.use_emit_random = False
# hair_length only sets normal_factor (a quarter of it): the random part of the direction
# is scaled with it, so strands leave about along the normal, spread, not as a brush.
s.factor_random = 0.25 * s.normal_factor

# Comb by gravity: a few frames of hair dynamics against the head as a collider, with no pull
# back towards the straight rest shape (pin_stiffness 0), so the strands fall around the head.
# The collision margins are Blender's defaults for a head a metre or more across (2 and 1.5 cm):
# at 0.1 m they push the first keys off the scalp and stretch the strands by a fifth, so 2 mm.
head.modifiers.new("Collision", "COLLISION")
head.collision.thickness_outer = 0.002
psys.use_hair_dynamics = True
psys.cloth.settings.pin_stiffness = 0.0
psys.cloth.collision_settings.distance_min = 0.002
# And a comb: a steady wind from the face to the back (Blender's front is -y; a wind field
# blows along its own z, turned here to +y), so that the hair at the forehead is swept back
# over the crown instead of falling over a face the sphere does not have.
bpy.ops.object.effector_add(type="WIND", location=(0.0, -0.3, 0.1), rotation=(-1.5708, 0.0, 0.0))
comb = bpy.context.active_object
comb.field.strength = args.comb
comb.field.flow = 1.0  # drags the hair towards the wind's speed, like air, not a push
for frame in range(1, args.frames + 1):
    bpy.context.scene.frame_set(frame)

# The strands as a mesh of loose edges: modifier_convert works on the active object in
# background mode too, without a context override, and makes the new mesh active.
bpy.ops.object.select_all(action="DESELECT")
head.select_set(True)
bpy.context.view_layer.objects.active = head
bpy.ops.object.modifier_convert(modifier=hair.name)
groom = bpy.context.active_object
groom.name = groom.data.name = "groom"
bpy.ops.object.select_all(action="DESELECT")
groom.select_set(True)

# OBJ is y up with the front towards +z: forward -Z, up Y; metres, geometry only. The 3.4
# exporter says when it cannot write the file but does not fail: look for the file after.
if os.path.exists(args.out):
    os.remove(args.out)
if hasattr(bpy.ops.wm, "obj_export") and not args.legacy:  # the C++ exporter, Blender 3.1 on
    bpy.ops.wm.obj_export(filepath=args.out, export_selected_objects=True,
                          forward_axis="NEGATIVE_Z", up_axis="Y", global_scale=1.0,
                          export_materials=False, export_normals=False, export_uv=False)
else:  # the Python exporter, older Blender
    bpy.ops.export_scene.obj(filepath=args.out, use_selection=True, axis_forward="-Z",
                             axis_up="Y", global_scale=1.0, use_materials=False,
                             use_normals=False, use_uvs=False, use_edges=True)
if not os.path.exists(args.out):
    sys.exit(f"blender_groom: {args.out} was not written")
mesh = groom.data
print(f"blender_groom: {args.out}: {len(mesh.vertices) - len(mesh.edges)} strands, "
      f"{len(mesh.vertices)} vertices, {len(mesh.edges)} edges "
      f"({time.time() - start:.1f} s)")
