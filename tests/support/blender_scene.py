# Helpers shared by the Blender scripts that write the tests' scenes
# (tests/assets/meet/make_meet.py, tests/quality/make_scenes.py): a
# script finds this folder from its own path and imports these.
import mathutils

import bpy


def reset():
    bpy.ops.wm.read_factory_settings(use_empty=True)


def material(name, rgba):
    m = bpy.data.materials.get(name) or bpy.data.materials.new(name)
    m.diffuse_color = rgba
    m.use_nodes = True
    m.node_tree.nodes["Principled BSDF"].inputs["Base Color"].default_value = rgba
    return m


def finish(obj, name, mat, smooth):
    """Names @p obj and its mesh, gives it @p mat (None: none) and shades
    every face smooth or flat."""
    obj.name = name
    obj.data.name = name + "Mesh"
    if mat:
        obj.data.materials.append(mat)
    for p in obj.data.polygons:
        p.use_smooth = smooth
    return obj


def apply_modifier(obj, kind, **settings):
    bpy.context.view_layer.objects.active = obj
    mod = obj.modifiers.new(kind.lower(), kind)
    for k, v in settings.items():
        setattr(mod, k, v)
    bpy.ops.object.modifier_apply(modifier=mod.name)


def box(name, mat, size, location, rotation=(0, 0, 0), bevel=0.0):
    """A flat-shaded box of @p size, bevelled (two segments) when @p bevel > 0."""
    bpy.ops.mesh.primitive_cube_add(size=1.0, location=location, rotation=rotation)
    o = bpy.context.object
    o.scale = size
    bpy.ops.object.transform_apply(location=False, rotation=False, scale=True)
    finish(o, name, mat, False)
    if bevel > 0:
        apply_modifier(o, 'BEVEL', width=bevel, segments=2)
    return o


def sphere(name, mat, radius, location, segments=48, rings=24):
    bpy.ops.mesh.primitive_uv_sphere_add(segments=segments, ring_count=rings, radius=radius, location=location)
    return finish(bpy.context.object, name, mat, True)


def cylinder(name, mat, radius, depth, location, rotation=(0, 0, 0), vertices=40):
    """The side smooth, the caps flat."""
    bpy.ops.mesh.primitive_cylinder_add(vertices=vertices, radius=radius, depth=depth, location=location,
                                        rotation=rotation)
    o = finish(bpy.context.object, name, mat, True)
    for p in o.data.polygons:
        p.use_smooth = len(p.vertices) == 4
    return o


def camera(name, location, target, lens=40):
    """A camera at @p location looking at @p target, the scene's camera."""
    bpy.ops.object.camera_add(location=location)
    cam = bpy.context.object
    cam.name = name
    cam.data.lens = lens
    direction = mathutils.Vector(target) - mathutils.Vector(location)
    cam.rotation_euler = direction.to_track_quat('-Z', 'Y').to_euler()
    bpy.context.scene.camera = cam
    return cam
