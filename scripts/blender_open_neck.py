"""A head scan as data sets ship one, made with Blender from a closed OBJ head: the neck cut open
below a height, written as a binary little-endian PLY in millimetres with z up (Blender's axes),
for measuring head.mesh's fit (unit, up from the opening, facing) on a real scan.

  blender -b --python scripts/blender_open_neck.py -- HEAD.obj OUT.ply [CUT_Y_METRES]
  e.g. ... -- ../shared/data/heads/LeePerrySmith.obj /tmp/LeePerrySmith_open_mm.ply -0.17"""
import sys

import bmesh
import bpy

args = sys.argv[sys.argv.index("--") + 1:]
src, out = args[0], args[1]
cut = float(args[2]) if len(args) > 2 else -0.17

bpy.ops.wm.read_factory_settings(use_empty=True)
bpy.ops.wm.obj_import(filepath=src)
ob = bpy.context.selected_objects[0]
me = ob.data
bm = bmesh.new()
bm.from_mesh(me)
# Blender's importer turns the file's y up into its z up: the cut is a height along z.
below = [v for v in bm.verts if (ob.matrix_world @ v.co).z < cut]
bmesh.ops.delete(bm, geom=below, context="VERTS")
bm.to_mesh(me)
bm.free()
print(f"{out}: {len(me.vertices)} vertices, {len(me.polygons)} faces")
bpy.ops.export_mesh.ply(filepath=out, use_ascii=False, use_selection=False,
                        use_mesh_modifiers=False, use_normals=True, use_uv_coords=False,
                        use_colors=False, global_scale=1000.0, axis_forward="Y", axis_up="Z")
