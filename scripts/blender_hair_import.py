# Takes csmhair's OBJ curves into Blender, as an artist on Linux would: Blender's own OBJ importer,
# then the strands counted (the edges' chains) and the axes checked. Run with Blender in batch mode:
#   blender -b --factory-startup --python scripts/blender_hair_import.py -- FRAME.obj [STRANDS]
# Prints the vertices, edges and strands the importer made and the height the hair spans (the
# file's y is Blender's z); exits 1 when a strand branches, or STRANDS is given and differs.
# scripts/blender_roundtrip.sh runs it on a frame csmhair exports.
import sys

import bpy

args = sys.argv[sys.argv.index("--") + 1:] if "--" in sys.argv else []
if not args:
    print("usage: blender -b --python blender_hair_import.py -- FILE.obj [STRANDS]")
    sys.exit(2)
path = args[0]
expected = int(args[1]) if len(args) > 1 else None

bpy.ops.object.select_all(action="SELECT")
bpy.ops.object.delete()
if hasattr(bpy.ops.wm, "obj_import"):  # the C++ importer (Blender 3.3 and later)
    importer = "wm.obj_import"
    bpy.ops.wm.obj_import(filepath=path)
else:
    importer = "import_scene.obj"
    bpy.ops.import_scene.obj(filepath=path)
meshes = [o for o in bpy.context.scene.objects if o.type == "MESH"]
if not meshes:
    print("blender_hair_import: the importer made no mesh from %s" % path)
    sys.exit(1)

vertices = edges = strands = 0
branches = 0
low, high = float("inf"), float("-inf")
for o in meshes:
    m = o.data
    n = len(m.vertices)
    parent = list(range(n))
    degree = [0] * n

    def root(i):
        while parent[i] != i:
            parent[i] = parent[parent[i]]
            i = parent[i]
        return i

    for e in m.edges:
        a, b = e.vertices
        degree[a] += 1
        degree[b] += 1
        ra, rb = root(a), root(b)
        if ra != rb:
            parent[ra] = rb
    used = set()
    for e in m.edges:
        used.add(root(e.vertices[0]))
    vertices += n
    edges += len(m.edges)
    strands += len(used)
    branches += sum(1 for d in degree if d > 2)
    for v in m.vertices:
        z = (o.matrix_world @ v.co).z
        low, high = min(low, z), max(high, z)

print("blender_hair_import: %s with %s (Blender %s): %d vertices, %d edges, %d strands, "
      "z from %.4f to %.4f m" % (path, importer, bpy.app.version_string, vertices, edges,
                                 strands, low, high))
status = 0
if branches:
    print("blender_hair_import: FAIL: %d vertices with three or more edges" % branches)
    status = 1
if expected is not None and strands != expected:
    print("blender_hair_import: FAIL: %d strands, expected %d" % (strands, expected))
    status = 1
sys.exit(status)
