# Writes scenes of objects that meet, through Blender 3.4's Collada and
# glTF exporters, for the tests of intersection lines, of fills that stop
# where one surface enters another, and of visibility near contact
# (tests/core/snaxel/test_intersections.cpp, tests/core/planarmap/
# test_map_reference.cpp):
#   still-life   a table (a slab on four legs pushed up into it, the legs
#                standing on the floor), a mug whose handle runs into its
#                body, standing on the table, a ball sunk a little into the
#                tabletop, a box resting on it (faces exactly in contact),
#                Suzanne sitting on it, a floor; seven materials, a camera
#                "ShotCam".
#   sunk         a slab with a ball sunk half into it, a post through it,
#                a cone pushed into the floor, a ring round the post; five
#                materials.
#   crossing     two spheres through each other, a rod through a third, a
#                torus through a box, and one object that passes through
#                itself (two boxes in one mesh); six materials.
#   apart        objects that do not meet, one in front of another from
#                most views: two balls, a cylinder with flat caps, a box, a
#                torus, at different depths, no floor; five materials (the
#                case where the maps' own outlines part every object).
#   rolling      a ball that rolls into a box through its wall, runs half
#                sunk in its top and leaves through the far wall (frames
#                1-96 at 24 fps); two materials. glTF only (node
#                animation).
# The glTF exporter needs numpy (Debian's python3-numpy).
#   blender -b -P make_meet.py -- OUTDIR
import math
import os
import sys

import bpy

sys.path.insert(0, os.path.join(os.path.dirname(os.path.abspath(__file__)), "..", "..", "support"))
from blender_scene import box, camera, cylinder, finish, material, reset, sphere  # noqa: E402

out = sys.argv[sys.argv.index("--") + 1] if "--" in sys.argv else os.path.dirname(os.path.abspath(__file__))


def export(name, collada=True):
    bpy.ops.object.select_all(action='SELECT')
    if collada:
        bpy.ops.wm.collada_export(filepath=os.path.join(out, name + ".dae"), triangulate=True)
    bpy.ops.export_scene.gltf(filepath=os.path.join(out, name + ".gltf"), export_format='GLTF_SEPARATE',
                              export_cameras=True, export_apply=True)


# The still life.
reset()
scene = bpy.context.scene
scene.render.resolution_x, scene.render.resolution_y = 1600, 900
wood, steel = material("Wood", (0.55, 0.33, 0.15, 1)), material("Steel", (0.45, 0.47, 0.5, 1))
ceramic, red = material("Ceramic", (0.85, 0.85, 0.8, 1)), material("Red", (0.8, 0.08, 0.06, 1))
card, skin = material("Cardboard", (0.7, 0.55, 0.3, 1)), material("Skin", (0.9, 0.6, 0.45, 1))
floor = material("Floor", (0.25, 0.35, 0.3, 1))
box("Tabletop", wood, (3.0, 2.0, 0.12), (0, 0, 1.0))
for i, (x, y) in enumerate([(-1.3, -0.8), (1.3, -0.8), (-1.3, 0.8), (1.3, 0.8)]):
    # From the floor up into the slab, ending 0.04 inside it.
    cylinder("Leg%d" % (i + 1), steel, 0.06, 1.0, (x, y, 0.5), vertices=24)
mug = cylinder("Mug", ceramic, 0.28, 0.6, (-0.6, 0.2, 1.06 + 0.3), vertices=48)
bpy.ops.mesh.primitive_torus_add(major_radius=0.2, minor_radius=0.05, location=(-0.6 + 0.3, 0.2, 1.36),
                                 rotation=(math.radians(90), 0, 0))
finish(bpy.context.object, "Handle", ceramic, True)
sphere("Ball", red, 0.3, (0.5, -0.3, 1.06 + 0.3 - 0.08))
box("Box", card, (0.5, 0.4, 0.35), (0.9, 0.5, 1.06 + 0.175))
bpy.ops.mesh.primitive_monkey_add(size=0.6, location=(-0.2, -0.55, 1.06 + 0.25), rotation=(0, 0, math.radians(20)))
monkey = finish(bpy.context.object, "Monkey", skin, True)
mod = monkey.modifiers.new("subd", 'SUBSURF')
mod.levels = 1
bpy.ops.object.modifier_apply(modifier="subd")
bpy.ops.mesh.primitive_plane_add(size=8, location=(0, 0, 0))
finish(bpy.context.object, "Floor", floor, False)
camera("ShotCam", (4.2, -5.0, 3.6), (0, 0, 1.1))
export("still-life")

# A ball sunk into a slab, a post through it.
reset()
stone, red, steel = material("Stone", (0.5, 0.5, 0.48, 1)), material("Red", (0.8, 0.08, 0.06, 1)), material("Steel", (0.45, 0.47, 0.5, 1))
gold, floor = material("Gold", (0.9, 0.7, 0.2, 1)), material("Floor", (0.25, 0.35, 0.3, 1))
box("Slab", stone, (3.0, 2.0, 0.4), (0, 0, 0.2))
sphere("Ball", red, 0.6, (-0.7, 0, 0.4))
cylinder("Post", steel, 0.15, 2.0, (0.8, 0.2, 0.9))
bpy.ops.mesh.primitive_torus_add(major_radius=0.35, minor_radius=0.08, location=(0.8, 0.2, 1.2),
                                 rotation=(math.radians(10), 0, 0))
finish(bpy.context.object, "Ring", gold, True)
bpy.ops.mesh.primitive_cone_add(vertices=40, radius1=0.5, depth=1.2, location=(1.0, -1.6, 0.3))
finish(bpy.context.object, "Cone", gold, False)
bpy.ops.mesh.primitive_plane_add(size=8, location=(0, 0, 0.0))
finish(bpy.context.object, "Floor", floor, False)
camera("ShotCam", (3.5, -5.0, 3.5), (0, 0, 0.4))
export("sunk")

# Objects through each other, and one through itself.
reset()
red, blue, steel = material("Red", (0.8, 0.08, 0.06, 1)), material("Blue", (0.1, 0.2, 0.8, 1)), material("Steel", (0.45, 0.47, 0.5, 1))
gold, card, floor = material("Gold", (0.9, 0.7, 0.2, 1)), material("Cardboard", (0.7, 0.55, 0.3, 1)), material("Floor", (0.25, 0.35, 0.3, 1))
sphere("BallA", red, 0.7, (-1.2, 0, 0.9))
sphere("BallB", blue, 0.55, (-0.5, 0.2, 1.1))
sphere("BallC", blue, 0.5, (1.2, 1.0, 0.7))
cylinder("Rod", steel, 0.12, 2.2, (1.2, 1.0, 0.7), rotation=(0, math.radians(70), math.radians(20)))
box("Crate", card, (0.8, 0.8, 0.8), (0.9, -1.0, 0.5))
bpy.ops.mesh.primitive_torus_add(major_radius=0.55, minor_radius=0.12, location=(0.9, -1.0, 0.9),
                                 rotation=(math.radians(90), 0, math.radians(30)))
finish(bpy.context.object, "Torus", gold, True)
bpy.ops.mesh.primitive_cube_add(size=0.6, location=(-1.0, -1.4, 0.3))
cross = bpy.context.object
bpy.ops.mesh.primitive_cube_add(size=0.6, location=(-0.8, -1.2, 0.5), rotation=(0.3, 0.4, 0.2))
other = bpy.context.object
bpy.ops.object.select_all(action='DESELECT')
cross.select_set(True)
other.select_set(True)
bpy.context.view_layer.objects.active = cross
bpy.ops.object.join()
finish(cross, "SelfCross", red, False)
bpy.ops.mesh.primitive_plane_add(size=8, location=(0, 0, 0.0))
finish(bpy.context.object, "Floor", floor, False)
camera("ShotCam", (4.0, -5.0, 3.2), (0, 0, 0.6))
export("crossing")

# Objects apart.
reset()
red, blue, steel = material("Red", (0.8, 0.08, 0.06, 1)), material("Blue", (0.1, 0.2, 0.8, 1)), material("Steel", (0.45, 0.47, 0.5, 1))
gold, card = material("Gold", (0.9, 0.7, 0.2, 1)), material("Cardboard", (0.7, 0.55, 0.3, 1))
sphere("BallA", red, 0.6, (-1.0, 0, 0.8))
sphere("BallB", blue, 0.35, (0.4, 1.4, 1.2))
cylinder("Can", steel, 0.3, 1.2, (0.9, -0.6, 0.7), rotation=(math.radians(20), 0, 0))
box("Crate", card, (0.6, 0.6, 0.6), (-0.4, -1.5, 0.4))
bpy.ops.mesh.primitive_torus_add(major_radius=0.45, minor_radius=0.1, location=(1.6, 1.0, 0.5),
                                 rotation=(math.radians(60), 0, 0))
finish(bpy.context.object, "Torus", gold, True)
camera("ShotCam", (4.0, -5.0, 3.2), (0, 0, 0.6))
export("apart")

# A ball rolling through a box: it enters through one wall, half sunk in
# the box's top, runs along it and leaves through the far wall.
reset()
scene = bpy.context.scene
scene.render.fps = 24
scene.frame_start, scene.frame_end = 1, 96
red, card = material("Red", (0.8, 0.08, 0.06, 1)), material("Cardboard", (0.7, 0.55, 0.3, 1))
box("Box", card, (2.4, 1.4, 0.8), (0, 0, 0.4))
ball = sphere("Ball", red, 0.4, (-1.5, 0, 0.8), segments=32, rings=16)
ball.keyframe_insert("location", frame=1)
ball.keyframe_insert("rotation_euler", frame=1)
ball.location = (1.5, 0, 0.8)
ball.rotation_euler = (0, 3.0 / 0.4, 0)
ball.keyframe_insert("location", frame=96)
ball.keyframe_insert("rotation_euler", frame=96)
for fc in ball.animation_data.action.fcurves:
    for k in fc.keyframe_points:
        k.interpolation = 'LINEAR'
camera("ShotCam", (3.0, -5.0, 3.0), (0, 0, 0.4))
export("rolling", collada=False)
