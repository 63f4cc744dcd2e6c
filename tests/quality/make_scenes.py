# The quality corpus's own scenes (scripts/quality.sh, docs/quality.md),
# written by Blender 3.4's exporters (glTF, FBX, Collada, OBJ, PLY) so that
# the corpus holds files of several exporters, made the way users make them:
#   walker.glb        a character of primitives skinned to an armature (hips,
#                     spine, head, arms, legs), a 24-frame walk cycle
#   waver.fbx         the same character, waving an arm (FBX's armature)
#   snake.glb         a tube skinned to a chain of six bones, wriggling
#   car.gltf          a car: bevelled body, cabin, four wheels (smooth sides,
#                     flat caps), lamps; five materials, a camera
#   truck.fbx         a truck: cab, box, six wheels; FBX
#   chair.obj         a chair of bevelled boxes, with the file's normals
#   dining.dae        a table with four chairs round it, a plate, a bowl and
#                     a vase resting on it, a floor; Collada
#   shelf.glb         a bookshelf with books leaning and standing, a vase
#   house.fbx         walls, a gabled roof, windows and a door set in, a
#                     chimney through the roof, a ground plane
#   room.gltf         a room's floor and walls, a sofa, a lamp, a rug, and a
#                     camera inside the room
#   stairs.dae        a stair of twelve steps with posts and a handrail
#   cage.obj          a subdivision cage (a box with two extrusions), no normals
#   cage-smooth.obj   the same cage subdivided twice, smooth, with normals
#   cube.obj, cylinder.obj, part.obj
#                     a cube, a 32-sided cylinder and a CAD-like part (a
#                     plate with a boss, bevelled, holes cut; triangulated by
#                     Blender, its faces with holes being n-gons), no normals
#   rock-N.ply        scan-like: a subdivided icosphere displaced by noise, at
#                     three noise levels (N = 1, 2, 3), no normals, as a
#                     scanner's PLY gives it
#   bust-N.ply        scan-like: Suzanne subdivided three times with noise at
#                     two levels, no normals
#   blender -b -P make_scenes.py -- OUTDIR
import math
import os
import sys

import bpy

sys.path.insert(0, os.path.join(os.path.dirname(os.path.abspath(__file__)), "..", "support"))
from blender_scene import apply_modifier, box, camera, finish, material, sphere  # noqa: E402
from blender_scene import cylinder as base_cylinder  # noqa: E402
from blender_scene import reset as base_reset  # noqa: E402


def cylinder(name, mat, radius, depth, location, rotation=(0, 0, 0), vertices=32):
    return base_cylinder(name, mat, radius, depth, location, rotation, vertices)

out = sys.argv[sys.argv.index("--") + 1] if "--" in sys.argv else os.getcwd()
os.makedirs(out, exist_ok=True)


def reset():
    base_reset()
    bpy.context.scene.render.fps = 24


def select_all():
    bpy.ops.object.select_all(action='SELECT')


def gltf(name, binary=False, animation=False):
    select_all()
    bpy.ops.export_scene.gltf(filepath=os.path.join(out, name), export_format='GLB' if binary else 'GLTF_SEPARATE',
                              export_cameras=True, export_apply=True, export_animations=animation)


def fbx(name):
    select_all()
    bpy.ops.export_scene.fbx(filepath=os.path.join(out, name), use_selection=True, bake_anim=True)


def collada(name):
    select_all()
    bpy.ops.wm.collada_export(filepath=os.path.join(out, name), triangulate=True)


def obj(name, normals=True, triangulate=False):
    select_all()
    bpy.ops.wm.obj_export(filepath=os.path.join(out, name), export_normals=normals, export_uv=False,
                          export_materials=False, export_selected_objects=True,
                          export_triangulated_mesh=triangulate)


def ply(name):
    select_all()
    o = bpy.context.view_layer.objects.active or bpy.context.selected_objects[0]
    bpy.context.view_layer.objects.active = o
    bpy.ops.export_mesh.ply(filepath=os.path.join(out, name), use_normals=False, use_uv_coords=False,
                            use_colors=False, use_selection=True)


def join(objects, name, mat, smooth=True):
    bpy.ops.object.select_all(action='DESELECT')
    for o in objects:
        o.select_set(True)
    bpy.context.view_layer.objects.active = objects[0]
    bpy.ops.object.join()
    body = objects[0]
    finish(body, name, None, smooth)
    return body


def new_armature(name):
    """An armature object named @p name in edit mode: (object, its edit bones)."""
    bpy.ops.object.armature_add(location=(0, 0, 0))
    rig = bpy.context.object
    rig.name = name
    bpy.ops.object.mode_set(mode='EDIT')
    return rig, rig.data.edit_bones


def bind(mesh, rig):
    """@p mesh skinned to @p rig by Blender's automatic weights."""
    bpy.ops.object.mode_set(mode='OBJECT')
    bpy.ops.object.select_all(action='DESELECT')
    mesh.select_set(True)
    rig.select_set(True)
    bpy.context.view_layer.objects.active = rig
    bpy.ops.object.parent_set(type='ARMATURE_AUTO')


def character(skin, cloth):
    """A figure of primitives joined into one mesh, skinned to an armature
    by Blender's automatic weights: returns (mesh, armature)."""
    parts = []
    bpy.ops.mesh.primitive_uv_sphere_add(segments=24, ring_count=12, radius=0.22, location=(0, 0, 1.62))
    parts.append(bpy.context.object)
    for loc, scale in [((0, 0, 1.15), (0.28, 0.18, 0.35)), ((0, 0, 0.82), (0.24, 0.16, 0.14))]:
        bpy.ops.mesh.primitive_uv_sphere_add(segments=24, ring_count=12, radius=1.0, location=loc)
        o = bpy.context.object
        o.scale = scale
        parts.append(o)
    for side in (-1, 1):
        bpy.ops.mesh.primitive_cylinder_add(vertices=16, radius=0.065, depth=0.62, location=(side * 0.38, 0, 1.12))
        parts.append(bpy.context.object)
        bpy.ops.mesh.primitive_cylinder_add(vertices=16, radius=0.09, depth=0.8, location=(side * 0.12, 0, 0.42))
        parts.append(bpy.context.object)
    for o in parts:
        bpy.context.view_layer.objects.active = o
        bpy.ops.object.transform_apply(location=False, rotation=False, scale=True)
    body = join(parts, "Body", None)
    body.data.materials.append(skin)
    body.data.materials.append(cloth)
    for p in body.data.polygons:
        p.material_index = 1 if p.center.z < 1.4 else 0
    apply_modifier(body, 'REMESH', mode='SMOOTH', octree_depth=6, use_smooth_shade=True)
    rig, bones = new_armature("Rig")
    root = bones[0]
    root.name, root.head, root.tail = "Hips", (0, 0, 0.85), (0, 0, 1.05)
    def bone(name, head, tail, parent):
        b = bones.new(name)
        b.head, b.tail, b.parent = head, tail, parent
        return b
    spine = bone("Spine", (0, 0, 1.05), (0, 0, 1.42), root)
    bone("Head", (0, 0, 1.42), (0, 0, 1.85), spine)
    for side, tag in ((-1, "L"), (1, "R")):
        bone("Arm." + tag, (side * 0.38, 0, 1.42), (side * 0.38, 0, 0.82), spine)
        bone("Leg." + tag, (side * 0.12, 0, 0.85), (side * 0.12, 0, 0.02), root)
    bind(body, rig)
    return body, rig


def keys(rig, frames, poses):
    """Rotation keys: poses[bone] = list of (frame, (x, y, z) degrees)."""
    bpy.context.view_layer.objects.active = rig
    bpy.ops.object.mode_set(mode='POSE')
    for name, track in poses.items():
        pb = rig.pose.bones[name]
        pb.rotation_mode = 'XYZ'
        for frame, deg in track:
            pb.rotation_euler = [math.radians(d) for d in deg]
            pb.keyframe_insert("rotation_euler", frame=frame)
    bpy.ops.object.mode_set(mode='OBJECT')
    bpy.context.scene.frame_start, bpy.context.scene.frame_end = 1, frames


# Characters.
reset()
skin, cloth = material("Skin", (0.9, 0.6, 0.45, 1)), material("Cloth", (0.2, 0.3, 0.7, 1))
body, rig = character(skin, cloth)
keys(rig, 24, {"Leg.L": [(1, (30, 0, 0)), (13, (-30, 0, 0)), (24, (30, 0, 0))],
               "Leg.R": [(1, (-30, 0, 0)), (13, (30, 0, 0)), (24, (-30, 0, 0))],
               "Arm.L": [(1, (-25, 0, 0)), (13, (25, 0, 0)), (24, (-25, 0, 0))],
               "Arm.R": [(1, (25, 0, 0)), (13, (-25, 0, 0)), (24, (25, 0, 0))],
               "Spine": [(1, (0, 0, 8)), (13, (0, 0, -8)), (24, (0, 0, 8))]})
gltf("walker.glb", binary=True, animation=True)

reset()
skin, cloth = material("Skin", (0.9, 0.6, 0.45, 1)), material("Cloth", (0.6, 0.2, 0.2, 1))
body, rig = character(skin, cloth)
keys(rig, 36, {"Arm.R": [(1, (0, 0, 0)), (12, (0, 150, 0)), (24, (0, 110, 0)), (36, (0, 150, 0))],
               "Head": [(1, (0, 0, 0)), (18, (10, 0, 20)), (36, (0, 0, 0))]})
fbx("waver.fbx")

reset()
scales = material("Scales", (0.3, 0.6, 0.2, 1))
bpy.ops.mesh.primitive_cylinder_add(vertices=20, radius=0.15, depth=3.0, location=(0, 0, 0), rotation=(0, math.radians(90), 0))
tube = bpy.context.object
bpy.ops.object.transform_apply(location=False, rotation=True, scale=False)
finish(tube, "Snake", scales, True)
bpy.ops.object.mode_set(mode='EDIT')
bpy.ops.mesh.select_all(action='SELECT')
bpy.ops.mesh.subdivide(number_cuts=24)
bpy.ops.object.mode_set(mode='OBJECT')
rig, bones = new_armature("Spine")
prev = bones[0]
prev.name, prev.head, prev.tail = "B0", (-1.5, 0, 0), (-1.0, 0, 0)
for i in range(1, 6):
    b = bones.new("B%d" % i)
    b.head, b.tail, b.parent = (-1.5 + 0.5 * i, 0, 0), (-1.0 + 0.5 * i, 0, 0), prev
    b.use_connect = True
    prev = b
bind(tube, rig)
keys(rig, 32, {"B%d" % i: [(1, (0, 0, 20 * math.sin(i))), (17, (0, 0, -20 * math.sin(i))), (32, (0, 0, 20 * math.sin(i)))]
               for i in range(1, 6)})
gltf("snake.glb", binary=True, animation=True)

# Vehicles.
reset()
paint, glass, rubber = material("Paint", (0.8, 0.1, 0.1, 1)), material("Glass", (0.2, 0.3, 0.4, 1)), material("Rubber", (0.05, 0.05, 0.05, 1))
chrome, lamp = material("Chrome", (0.8, 0.8, 0.85, 1)), material("Lamp", (1.0, 0.95, 0.7, 1))
box("Body", paint, (4.0, 1.7, 0.7), (0, 0, 0.65), bevel=0.12)
box("Cabin", glass, (2.0, 1.5, 0.6), (-0.3, 0, 1.25), bevel=0.1)
for i, (x, y) in enumerate([(1.3, 0.85), (1.3, -0.85), (-1.3, 0.85), (-1.3, -0.85)]):
    cylinder("Wheel%d" % i, rubber, 0.36, 0.28, (x, y, 0.36), rotation=(math.radians(90), 0, 0), vertices=32)
    cylinder("Hub%d" % i, chrome, 0.18, 0.3, (x, y, 0.36), rotation=(math.radians(90), 0, 0), vertices=16)
for y in (0.55, -0.55):
    sphere("Lamp%s" % ("L" if y > 0 else "R"), lamp, 0.12, (2.0, y, 0.75), segments=16, rings=8)
camera("Shot", (7.0, -6.0, 3.5), (0, 0, 0.7), lens=35)
gltf("car.gltf")

reset()
paint, metal, rubber = material("Paint", (0.2, 0.4, 0.7, 1)), material("Metal", (0.6, 0.6, 0.6, 1)), material("Rubber", (0.05, 0.05, 0.05, 1))
box("Cab", paint, (1.6, 2.0, 1.8), (2.4, 0, 1.45), bevel=0.08)
box("Cargo", metal, (4.2, 2.2, 2.4), (-0.6, 0, 1.75))
box("Chassis", metal, (6.0, 1.6, 0.3), (0.2, 0, 0.6))
for i, (x, y) in enumerate([(2.4, 1.0), (2.4, -1.0), (-0.6, 1.0), (-0.6, -1.0), (-1.8, 1.0), (-1.8, -1.0)]):
    cylinder("Wheel%d" % i, rubber, 0.45, 0.35, (x, y, 0.45), rotation=(math.radians(90), 0, 0), vertices=24)
fbx("truck.fbx")

# Furniture.
def chair(mat, x, y, turn):
    parts = [box("Seat", mat, (0.5, 0.5, 0.06), (0, 0, 0.47), bevel=0.01),
             box("Back", mat, (0.5, 0.05, 0.55), (0, 0.225, 0.78), bevel=0.01)]
    for dx, dy in [(-0.21, -0.21), (0.21, -0.21), (-0.21, 0.21), (0.21, 0.21)]:
        parts.append(box("Leg", mat, (0.05, 0.05, 0.45), (dx, dy, 0.225)))
    c = join(parts, "Chair", None, smooth=False)
    c.location = (x, y, 0)
    c.rotation_euler = (0, 0, math.radians(turn))
    return c


reset()
wood = material("Wood", (0.55, 0.33, 0.15, 1))
chair(wood, 0, 0, 0)
obj("chair.obj", normals=True)

reset()
wood, cloth = material("Wood", (0.55, 0.33, 0.15, 1)), material("Cloth", (0.9, 0.9, 0.85, 1))
ceramic, glaze, floor = material("Ceramic", (0.95, 0.95, 0.9, 1)), material("Glaze", (0.2, 0.5, 0.6, 1)), material("Floor", (0.3, 0.3, 0.28, 1))
box("Top", wood, (1.8, 1.0, 0.05), (0, 0, 0.75), bevel=0.01)
for i, (x, y) in enumerate([(-0.8, -0.4), (0.8, -0.4), (-0.8, 0.4), (0.8, 0.4)]):
    box("TableLeg%d" % i, wood, (0.07, 0.07, 0.76), (x, y, 0.37))  # up into the top
for x, y, turn in [(0, -0.75, 180), (0, 0.75, 0), (-1.1, 0, 90), (1.1, 0, 270)]:
    chair(wood, x, y, turn)
cylinder("Plate", ceramic, 0.14, 0.02, (-0.3, -0.2, 0.785), vertices=40)
bpy.ops.mesh.primitive_uv_sphere_add(segments=32, ring_count=16, radius=0.12, location=(0.3, 0.1, 0.86))
bowl = finish(bpy.context.object, "Bowl", glaze, True)
bowl.scale = (1, 1, 0.6)
cylinder("Vase", glaze, 0.07, 0.3, (0.5, -0.2, 0.925), vertices=24)
bpy.ops.mesh.primitive_plane_add(size=6, location=(0, 0, 0))
finish(bpy.context.object, "Floor", floor, False)
collada("dining.dae")

reset()
wood, red, blue, green = (material("Wood", (0.5, 0.35, 0.2, 1)), material("Red", (0.7, 0.1, 0.1, 1)),
                          material("Blue", (0.1, 0.2, 0.6, 1)), material("Green", (0.1, 0.5, 0.2, 1)))
box("Left", wood, (0.04, 0.35, 1.8), (-0.6, 0, 0.9))
box("Right", wood, (0.04, 0.35, 1.8), (0.6, 0, 0.9))
for i, z in enumerate([0.02, 0.6, 1.2, 1.78]):
    box("Board%d" % i, wood, (1.2, 0.35, 0.04), (0, 0, z))
colours = [red, blue, green]
x = -0.55
for i in range(11):
    w = 0.04 + 0.01 * (i % 3)
    h = 0.3 + 0.03 * (i % 4)
    lean = math.radians(12) if i == 8 else 0.0
    box("Book%d" % i, colours[i % 3], (w, 0.24, h), (x + w / 2, 0, 0.62 + h / 2), rotation=(0, lean, 0), bevel=0.003)
    x += w + 0.005 + (0.06 if i == 8 else 0)
cylinder("Vase", blue, 0.08, 0.3, (0.3, 0, 1.37), vertices=32)
gltf("shelf.glb", binary=True)

# Architecture.
reset()
wall, roof, glass, door, ground = (material("Wall", (0.9, 0.85, 0.75, 1)), material("Roof", (0.5, 0.15, 0.1, 1)),
                                    material("Glass", (0.3, 0.4, 0.5, 1)), material("Door", (0.4, 0.25, 0.1, 1)),
                                    material("Ground", (0.3, 0.45, 0.25, 1)))
box("Walls", wall, (6.0, 4.0, 3.0), (0, 0, 1.5))
bpy.ops.mesh.primitive_cylinder_add(vertices=3, radius=2.6, depth=6.4, location=(0, 0, 3.0 + 1.3 * 0.5),
                                    rotation=(math.radians(90), 0, math.radians(90)))
r = finish(bpy.context.object, "Roof", roof, False)
r.scale = (1.0, 0.62, 1.0)
for i, x in enumerate([-2.0, 2.0]):
    box("Window%d" % i, glass, (1.0, 0.1, 1.0), (x, -1.97, 1.8))
box("Door", door, (1.0, 0.1, 2.0), (0, -1.97, 1.0))
box("Chimney", wall, (0.5, 0.5, 2.0), (1.5, 0.8, 4.0))
bpy.ops.mesh.primitive_plane_add(size=20, location=(0, 0, 0))
finish(bpy.context.object, "Ground", ground, False)
fbx("house.fbx")

reset()
floor, wall, fabric, brass, rug = (material("Floor", (0.6, 0.45, 0.3, 1)), material("Wall", (0.85, 0.85, 0.8, 1)),
                                   material("Fabric", (0.3, 0.5, 0.4, 1)), material("Brass", (0.8, 0.65, 0.3, 1)),
                                   material("Rug", (0.6, 0.2, 0.25, 1)))
box("Floor", floor, (8.0, 6.0, 0.1), (0, 0, -0.05))
box("BackWall", wall, (8.0, 0.1, 3.0), (0, 3.0, 1.5))
box("SideWall", wall, (0.1, 6.0, 3.0), (-4.0, 0, 1.5))
box("Seat", fabric, (2.2, 0.9, 0.45), (0, 2.3, 0.225), bevel=0.05)
box("SofaBack", fabric, (2.2, 0.25, 0.5), (0, 2.68, 0.7), bevel=0.05)
for x in (-1.1, 1.1):
    box("SofaArm", fabric, (0.25, 0.9, 0.6), (x, 2.3, 0.3), bevel=0.05)
cylinder("LampPole", brass, 0.03, 1.6, (2.0, 2.4, 0.8), vertices=16)
bpy.ops.mesh.primitive_cone_add(vertices=32, radius1=0.3, radius2=0.15, depth=0.35, location=(2.0, 2.4, 1.7))
finish(bpy.context.object, "Shade", brass, True)
cylinder("Rug", rug, 1.2, 0.02, (0, 0.8, 0.01), vertices=48)
camera("Inside", (1.5, -2.5, 1.6), (0, 1.5, 0.6), lens=24)
gltf("room.gltf")

reset()
stone, steel = material("Stone", (0.6, 0.6, 0.58, 1)), material("Steel", (0.3, 0.3, 0.32, 1))
for i in range(12):
    box("Step%d" % i, stone, (1.2, 0.3, 0.18), (0, 0.3 * i, 0.09 + 0.18 * i))
for i in range(0, 12, 3):
    cylinder("Post%d" % i, steel, 0.025, 0.9, (0.55, 0.3 * i, 0.18 * (i + 1) + 0.45), vertices=12)
rail_len = math.hypot(0.3 * 9, 0.18 * 9)
cylinder("Rail", steel, 0.03, rail_len + 0.4, (0.55, 0.3 * 4.5, 0.18 * 5.5 + 0.9),
         rotation=(math.atan2(0.18, 0.3) - math.radians(90), 0, 0), vertices=12)
collada("stairs.dae")

# Subdivision cage and its smooth surface.
reset()
bpy.ops.mesh.primitive_cube_add(size=1.0)
cage = finish(bpy.context.object, "Cage", None, False)
bpy.ops.object.mode_set(mode='EDIT')
bpy.ops.mesh.select_all(action='DESELECT')
bpy.ops.object.mode_set(mode='OBJECT')
for p in cage.data.polygons:
    p.select = p.normal.z > 0.5 or p.normal.x > 0.5
bpy.ops.object.mode_set(mode='EDIT')
bpy.ops.mesh.extrude_region_shrink_fatten(TRANSFORM_OT_shrink_fatten={"value": 0.4})
bpy.ops.object.mode_set(mode='OBJECT')
obj("cage.obj", normals=False)
apply_modifier(cage, 'SUBSURF', levels=2)
for p in cage.data.polygons:
    p.use_smooth = True
obj("cage-smooth.obj", normals=True)

# Meshes without normals.
reset()
bpy.ops.mesh.primitive_cube_add(size=1.0)
obj("cube.obj", normals=False)
reset()
bpy.ops.mesh.primitive_cylinder_add(vertices=32, radius=0.5, depth=1.5)
obj("cylinder.obj", normals=False)
reset()
plate = box("Plate", None, (2.0, 1.2, 0.25), (0, 0, 0.125), bevel=0.03)
boss = cylinder("Boss", None, 0.3, 0.5, (0.4, 0, 0.45), vertices=32)
bpy.context.view_layer.objects.active = plate
mod = plate.modifiers.new("union", 'BOOLEAN')
mod.operation, mod.object = 'UNION', boss
bpy.ops.object.modifier_apply(modifier=mod.name)
bpy.data.objects.remove(boss)
for i, x in enumerate([-0.7, -0.2]):
    hole = cylinder("Hole%d" % i, None, 0.12, 1.0, (x, 0, 0.1), vertices=24)
    bpy.context.view_layer.objects.active = plate
    mod = plate.modifiers.new("cut%d" % i, 'BOOLEAN')
    mod.operation, mod.object = 'DIFFERENCE', hole
    bpy.ops.object.modifier_apply(modifier=mod.name)
    bpy.data.objects.remove(hole)
obj("part.obj", normals=False, triangulate=True)  # its faces with holes: Blender triangulates them

# Scan-like meshes: noise displaced along the normals, no normals written.
for level, strength in enumerate([0.02, 0.05, 0.1], start=1):
    reset()
    bpy.ops.mesh.primitive_ico_sphere_add(subdivisions=6, radius=1.0)
    rock = bpy.context.object
    tex = bpy.data.textures.new("noise", 'CLOUDS')
    tex.noise_scale = 0.4
    apply_modifier(rock, 'DISPLACE', texture=tex, strength=0.4)
    fine = bpy.data.textures.new("fine", 'CLOUDS')
    fine.noise_scale = 0.03
    apply_modifier(rock, 'DISPLACE', texture=fine, strength=strength)
    ply("rock-%d.ply" % level)
for level, strength in enumerate([0.01, 0.03], start=1):
    reset()
    bpy.ops.mesh.primitive_monkey_add(size=2.0)
    bust = bpy.context.object
    apply_modifier(bust, 'SUBSURF', levels=3)
    fine = bpy.data.textures.new("fine", 'CLOUDS')
    fine.noise_scale = 0.02
    apply_modifier(bust, 'DISPLACE', texture=fine, strength=strength)
    ply("bust-%d.ply" % level)
