# A reference picture of a glTF file from an independent importer: Blender's (the Khronos glTF-Blender-IO add-on)
# rendered with Cycles, framed as vkmc frames it. For the real-file galleries, whose files come with no screenshot:
# tools/gltf_reference.sh runs it per file, and tools/gltf_gallery.sh --references puts each beside vkmc's render.
#   blender -b --factory-startup --python render_reference.py -- SCENE OUT.png [--width W --height H --spp N]
# The file's first camera where it has one; otherwise vkmc's automatic camera (scene/camera_rig.h autoCamera: 30
# degrees round from +Z towards +X, 25 degrees up, a 45-degree vertical field of view fitting the bounding sphere
# to the narrower side), on the bounds of every mesh's vertices; no animation played. Light: a uniform white world
# of radiance 1 plus the file's own lights as the importer reads them; the world is hidden behind a transparent
# film, so the backdrop is the sheet's. Blender's default Filmic view, no denoiser. A reference in what the
# importer understands (its materials, skins, textures, units), not vkmc's numbers: it differs where Blender's
# importer does (Blender 3.4 reads no meshopt, KTX2 or WebP, ignores COLOR_0 on a mesh without a material, and
# gives such a mesh a grey dielectric where glTF's default material is a white rough metal), and Cycles renders
# overlapping opposite faces as black speckles.
import math
import sys

try:
    import numpy
except ImportError:
    sys.path.append("/usr/lib/python3/dist-packages")
    import numpy
if "bool" not in numpy.__dict__:  # Blender 3.4's importer uses numpy's removed `bool` alias
    numpy.bool = bool

import bpy  # noqa: E402
import mathutils  # noqa: E402


def parse_args(argv):
    import argparse
    p = argparse.ArgumentParser(prog="render_reference.py")
    p.add_argument("scene")
    p.add_argument("output")
    p.add_argument("--width", type=int, default=192)
    p.add_argument("--height", type=int, default=192)
    p.add_argument("--spp", type=int, default=32)
    p.add_argument("--threads", type=int, default=2)
    return p.parse_args(argv)


def mesh_bounds(scene):
    """The world-space box of every mesh's vertices as posed (an object's rotated bounding box would be larger)."""
    lo, hi = numpy.full(3, math.inf), numpy.full(3, -math.inf)
    depsgraph = bpy.context.evaluated_depsgraph_get()
    for obj in scene.objects:
        if obj.type != "MESH":
            continue
        evaluated = obj.evaluated_get(depsgraph)
        mesh = evaluated.to_mesh()
        co = numpy.empty(3 * len(mesh.vertices))
        mesh.vertices.foreach_get("co", co)
        evaluated.to_mesh_clear()
        if co.size == 0:
            continue
        m = numpy.array(obj.matrix_world)
        world = co.reshape(-1, 3) @ m[:3, :3].T + m[:3, 3]
        lo, hi = numpy.minimum(lo, world.min(axis=0)), numpy.maximum(hi, world.max(axis=0))
    if lo[0] > hi[0]:
        return mathutils.Vector((0, 0, 0)), 1.0
    centre = mathutils.Vector((0.5 * (lo + hi)).tolist())
    radius = 0.5 * float(numpy.linalg.norm(hi - lo))
    return centre, radius if radius > 0 else 1.0


def rest_pose(scene):
    """The file's pose without its animations, as vkmc renders it: the importer leaves the first animation playing
    (its first frame posed); armatures go back to their rest pose, the importer's reading of the bind pose."""
    for obj in scene.objects:
        if obj.animation_data:
            obj.animation_data.action = None
        if obj.type == "ARMATURE":
            for bone in obj.pose.bones:
                bone.matrix_basis = mathutils.Matrix.Identity(4)
    bpy.context.view_layer.update()


def auto_camera(scene, aspect):
    centre, radius = mesh_bounds(scene)
    yfov = math.radians(45.0)
    half = 0.5 * yfov if aspect >= 1.0 else math.atan(math.tan(0.5 * yfov) * aspect)
    distance = radius / math.sin(half)
    az, el = math.radians(30.0), math.radians(25.0)
    gltf_dir = (math.sin(az) * math.cos(el), math.sin(el), math.cos(az) * math.cos(el))
    to_camera = mathutils.Vector((gltf_dir[0], -gltf_dir[2], gltf_dir[1]))  # glTF +Y up is Blender's +Z
    data = bpy.data.cameras.new("auto")
    data.sensor_fit = "VERTICAL"
    data.angle_y = yfov
    data.clip_end = max(1e3, 4.0 * distance)
    data.clip_start = max(1e-4, distance * 1e-4)
    cam = bpy.data.objects.new("auto", data)
    scene.collection.objects.link(cam)
    cam.location = centre + to_camera * distance
    cam.rotation_euler = (centre - cam.location).to_track_quat("-Z", "Y").to_euler()
    return cam


def main():
    args = parse_args(sys.argv[sys.argv.index("--") + 1:] if "--" in sys.argv else [])
    bpy.ops.wm.read_factory_settings(use_empty=True)
    bpy.ops.import_scene.gltf(filepath=args.scene)
    scene = bpy.context.scene
    rest_pose(scene)
    cameras = [o for o in scene.objects if o.type == "CAMERA"]
    scene.camera = cameras[0] if cameras else auto_camera(scene, args.width / args.height)
    world = bpy.data.worlds.new("white")
    world.use_nodes = True
    world.node_tree.nodes["Background"].inputs["Color"].default_value = (1.0, 1.0, 1.0, 1.0)
    world.node_tree.nodes["Background"].inputs["Strength"].default_value = 1.0
    scene.world = world
    scene.render.engine = "CYCLES"
    scene.cycles.device = "CPU"
    scene.cycles.samples = args.spp
    scene.cycles.use_denoising = False
    scene.render.threads_mode = "FIXED"
    scene.render.threads = args.threads
    scene.render.film_transparent = True
    scene.render.resolution_x, scene.render.resolution_y = args.width, args.height
    scene.render.resolution_percentage = 100
    scene.render.image_settings.file_format = "PNG"
    scene.render.image_settings.color_mode = "RGBA"
    scene.render.filepath = args.output
    bpy.ops.render.render(write_still=True)


main()
