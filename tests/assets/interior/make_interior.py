# Writes a scene whose camera stands inside it, through Blender 3.4's glTF
# exporter, for the tests of near-plane clipping (cameras inside the scene):
#   walk   a ground plane 40 m across (far larger than the camera's
#          distance to anything: it runs on behind the camera), pillars,
#          crates and balls standing on it, an arch the camera passes
#          under, and a camera "WalkCam" (clip start 0.1 m, Blender's
#          default) that walks through them 1.6 m above the ground for
#          frames 1-120 at 24 fps, turning as it goes and passing close
#          by a pillar, whose outline crosses its near plane; seven
#          materials. The camera's position keys are linear, its aim a
#          track-to constraint baked into keys.
# The glTF exporter needs numpy (Debian's python3-numpy).
#   blender -b -P make_interior.py -- OUTDIR
import math
import os
import sys

import bpy

sys.path.insert(0, os.path.join(os.path.dirname(os.path.abspath(__file__)), "..", "..", "support"))
from blender_scene import box, camera, cylinder, finish, material, reset, sphere  # noqa: E402

out = sys.argv[sys.argv.index("--") + 1] if "--" in sys.argv else os.path.dirname(os.path.abspath(__file__))

reset()
scene = bpy.context.scene
scene.render.fps = 24
scene.frame_start, scene.frame_end = 1, 120
scene.render.resolution_x, scene.render.resolution_y = 1600, 900
stone, wood = material("Stone", (0.55, 0.55, 0.52, 1)), material("Wood", (0.55, 0.33, 0.15, 1))
red, blue = material("Red", (0.8, 0.08, 0.06, 1)), material("Blue", (0.1, 0.2, 0.8, 1))
card, gold = material("Cardboard", (0.7, 0.55, 0.3, 1)), material("Gold", (0.9, 0.7, 0.2, 1))
ground = material("Ground", (0.25, 0.35, 0.3, 1))

# The ground, subdivided so it has inner vertices on both sides of the camera.
bpy.ops.mesh.primitive_grid_add(x_subdivisions=8, y_subdivisions=8, size=40, location=(0, 0, 0))
finish(bpy.context.object, "Ground", ground, False)
for i, (x, y) in enumerate([(-3.0, 2.0), (3.0, 2.5), (-2.5, 7.0), (1.2, 9.0), (0.9, 4.2)]):
    cylinder("Pillar%d" % (i + 1), stone, 0.35, 4.0, (x, y, 2.0), vertices=32)
for i, (x, y, s) in enumerate([(-1.5, 4.5, 0.8), (2.5, 6.0, 1.0), (-3.5, 10.0, 1.2)]):
    box("Crate%d" % (i + 1), card, (s, s, s), (x, y, s / 2), rotation=(0, 0, math.radians(20 * i + 10)))
sphere("BallA", red, 0.5, (2.0, 3.5, 0.5))
sphere("BallB", blue, 0.7, (-1.0, 8.5, 0.7))
# An arch over the path: two posts and a beam.
box("ArchLeft", wood, (0.3, 0.3, 3.0), (-1.1, 12.0, 1.5))
box("ArchRight", wood, (0.3, 0.3, 3.0), (1.1, 12.0, 1.5))
box("ArchBeam", wood, (2.6, 0.3, 0.3), (0.0, 12.0, 3.15))
bpy.ops.mesh.primitive_torus_add(major_radius=0.5, minor_radius=0.12, location=(0.0, 12.0, 2.2),
                                 rotation=(math.radians(90), 0, 0))
finish(bpy.context.object, "Ring", gold, True)

# The walk: from behind the first pillars, between them, close by Pillar5,
# under the arch; aimed a little ahead of itself, turning.
cam = camera("WalkCam", (0.0, -3.0, 1.6), (0.0, 3.0, 1.2), lens=24)
cam.data.clip_start = 0.1
target = bpy.data.objects.new("WalkTarget", None)
scene.collection.objects.link(target)
path = [(1, (0.0, -3.0, 1.6), (0.0, 3.0, 1.2)),
        (40, (0.3, 3.2, 1.6), (1.5, 8.0, 1.0)),
        (60, (0.45, 4.2, 1.6), (0.0, 10.0, 1.4)),  # the pillar at (0.9, 4.2) 0.1 m from the eye's side
        (90, (0.0, 8.0, 1.6), (0.0, 13.0, 2.0)),
        (120, (0.0, 13.5, 1.6), (-1.0, 18.0, 1.4))]
for frame, eye, aim in path:
    cam.location = eye
    cam.keyframe_insert("location", frame=frame)
    target.location = aim
    target.keyframe_insert("location", frame=frame)
for o in (cam, target):
    for fc in o.animation_data.action.fcurves:
        for k in fc.keyframe_points:
            k.interpolation = 'LINEAR'
track = cam.constraints.new('TRACK_TO')
track.target = target
track.track_axis, track.up_axis = 'TRACK_NEGATIVE_Z', 'UP_Y'
bpy.ops.object.select_all(action='DESELECT')
cam.select_set(True)
bpy.context.view_layer.objects.active = cam
bpy.ops.nla.bake(frame_start=1, frame_end=120, only_selected=True, visual_keying=True, clear_constraints=True,
                 bake_types={'OBJECT'})
bpy.data.objects.remove(target)

bpy.ops.object.select_all(action='SELECT')
bpy.ops.export_scene.gltf(filepath=os.path.join(out, "walk.gltf"), export_format='GLTF_SEPARATE',
                          export_cameras=True, export_apply=True)
