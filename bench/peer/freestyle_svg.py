"""Blender (run as `blender -b --factory-startup --python freestyle_svg.py --
MESH OUT_DIR FRAMES DEG`): imports MESH, turns it DEG degrees per frame
about the vertical axis for FRAMES frames under an orthographic camera, and
renders Freestyle's visible silhouette and border lines with the bundled
SVG exporter in animation mode (one SVG with every frame), at 800 x 800.
The render itself is Cycles at one sample (Freestyle needs a render)."""
import math
import sys

import addon_utils
import bpy
import mathutils

mesh_path, out_dir, frames, degrees = sys.argv[sys.argv.index("--") + 1:][:4]
frames, degrees = int(frames), float(degrees)

bpy.ops.wm.read_factory_settings(use_empty=True)
addon_utils.enable("render_freestyle_svg", default_set=True)
scene = bpy.context.scene
bpy.ops.wm.obj_import(filepath=mesh_path, forward_axis='NEGATIVE_Z', up_axis='Y')
obj = bpy.context.selected_objects[0]
# Turntable: the object turns about the vertical axis, DEG per frame.
scene.frame_start, scene.frame_end = 1, frames
obj.rotation_mode = 'XYZ'
obj.rotation_euler = (0.0, 0.0, 0.0)
obj.keyframe_insert("rotation_euler", index=2, frame=1)
obj.rotation_euler[2] = math.radians(degrees * (frames - 1))
obj.keyframe_insert("rotation_euler", index=2, frame=frames)
for fc in obj.animation_data.action.fcurves:
    for k in fc.keyframe_points:
        k.interpolation = 'LINEAR'

# Framed as snaxels-cli frames it: the bounding box's sphere fills the
# 800-pixel image less a 32-pixel margin on each side.
corners = [obj.matrix_world @ mathutils.Vector(c) for c in obj.bound_box]
lo = mathutils.Vector([min(c[i] for c in corners) for i in range(3)])
hi = mathutils.Vector([max(c[i] for c in corners) for i in range(3)])
centre, radius = (lo + hi) / 2.0, (hi - lo).length / 2.0
cam_data = bpy.data.cameras.new("camera")
cam_data.type = 'ORTHO'
cam_data.ortho_scale = 2.0 * radius * 800.0 / (800.0 - 2.0 * 32.0)
cam_data.clip_end = 100.0 * radius
cam = bpy.data.objects.new("camera", cam_data)
scene.collection.objects.link(cam)
cam.location = (centre.x, centre.y - 4.0 * radius, centre.z)
cam.rotation_euler = (math.radians(90.0), 0.0, 0.0)
scene.camera = cam

scene.render.engine = 'CYCLES'
scene.cycles.samples = 1
scene.cycles.device = 'CPU'
scene.cycles.use_denoising = False  # Debian's build has no OpenImageDenoise
scene.render.resolution_x = scene.render.resolution_y = 800
scene.render.resolution_percentage = 100
scene.render.use_freestyle = True
scene.render.line_thickness_mode = 'ABSOLUTE'
layer = scene.view_layers[0]
layer.use_freestyle = True
settings = layer.freestyle_settings
settings.mode = 'EDITOR'
lineset = settings.linesets[0] if settings.linesets else settings.linesets.new("outline")
if lineset.linestyle is None:
    lineset.linestyle = bpy.data.linestyles.new("outline")
lineset.linestyle.thickness = 1.0
lineset.select_by_visibility = True
lineset.visibility = 'VISIBLE'
lineset.select_by_edge_types = True
for edge_type in ("silhouette", "border", "crease", "ridge_valley", "suggestive_contour", "material_boundary",
                  "contour", "external_contour", "edge_mark"):
    setattr(lineset, "select_" + edge_type, edge_type in ("silhouette", "border"))

scene.svg_export.use_svg_export = True
scene.svg_export.mode = 'ANIMATION'
scene.render.filepath = out_dir.rstrip("/") + "/freestyle_"
scene.render.image_settings.file_format = 'PNG'
bpy.ops.render.render(animation=True)
