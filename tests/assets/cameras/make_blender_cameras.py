# Writes blender-shot.gltf (+ .bin), .fbx and .dae: Suzanne filmed by
# "ShotCam" (perspective, 50 degrees across a 1600 x 900 frame) that flies
# from Blender's (0, -6, 1.5) looking at her face to (6, 0, 1.5) looking at
# her side over frames 1-48 at 24 fps, and "TopOrtho" (orthographic, 4
# units across) 8 units above her. The same scene through three exporters,
# for tests/core/mesh/test_file_cameras.cpp.
#   blender -b -P make_blender_cameras.py -- OUTDIR
import math
import os
import sys

import bpy

out = sys.argv[sys.argv.index("--") + 1] if "--" in sys.argv else os.path.dirname(os.path.abspath(__file__))
bpy.ops.wm.read_factory_settings(use_empty=True)
scene = bpy.context.scene
scene.render.resolution_x, scene.render.resolution_y = 1600, 900
scene.render.fps = 24
bpy.ops.mesh.primitive_monkey_add(location=(0, 0, 0))
bpy.ops.object.camera_add(location=(0, -6, 1.5))
cam = bpy.context.object
cam.name = "ShotCam"
cam.data.sensor_fit = 'AUTO'
cam.data.angle = math.radians(50)
cam.rotation_euler = (math.radians(80), 0, 0)
scene.camera = cam
scene.frame_start, scene.frame_end = 1, 48
cam.keyframe_insert("location", frame=1)
cam.keyframe_insert("rotation_euler", frame=1)
cam.location = (6, 0, 1.5)
cam.rotation_euler = (math.radians(80), 0, math.radians(90))
cam.keyframe_insert("location", frame=48)
cam.keyframe_insert("rotation_euler", frame=48)
bpy.ops.object.camera_add(location=(0, 0, 8))
top = bpy.context.object
top.name = "TopOrtho"
top.data.type = 'ORTHO'
top.data.ortho_scale = 4.0
bpy.ops.export_scene.gltf(filepath=os.path.join(out, "blender-shot.gltf"), export_format='GLTF_SEPARATE',
                          export_cameras=True)
bpy.ops.export_scene.fbx(filepath=os.path.join(out, "blender-shot.fbx"))
bpy.ops.wm.collada_export(filepath=os.path.join(out, "blender-shot.dae"))
