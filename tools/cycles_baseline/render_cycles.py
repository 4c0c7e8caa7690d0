# Renders a glTF scene with Blender's Cycles on the CPU with settings matched to vkmc's defaults (issue 14).
# Run by tools/cycles_baseline.sh:
#   blender -b --factory-startup --python render_cycles.py -- SCENE OUT.exr --width W --height H
#           (--spp N | --time-limit S) [--seed S] [--threads T] [--max-bounces B] [--min-bounces M] [--json OUT.json]
# Materials are rebuilt from the glTF file itself rather than taken from Blender's importer, so that what Cycles
# shades is what vkmc shades (docs/manual/scenes.md):
#   - metallic 0 and KHR_materials_specular.specularFactor 0: vkmc's BRDF is exactly baseColor/pi, which is
#     Cycles' Diffuse BSDF with roughness 0 (Lambert; roughness > 0 would be Oren-Nayar);
#   - anything else: the Principled BSDF (GGX, metallic, roughness, specular 0.5 x specularFactor, i.e. the same
#     F0 = 0.04 x specularFactor). Not exact: Cycles' Fresnel, its separable Smith G and its diffuse term differ
#     from the glTF appendix B model vkmc uses;
#   - emission emissiveFactor x KHR_materials_emissive_strength as radiance (Cycles' mesh emission of strength 1
#     is radiance 1, the same unit as vkmc's W m^-2 sr^-1), from the front face only unless the material is
#     doubleSided (Cycles' Emission shader emits from both faces);
#   - a single-sided material (doubleSided false, glTF's default) is culled from the back as in vkmc: its back
#     face is a white Transparent BSDF through a Backfacing mix. Double-sided ones reflect on both faces.
# Textures, alpha, vertex colours and punctual lights are not mapped (the baseline's scenes have none).
import json
import math
import os
import sys
import time

try:
    import numpy
except ImportError:
    # Debian's python3-numpy, when Blender's embedded interpreter was started with another Python's paths (a
    # pyenv shim earlier in PATH does that).
    sys.path.append("/usr/lib/python3/dist-packages")
    import numpy

# Blender 3.4's glTF importer uses numpy's `bool` alias, removed in numpy 1.24; restore it for this process
# only (no system file is edited).
if "bool" not in numpy.__dict__:
    numpy.bool = bool

import bpy  # noqa: E402


def parse_args(argv):
    import argparse
    p = argparse.ArgumentParser(prog="render_cycles.py")
    p.add_argument("scene")
    p.add_argument("output")
    p.add_argument("--width", type=int, default=256)
    p.add_argument("--height", type=int, default=256)
    p.add_argument("--spp", type=int, default=0, help="samples per pixel (0: with --time-limit, as many as fit)")
    p.add_argument("--time-limit", type=float, default=0.0, help="Cycles' time limit in seconds (render only)")
    p.add_argument("--seed", type=int, default=1)
    p.add_argument("--threads", type=int, default=2)
    p.add_argument("--max-bounces", type=int, default=1024)
    p.add_argument("--min-bounces", type=int, default=2)
    p.add_argument("--pattern", default="PROGRESSIVE_MULTI_JITTER", choices=["PROGRESSIVE_MULTI_JITTER", "SOBOL"])
    p.add_argument("--json", default="")
    p.add_argument("--adaptive-threshold", type=float, default=0.0,
                   help="Cycles' adaptive sampling at this noise threshold (0: off, every pixel the same samples)")
    return p.parse_args(argv)


def load_gltf_json(path):
    if path.lower().endswith(".glb"):
        with open(path, "rb") as f:
            data = f.read()
        length = int.from_bytes(data[12:16], "little")
        return json.loads(data[20:20 + length])
    with open(path) as f:
        return json.load(f)


def material_rows(gltf):
    rows = []
    for i, m in enumerate(gltf.get("materials", [])):
        pbr = m.get("pbrMetallicRoughness", {})
        ext = m.get("extensions", {})
        for key in ("baseColorTexture", "metallicRoughnessTexture"):
            if key in pbr:
                print(f"cycles_baseline: warning: material {i}: {key} is not mapped", file=sys.stderr)
        if "emissiveTexture" in m or m.get("alphaMode", "OPAQUE") != "OPAQUE":
            print(f"cycles_baseline: warning: material {i}: emissive texture / alpha not mapped", file=sys.stderr)
        strength = ext.get("KHR_materials_emissive_strength", {}).get("emissiveStrength", 1.0)
        rows.append({
            "name": m.get("name") or f"Material_{i}",  # the importer's naming (gltf2_blender_material.py)
            "base": list(pbr.get("baseColorFactor", [1, 1, 1, 1]))[:3],
            "metallic": pbr.get("metallicFactor", 1.0),
            "roughness": pbr.get("roughnessFactor", 1.0),
            "specular": ext.get("KHR_materials_specular", {}).get("specularFactor", 1.0),
            "emission": [c * strength for c in m.get("emissiveFactor", [0, 0, 0])],
            "double_sided": bool(m.get("doubleSided", False)),
        })
    names = [r["name"] for r in rows]
    if len(set(names)) != len(names):
        sys.exit("cycles_baseline: materials need distinct names (Blender's importer renames duplicates)")
    return rows


def build_material(mat, row):
    mat.use_nodes = True
    nt = mat.node_tree
    nt.nodes.clear()
    out = nt.nodes.new("ShaderNodeOutputMaterial")
    out.target = "CYCLES"
    lambert = row["metallic"] == 0.0 and row["specular"] == 0.0
    if lambert:
        surface = nt.nodes.new("ShaderNodeBsdfDiffuse")
        surface.inputs["Color"].default_value = row["base"] + [1.0]
        surface.inputs["Roughness"].default_value = 0.0
    else:
        surface = nt.nodes.new("ShaderNodeBsdfPrincipled")
        surface.distribution = "GGX"
        surface.inputs["Base Color"].default_value = row["base"] + [1.0]
        surface.inputs["Metallic"].default_value = row["metallic"]
        surface.inputs["Roughness"].default_value = row["roughness"]
        surface.inputs["Specular"].default_value = 0.5 * row["specular"]
        surface.inputs["Specular Tint"].default_value = 0.0
        surface.inputs["Sheen"].default_value = 0.0
        surface.inputs["Clearcoat"].default_value = 0.0
        surface.inputs["Emission Strength"].default_value = 0.0
    front = surface.outputs[0]
    if max(row["emission"]) > 0.0:
        emission = nt.nodes.new("ShaderNodeEmission")
        emission.inputs["Color"].default_value = row["emission"] + [1.0]
        emission.inputs["Strength"].default_value = 1.0
        add = nt.nodes.new("ShaderNodeAddShader")
        nt.links.new(front, add.inputs[0])
        nt.links.new(emission.outputs[0], add.inputs[1])
        front = add.outputs[0]
    shader = front
    if not row["double_sided"]:
        # glTF's back-face culling, as vkmc does it: a ray meeting the back of a single-sided surface passes
        # (a white Transparent BSDF, which Cycles also lets shadow rays through).
        geometry = nt.nodes.new("ShaderNodeNewGeometry")
        through = nt.nodes.new("ShaderNodeBsdfTransparent")
        through.inputs["Color"].default_value = [1.0, 1.0, 1.0, 1.0]
        mix = nt.nodes.new("ShaderNodeMixShader")  # Fac 0: input 1 (front), 1: input 2 (back)
        nt.links.new(geometry.outputs["Backfacing"], mix.inputs["Fac"])
        nt.links.new(front, mix.inputs[1])
        nt.links.new(through.outputs[0], mix.inputs[2])
        shader = mix.outputs[0]
    nt.links.new(shader, out.inputs["Surface"])
    return lambert


def setup_scene(args, rows):
    scene = bpy.context.scene
    cameras = [o for o in scene.objects if o.type == "CAMERA"]
    if not cameras:
        sys.exit("cycles_baseline: the scene has no camera (vkmc's automatic camera is not reproduced)")
    # vkmc: the first camera instance in node order. The importer names objects after nodes; with one camera
    # (all of the baseline's scenes) there is no choice to make.
    if len(cameras) > 1:
        print("cycles_baseline: warning: several cameras; using the first by name", file=sys.stderr)
    cam = sorted(cameras, key=lambda o: o.name)[0]
    scene.camera = cam
    if cam.data.type == "PERSP":
        # vkmc: vertical field of view yfov whatever the image's aspect (horizontal = yfov x width/height).
        cam.data.sensor_fit = "VERTICAL"
    cam.data.shift_x = cam.data.shift_y = 0.0
    cam.data.clip_start = 1e-4
    cam.data.clip_end = 1e6

    rs = scene.render
    rs.engine = "CYCLES"
    rs.resolution_x, rs.resolution_y, rs.resolution_percentage = args.width, args.height, 100
    rs.pixel_aspect_x = rs.pixel_aspect_y = 1.0
    rs.threads_mode = "FIXED"
    rs.threads = args.threads
    rs.film_transparent = False
    rs.use_persistent_data = False
    rs.image_settings.file_format = "OPEN_EXR"
    rs.image_settings.color_mode = "RGBA"
    rs.image_settings.color_depth = "32"
    rs.image_settings.exr_codec = "NONE"
    scene.view_settings.view_transform = "Standard"
    scene.view_settings.look = "None"
    scene.view_settings.exposure = 0.0
    scene.view_settings.gamma = 1.0

    c = scene.cycles
    c.device = "CPU"
    c.feature_set = "SUPPORTED"
    c.use_adaptive_sampling = args.adaptive_threshold > 0
    if args.adaptive_threshold > 0:
        c.adaptive_threshold = args.adaptive_threshold
        c.adaptive_min_samples = 0  # Cycles' automatic minimum
    c.use_denoising = False
    c.use_preview_denoising = False
    c.sample_clamp_direct = 0.0
    c.sample_clamp_indirect = 0.0
    c.light_sampling_threshold = 0.0
    c.blur_glossy = 0.0
    c.caustics_reflective = True
    c.caustics_refractive = True
    c.max_bounces = c.diffuse_bounces = c.glossy_bounces = args.max_bounces
    c.transmission_bounces = c.volume_bounces = args.max_bounces
    c.transparent_max_bounces = 1024  # culled back faces: vkmc passes them without counting a bounce
    c.min_light_bounces = args.min_bounces
    c.min_transparent_bounces = args.min_bounces
    c.seed = args.seed
    c.use_animated_seed = False
    c.sampling_pattern = args.pattern
    c.filter_width = 1.0
    c.pixel_filter_type = "BOX"  # Film > Pixel Filter
    if args.time_limit > 0:
        c.time_limit = args.time_limit
        c.samples = args.spp if args.spp > 0 else 1 << 24
    else:
        c.time_limit = 0.0
        c.samples = args.spp
    c.use_auto_tile = False

    world = bpy.data.worlds.new("black")
    world.use_nodes = True
    bg = world.node_tree.nodes.get("Background")
    bg.inputs["Color"].default_value = (0, 0, 0, 1)
    bg.inputs["Strength"].default_value = 0.0
    world.cycles.sample_as_light = False
    scene.world = world


def stamp_seconds(result_metadata, key):
    for k, v in result_metadata.items():
        if k.endswith(key):
            return v
    return None


def main():
    argv = sys.argv[sys.argv.index("--") + 1:] if "--" in sys.argv else []
    args = parse_args(argv)
    scene_path = os.path.abspath(args.scene)
    gltf = load_gltf_json(scene_path)
    rows = material_rows(gltf)

    bpy.ops.wm.read_factory_settings(use_empty=True)
    t0 = time.perf_counter()
    bpy.ops.import_scene.gltf(filepath=scene_path)
    t_import = time.perf_counter() - t0

    mapped = {}
    for row in rows:
        mat = bpy.data.materials.get(row["name"])
        if mat is None:
            continue  # unused by any primitive
        mapped[row["name"]] = "diffuse" if build_material(mat, row) else "principled"
    setup_scene(args, rows)

    # Cycles writes its own timings into the render result's metadata ("cycles.<layer>.render_time" excludes
    # synchronization, "synchronization_time" is the scene export); they are parsed from Blender's log by the
    # caller too. The wall time around render() includes sync and kernel set-up.
    bpy.context.scene.render.filepath = os.path.abspath(args.output)
    t0 = time.perf_counter()
    bpy.ops.render.render(write_still=True)
    t_render_call = time.perf_counter() - t0
    report = {
        "scene": scene_path, "width": args.width, "height": args.height, "seed": args.seed,
        "requested_spp": args.spp, "time_limit": args.time_limit, "threads": args.threads,
        "max_bounces": args.max_bounces, "min_light_bounces": args.min_bounces, "pattern": args.pattern,
        "materials": mapped, "import_seconds": t_import, "render_call_seconds": t_render_call,
        "blender": bpy.app.version_string,
    }
    if args.json:
        with open(args.json, "w") as f:
            json.dump(report, f, indent=1)
    print("cycles_baseline: " + json.dumps(report))


main()
