# Writes parts.obj (+ parts.mtl), parts.dae, parts.fbx and parts.gltf (+
# .bin): a small scene of several objects and materials, through Blender
# 3.4's exporters, for the tests of objects and materials
# (tests/core/export/test_parts.cpp and the CLI's tests):
#   "Ball"   a UV sphere, its upper half "Red", its lower half "Blue": a
#            material boundary along a smooth surface;
#   "Crate"  a cube of material "Wood" beside the ball, partly behind it in
#            the default view;
#   "Post"   a cylinder of material "Steel" in front of the ball, hiding
#            part of it;
#   "Ground" a plane of material "Grass" under them all.
#   blender -b -P make_parts.py -- OUTDIR
import os
import sys

import bpy

out = sys.argv[sys.argv.index("--") + 1] if "--" in sys.argv else os.path.dirname(os.path.abspath(__file__))
bpy.ops.wm.read_factory_settings(use_empty=True)


def material(name, rgba):
    m = bpy.data.materials.new(name)
    m.diffuse_color = rgba
    m.use_nodes = True
    m.node_tree.nodes["Principled BSDF"].inputs["Base Color"].default_value = rgba
    return m


red, blue = material("Red", (0.8, 0.1, 0.1, 1)), material("Blue", (0.1, 0.2, 0.8, 1))
wood, steel, grass = material("Wood", (0.6, 0.4, 0.2, 1)), material("Steel", (0.5, 0.5, 0.55, 1)), material("Grass", (0.2, 0.6, 0.2, 1))

bpy.ops.mesh.primitive_uv_sphere_add(segments=48, ring_count=24, radius=1.0, location=(0, 0, 1.0))
ball = bpy.context.object
ball.name = "Ball"
ball.data.materials.append(red)
ball.data.materials.append(blue)
for p in ball.data.polygons:
    p.material_index = 0 if p.center.z > 0 else 1
    p.use_smooth = True

bpy.ops.mesh.primitive_cube_add(size=1.2, location=(1.9, 1.2, 0.6))
crate = bpy.context.object
crate.name = "Crate"
crate.data.materials.append(wood)

bpy.ops.mesh.primitive_cylinder_add(vertices=32, radius=0.25, depth=2.4, location=(0.5, -1.4, 1.2))
post = bpy.context.object
post.name = "Post"
post.data.materials.append(steel)
for p in post.data.polygons:
    p.use_smooth = len(p.vertices) == 4  # the side smooth, the caps flat

bpy.ops.mesh.primitive_plane_add(size=6, location=(0.5, 0, 0))
ground = bpy.context.object
ground.name = "Ground"
ground.data.materials.append(grass)

bpy.ops.object.select_all(action='SELECT')
bpy.ops.export_scene.obj(filepath=os.path.join(out, "parts.obj"), use_selection=False, use_materials=True,
                         use_triangles=True, use_normals=True, use_uvs=False)
bpy.ops.wm.collada_export(filepath=os.path.join(out, "parts.dae"), triangulate=True)
bpy.ops.export_scene.fbx(filepath=os.path.join(out, "parts.fbx"))
bpy.ops.export_scene.gltf(filepath=os.path.join(out, "parts.gltf"), export_format='GLTF_SEPARATE')
