#!/usr/bin/env python3
"""Writes vkmc's canonical glTF scenes into scenes/ (embedded buffers, no dependencies beyond Python 3).

Run from the project root: python3 tools/make_scenes.py. The outputs are committed; vkmc never runs this.
"""
import base64, json, math, os, random, struct, zlib

def normalize(v):
    l = math.sqrt(sum(c * c for c in v))
    return [c / l for c in v]

def cross(a, b):
    return [a[1]*b[2]-a[2]*b[1], a[2]*b[0]-a[0]*b[2], a[0]*b[1]-a[1]*b[0]]

def sub(a, b):
    return [x - y for x, y in zip(a, b)]

class Builder:
    def __init__(self):
        self.meshes, self.materials, self.nodes, self.blob = [], [], [], bytearray()
        self.accessors, self.views, self.cameras = [], [], []

    def material(self, name, base, emission=None, strength=1.0, double_sided=False, metallic=0.0, roughness=1.0,
                 specular=0.0, extensions=None):
        """specular: KHR_materials_specular specularFactor; 0 (the default here) is a pure Lambertian surface.
        extensions: further material extensions, e.g. {"KHR_materials_transmission": {...}}."""
        m = {"name": name, "pbrMetallicRoughness": {"baseColorFactor": list(base) + [1.0], "metallicFactor": metallic,
                                                    "roughnessFactor": roughness}, "doubleSided": double_sided}
        ext = dict(extensions or {})
        if specular != 1.0:
            ext["KHR_materials_specular"] = {"specularFactor": specular}
        if emission:
            m["emissiveFactor"] = list(emission)
            if strength != 1.0:
                ext["KHR_materials_emissive_strength"] = {"emissiveStrength": strength}
        if ext:
            m["extensions"] = ext
        self.materials.append(m)
        return len(self.materials) - 1

    def _accessor(self, data, fmt, count, type_, ctype, minmax=None, target=None):
        while len(self.blob) % 4:
            self.blob.append(0)
        offset = len(self.blob)
        self.blob += struct.pack("<" + fmt * (len(data)), *data)
        view = {"buffer": 0, "byteOffset": offset, "byteLength": len(self.blob) - offset}
        if target:
            view["target"] = target
        self.views.append(view)
        acc = {"bufferView": len(self.views) - 1, "componentType": ctype, "count": count, "type": type_}
        if minmax:
            acc["min"], acc["max"] = minmax
        self.accessors.append(acc)
        return len(self.accessors) - 1

    def mesh(self, name, triangles, material, uvs=None):
        """triangles: list of (p0, p1, p2), counter-clockwise seen from the front; uvs: one (uv0, uv1, uv2) each."""
        pos, nrm, idx, tex = [], [], [], []
        for k, tri in enumerate(triangles):
            n = normalize(cross(sub(tri[1], tri[0]), sub(tri[2], tri[0])))
            for c, p in enumerate(tri):
                idx.append(len(pos) // 3)
                pos += p
                nrm += n
                if uvs:
                    tex += uvs[k][c]
        lo = [min(pos[i::3]) for i in range(3)]
        hi = [max(pos[i::3]) for i in range(3)]
        pa = self._accessor(pos, "f", len(pos) // 3, "VEC3", 5126, (lo, hi), 34962)
        na = self._accessor(nrm, "f", len(nrm) // 3, "VEC3", 5126, None, 34962)
        ia = self._accessor(idx, "I", len(idx), "SCALAR", 5125, None, 34963)
        attributes = {"POSITION": pa, "NORMAL": na}
        if uvs:
            attributes["TEXCOORD_0"] = self._accessor(tex, "f", len(tex) // 2, "VEC2", 5126, None, 34962)
        self.meshes.append({"name": name, "primitives": [{"attributes": attributes, "indices": ia,
                                                          "material": material, "mode": 4}]})
        self.nodes.append({"name": name, "mesh": len(self.meshes) - 1})

    def texture(self, png_bytes):
        """A PNG texture (embedded as a data URI) with the default sampler (bilinear, REPEAT); returns its index."""
        self.images = getattr(self, "images", []) + [{"uri": "data:image/png;base64," + base64.b64encode(png_bytes).decode()}]
        self.textures = getattr(self, "textures", []) + [{"source": len(self.images) - 1}]
        return len(self.textures) - 1

    def camera(self, name, eye, target, yfov_deg, aspect=1.0):
        f = normalize(sub(target, eye))
        r = normalize(cross(f, [0, 1, 0]))
        u = cross(r, f)
        # Column-major node matrix: local x = right, y = up, -z = forward.
        m = r + [0] + u + [0] + [-c for c in f] + [0] + list(eye) + [1]
        self.cameras.append({"type": "perspective", "perspective": {"yfov": math.radians(yfov_deg), "aspectRatio": aspect,
                                                                    "znear": 0.01}})
        self.nodes.append({"name": name, "camera": len(self.cameras) - 1, "matrix": m})

    def ortho_camera_down(self, name, eye, half_size):
        """Orthographic camera at eye looking down -y, image up = -z, covering x, z in eye +- half_size."""
        m = [1, 0, 0, 0, 0, 0, -1, 0, 0, 1, 0, 0] + list(eye) + [1]
        self.cameras.append({"type": "orthographic", "orthographic": {"xmag": half_size, "ymag": half_size, "znear": 0.001,
                                                                     "zfar": 100.0}})
        self.nodes.append({"name": name, "camera": len(self.cameras) - 1, "matrix": m})

    def write(self, path, extensions_used=()):
        doc = {"asset": {"version": "2.0", "generator": "vkmc tools/make_scenes.py"},
               "scene": 0, "nodes": self.nodes,
               # Lab scenes: lit by their own emitters alone, in a black world (not the studio a file gets undeclared).
               "scenes": [{"nodes": list(range(len(self.nodes))), "extras": {"vkmc_world": "lights-only"}}],
               "meshes": self.meshes, "materials": self.materials, "accessors": self.accessors,
               "bufferViews": self.views,
               "buffers": [{"byteLength": len(self.blob),
                            "uri": "data:application/octet-stream;base64," + base64.b64encode(bytes(self.blob)).decode()}]}
        if self.cameras:
            doc["cameras"] = self.cameras
        if getattr(self, "textures", None):
            doc["images"], doc["textures"] = self.images, self.textures
        if extensions_used:
            doc["extensionsUsed"] = list(extensions_used)
        with open(path, "w") as f:
            json.dump(doc, f, indent=1)
            f.write("\n")

def quad(a, b, c, d):
    """Two triangles of the quad a-b-c-d (counter-clockwise from the front)."""
    return [(a, b, c), (a, c, d)]

def box(center, size, angle_deg):
    """Closed box rotated about +y, outward-facing."""
    cx, cy, cz = center
    sx, sy, sz = [s / 2 for s in size]
    a = math.radians(angle_deg)
    def p(x, y, z):
        return [cx + x * math.cos(a) + z * math.sin(a), cy + y, cz - x * math.sin(a) + z * math.cos(a)]
    v = {(i, j, k): p(i * sx, j * sy, k * sz) for i in (-1, 1) for j in (-1, 1) for k in (-1, 1)}
    faces = []
    faces += quad(v[1, -1, -1], v[1, 1, -1], v[1, 1, 1], v[1, -1, 1])        # +x
    faces += quad(v[-1, -1, -1], v[-1, -1, 1], v[-1, 1, 1], v[-1, 1, -1])    # -x
    faces += quad(v[-1, 1, -1], v[-1, 1, 1], v[1, 1, 1], v[1, 1, -1])        # +y
    faces += quad(v[-1, -1, -1], v[1, -1, -1], v[1, -1, 1], v[-1, -1, 1])    # -y
    faces += quad(v[-1, -1, 1], v[1, -1, 1], v[1, 1, 1], v[-1, 1, 1])        # +z
    faces += quad(v[-1, -1, -1], v[-1, 1, -1], v[1, 1, -1], v[1, -1, -1])    # -z
    return faces

def cornell_box(path):
    """The Cornell box: a 2 x 2 x 2 room (x, z in [-1, 1], y in [0, 2]) open towards +z, two blocks,
    one downward-facing area light of radiance (17, 12, 4) just below the ceiling."""
    b = Builder()
    white = b.material("white", (0.725, 0.71, 0.68))
    red = b.material("red", (0.63, 0.065, 0.05))
    green = b.material("green", (0.14, 0.45, 0.091))
    light = b.material("light", (0.0, 0.0, 0.0), emission=(1.0, 12 / 17, 4 / 17), strength=17.0)
    b.mesh("floor", quad([-1, 0, -1], [-1, 0, 1], [1, 0, 1], [1, 0, -1]), white)
    b.mesh("ceiling", quad([-1, 2, -1], [1, 2, -1], [1, 2, 1], [-1, 2, 1]), white)
    b.mesh("back", quad([-1, 0, -1], [1, 0, -1], [1, 2, -1], [-1, 2, -1]), white)
    b.mesh("left", quad([-1, 0, -1], [-1, 2, -1], [-1, 2, 1], [-1, 0, 1]), red)
    b.mesh("right", quad([1, 0, -1], [1, 0, 1], [1, 2, 1], [1, 2, -1]), green)
    b.mesh("short_block", box([0.33, 0.3, 0.3], [0.6, 0.6, 0.6], -17), white)
    b.mesh("tall_block", box([-0.33, 0.6, -0.3], [0.6, 1.2, 0.6], 17), white)
    b.mesh("light", quad([-0.24, 1.98, -0.19], [0.24, 1.98, -0.19], [0.24, 1.98, 0.19], [-0.24, 1.98, 0.19]), light)
    b.camera("camera", [0, 1, 3.94], [0, 1, 0], 39.3)
    b.write(path, ["KHR_materials_emissive_strength", "KHR_materials_specular"])

def icosphere(radius, levels, inward):
    t = (1 + math.sqrt(5)) / 2
    verts = [normalize(v) for v in [[-1, t, 0], [1, t, 0], [-1, -t, 0], [1, -t, 0], [0, -1, t], [0, 1, t], [0, -1, -t],
                                    [0, 1, -t], [t, 0, -1], [t, 0, 1], [-t, 0, -1], [-t, 0, 1]]]
    faces = [(0, 11, 5), (0, 5, 1), (0, 1, 7), (0, 7, 10), (0, 10, 11), (1, 5, 9), (5, 11, 4), (11, 10, 2), (10, 7, 6),
             (7, 1, 8), (3, 9, 4), (3, 4, 2), (3, 2, 6), (3, 6, 8), (3, 8, 9), (4, 9, 5), (2, 4, 11), (6, 2, 10),
             (8, 6, 7), (9, 8, 1)]
    for _ in range(levels):
        cache, new = {}, []
        def mid(i, j):
            key = (min(i, j), max(i, j))
            if key not in cache:
                verts.append(normalize([(a + b) / 2 for a, b in zip(verts[i], verts[j])]))
                cache[key] = len(verts) - 1
            return cache[key]
        for a, b_, c in faces:
            ab, bc, ca = mid(a, b_), mid(b_, c), mid(c, a)
            new += [(a, ab, ca), (b_, bc, ab), (c, ca, bc), (ab, bc, ca)]
        faces = new
    tris = []
    for a, b_, c in faces:
        tri = [[radius * x for x in verts[i]] for i in (a, b_, c)]
        tris.append((tri[0], tri[2], tri[1]) if inward else tuple(tri))
    return tris

def furnace(path, albedo, emission, name):
    """A closed sphere seen from its centre; every surface is Lambertian (specularFactor 0) with albedo a and
    emits Le on both sides, so the radiance everywhere is L = Le / (1 - a), whatever the shape."""
    b = Builder()
    m = b.material(name, (albedo, albedo, albedo), emission=(1.0, 1.0, 1.0), strength=emission, double_sided=True)
    b.mesh("sphere", icosphere(1.0, 3, inward=True), m)
    b.camera("camera", [0, 0, 0], [0, 0, -1], 60.0)
    b.write(path, ["KHR_materials_specular"] + (["KHR_materials_emissive_strength"] if emission != 1.0 else []))

GLASS = {"KHR_materials_transmission": {"transmissionFactor": 1.0}, "KHR_materials_volume": {"thicknessFactor": 1.0},
         "KHR_materials_ior": {"ior": 1.5}}
GLASS_EXTENSIONS = ["KHR_materials_transmission", "KHR_materials_volume", "KHR_materials_ior", "KHR_materials_specular"]

def material_furnace(path, kind):
    """A closed emitter (radiance 1 inside, black) around a sphere of lossless smooth glass or a perfect mirror,
    seen from inside the emitter: every path ends on the emitter with throughput 1 (Fresnel splits, total
    internal reflection and the eta^2 radiance scaling on the way in and out cancel), so L = 1 at every pixel."""
    b = Builder()
    wall = b.material("emitter", (0, 0, 0), emission=(1.0, 1.0, 1.0), double_sided=True)
    b.mesh("emitter", icosphere(3.0, 2, inward=True), wall)
    if kind == "glass":
        m = b.material("glass", (1, 1, 1), roughness=0.0, specular=1.0, extensions=GLASS)
    else:
        m = b.material("mirror", (1, 1, 1), metallic=1.0, roughness=0.0, specular=1.0)
    b.mesh(kind, icosphere(1.0, 3, inward=False), m)
    b.camera("camera", [0, 0, 2.5], [0, 0, 0], 45.0)
    b.write(path, GLASS_EXTENSIONS if kind == "glass" else [])

def caustic(path):
    """Light through glass: a smooth glass sphere (radius 0.5) on a white Lambertian floor under a small square
    light 2 m up; its caustic on the floor is reachable only by BSDF sampling through two delta refractions."""
    b = Builder()
    floor = b.material("floor", (0.8, 0.8, 0.8))
    light = b.material("light", (0, 0, 0), emission=(1.0, 1.0, 1.0), strength=50.0)
    glass = b.material("glass", (1, 1, 1), roughness=0.0, specular=1.0, extensions=GLASS)
    b.mesh("floor", quad([-3, 0, -3], [-3, 0, 3], [3, 0, 3], [3, 0, -3]), floor)
    s = 0.2
    b.mesh("light", quad([0.3 - s, 2, -s], [0.3 + s, 2, -s], [0.3 + s, 2, s], [0.3 - s, 2, s]), light)
    b.mesh("sphere", translate(icosphere(0.5, 4, inward=False), (0, 0.5, 0)), glass)
    b.camera("camera", [0, 2.2, 3.2], [0, 0.3, 0], 40.0)
    b.write(path, GLASS_EXTENSIONS + ["KHR_materials_emissive_strength"])

def glass_bulb(path):
    """A lamp inside a glass bulb over a diffuse floor: a small emissive sphere (radius 0.05) inside a thin-walled
    smooth glass shell (radius 0.3, transmission without a volume). Light sampling cannot see the filament through
    the glass: every light path leaves by BSDF sampling through the delta transmission."""
    b = Builder()
    floor = b.material("floor", (0.8, 0.8, 0.8))
    filament = b.material("filament", (0, 0, 0), emission=(1.0, 0.8, 0.5), strength=400.0)
    bulb = b.material("bulb", (1, 1, 1), roughness=0.0, specular=1.0, double_sided=True,
                      extensions={"KHR_materials_transmission": {"transmissionFactor": 1.0}})
    b.mesh("floor", quad([-3, 0, -3], [-3, 0, 3], [3, 0, 3], [3, 0, -3]), floor)
    b.mesh("filament", translate(icosphere(0.05, 2, inward=False), (0, 0.8, 0)), filament)
    b.mesh("bulb", translate(icosphere(0.3, 3, inward=False), (0, 0.8, 0)), bulb)
    b.camera("camera", [0, 1.2, 2.8], [0, 0.5, 0], 45.0)
    b.write(path, ["KHR_materials_transmission", "KHR_materials_specular", "KHR_materials_emissive_strength"])

def translate(tris, offset):
    return [tuple([c + o for c, o in zip(v, offset)] for v in t) for t in tris]

def veach_mis(path):
    """Veach's MIS test (thesis fig. 9.2): four glossy metal plates (GGX roughness 0.5, 0.25, 0.1, 0.02 from
    the bottom up) reflect a row of four spherical lights of equal power whose radii span 30x (0.03 .. 0.9).
    Each plate's normal is the half vector between the camera and the light row, so every plate shows all
    four reflections. Light sampling wins on rough plates with small lights, BSDF sampling on sharp plates
    with big lights; MIS should be close to the better of the two on every plate. As fractions of the image height (measured on
    a render): lights 0.11-0.34, plates 0.44-0.50 (roughness 0.02), 0.58-0.64 (0.1), 0.70-0.80 (0.25),
    0.86-0.95 (0.5)."""
    def n3(v):
        l = math.sqrt(sum(c * c for c in v))
        return [c / l for c in v]
    cam, light_row = [0.0, 2.0, 15.0], [0.0, 0.5, -1.5]
    b = Builder()
    radii = [0.03, 0.1, 0.3, 0.9]
    total_power = 100.0
    for i, r in enumerate(radii):
        # Equal power: Le * (4 pi r^2) * pi is the same for every light, so Le ~ 1 / r^2.
        le = total_power / 4 / (4 * math.pi * r * r * math.pi)
        m = b.material(f"light_{i}", (0, 0, 0), emission=(1.0, 1.0, 1.0), strength=le)
        b.mesh(f"light_{i}", translate(icosphere(r, 2, inward=False), (-3.75 + 2.5 * i, light_row[1], light_row[2])), m)
    plates = [(-2.79, 5.0, 0.5), (-2.328, 3.8, 0.25), (-1.76, 2.6, 0.1), (-1.072, 1.4, 0.02)]  # (y, z, roughness)
    for i, (y, z, rough) in enumerate(plates):
        m = b.material(f"plate_{i}", (0.7, 0.7, 0.7), metallic=1.0, roughness=rough, specular=1.0)
        c = [0.0, y, z]
        n = n3([a + bb for a, bb in zip(n3(sub(cam, c)), n3(sub(light_row, c)))])
        d = n3(cross(n, [1.0, 0.0, 0.0]))
        corner = lambda sx, sd: [c[k] + sx * 4.0 * (1.0 if k == 0 else 0.0) + sd * 0.5 * d[k] for k in range(3)]
        b.mesh(f"plate_{i}", quad(corner(-1, -1), corner(1, -1), corner(1, 1), corner(-1, 1)), m)
    b.camera("camera", cam, [0.0, -1.0, 2.5], 30.0, aspect=1.5)
    b.write(path, ["KHR_materials_emissive_strength", "KHR_materials_specular"])

def many_lights(path):
    """A white Lambertian room lit by 64 small square lights on the ceiling whose powers span 1e4 (one bright
    light, many dim ones): power-proportional light selection should beat uniform selection by a wide margin."""
    b = Builder()
    white = b.material("white", (0.7, 0.7, 0.7))
    b.mesh("floor", quad([-2, 0, -2], [-2, 0, 2], [2, 0, 2], [2, 0, -2]), white)
    b.mesh("back", quad([-2, 0, -2], [2, 0, -2], [2, 2, -2], [-2, 2, -2]), white)
    b.mesh("ceiling", quad([-2, 2, -2], [2, 2, -2], [2, 2, 2], [-2, 2, 2]), white)
    s = 0.06
    for i in range(8):
        for j in range(8):
            k = i * 8 + j
            strength = 400.0 if k == 27 else 0.04 * (1 + (k % 5))
            m = b.material(f"light_{k}", (0, 0, 0), emission=(1.0, 0.9, 0.8), strength=strength)
            x, z = -1.75 + 0.5 * i, -1.75 + 0.5 * j
            b.mesh(f"light_{k}", quad([x - s, 1.99, z - s], [x + s, 1.99, z - s], [x + s, 1.99, z + s], [x - s, 1.99, z + s]), m)
    b.camera("camera", [0, 1.0, 5.5], [0, 0.8, 0], 45.0)
    b.write(path, ["KHR_materials_emissive_strength", "KHR_materials_specular"])

def tiny_light(path):
    """Stiff case 2: a 1 mm x 1 mm emitter of radiance 1e6 facing down, h = 1 m above a Lambertian floor of
    albedo 0.5 (x, z in [-1, 1]); an orthographic camera between them looks straight down at the floor, so
    pixel (i, j) sees x in -1 + 2 [i, i + 1] / W and z in -1 + 2 [j, j + 1] / H, where
    L(x, z) = rho / pi * Le * A * h^2 / (h^2 + x^2 + z^2)^2 (the light is 1e-3 of h: a point to 1e-7)."""
    b = Builder()
    floor = b.material("floor", (0.5, 0.5, 0.5))
    light = b.material("light", (0, 0, 0), emission=(1.0, 1.0, 1.0), strength=1e6)
    b.mesh("floor", quad([-1, 0, -1], [-1, 0, 1], [1, 0, 1], [1, 0, -1]), floor)
    s = 0.0005
    b.mesh("light", quad([-s, 1, -s], [s, 1, -s], [s, 1, s], [-s, 1, s]), light)
    b.ortho_camera_down("camera", [0.0, 0.5, 0.0], 1.0)
    b.write(path, ["KHR_materials_emissive_strength", "KHR_materials_specular"])

def two_rooms(path):
    """Where splitting should pay (EARS): the camera's room (x in [-1, 1]) is lit only through a 0.1-wide slit in
    the wall x = 1 from a second room (x in [1, 3]) whose lamp faces away from the slit, towards that room's far
    wall: every light path into the first room crosses the slit after at least one bounce. Lambertian white walls
    (double-sided), y in [0, 2], z in [-1, 1]."""
    b = Builder()
    white = b.material("white", (0.8, 0.8, 0.8), double_sided=True)
    lamp = b.material("lamp", (0.0, 0.0, 0.0), emission=(1.0, 0.9, 0.75), strength=60.0)
    b.mesh("floor", quad([-1, 0, -1], [-1, 0, 1], [3, 0, 1], [3, 0, -1]), white)
    b.mesh("ceiling", quad([-1, 2, -1], [3, 2, -1], [3, 2, 1], [-1, 2, 1]), white)
    b.mesh("back", quad([-1, 0, -1], [3, 0, -1], [3, 2, -1], [-1, 2, -1]), white)
    b.mesh("front", quad([-1, 0, 1], [-1, 2, 1], [3, 2, 1], [3, 0, 1]), white)
    b.mesh("left", quad([-1, 0, -1], [-1, 2, -1], [-1, 2, 1], [-1, 0, 1]), white)
    b.mesh("right", quad([3, 0, -1], [3, 0, 1], [3, 2, 1], [3, 2, -1]), white)
    slit = 0.05
    b.mesh("divider_back", quad([1, 0, -1], [1, 0, -slit], [1, 2, -slit], [1, 2, -1]), white)
    b.mesh("divider_front", quad([1, 0, slit], [1, 0, 1], [1, 2, 1], [1, 2, slit]), white)
    # Facing +x (away from the slit): its front face is where u x v points.
    b.mesh("lamp", quad([2.2, 0.75, -0.25], [2.2, 1.25, -0.25], [2.2, 1.25, 0.25], [2.2, 0.75, 0.25]), lamp)
    b.camera("camera", [-0.85, 1.2, 0.85], [1.0, 0.8, -0.2], 70.0)
    b.write(path, ["KHR_materials_emissive_strength", "KHR_materials_specular"])

def glossy_room(path):
    """Glossy-diffuse interreflection (EARS's other case): a white room (x, z in [-1, 1], y in [0, 2]) whose floor is
    a glossy metal (GGX roughness 0.1) and whose only lamp, a 0.3-wide quad on the ceiling, faces down onto it. The
    ceiling and the upper walls see the lamp only through the floor: their light comes along diffuse -> glossy ->
    lamp paths, which light sampling at the diffuse vertex cannot reach and BSDF sampling finds rarely."""
    b = Builder()
    white = b.material("white", (0.8, 0.8, 0.8), double_sided=True)
    floor = b.material("glossy_floor", (0.9, 0.9, 0.9), metallic=1.0, roughness=0.1, specular=1.0)
    lamp = b.material("lamp", (0.0, 0.0, 0.0), emission=(1.0, 0.95, 0.85), strength=10.0)
    b.mesh("floor", quad([-1, 0, -1], [-1, 0, 1], [1, 0, 1], [1, 0, -1]), floor)
    b.mesh("ceiling", quad([-1, 2, -1], [1, 2, -1], [1, 2, 1], [-1, 2, 1]), white)
    b.mesh("back", quad([-1, 0, -1], [1, 0, -1], [1, 2, -1], [-1, 2, -1]), white)
    b.mesh("front", quad([-1, 0, 1], [-1, 2, 1], [1, 2, 1], [1, 0, 1]), white)
    b.mesh("left", quad([-1, 0, -1], [-1, 2, -1], [-1, 2, 1], [-1, 0, 1]), white)
    b.mesh("right", quad([1, 0, -1], [1, 0, 1], [1, 2, 1], [1, 2, -1]), white)
    s = 0.15
    # Facing -y (down, onto the floor): its front face is where u x v points.
    b.mesh("lamp", quad([-s, 1.98, -s], [s, 1.98, -s], [s, 1.98, s], [-s, 1.98, s]), lamp)
    b.camera("camera", [-0.85, 1.1, 0.9], [0.5, 0.9, -0.9], 80.0)
    b.write(path, ["KHR_materials_emissive_strength", "KHR_materials_specular"])

def soft_shadows(path):
    """The lecture's splitting example (N image x M light samples): a large square lamp (1.2 x 1.2, facing down,
    y = 1.4) over an open Lambertian floor (albedo 0.5, x, z in [-2, 2]) with a block, a floating slab and a row of
    thin posts under it. Most of what the camera sees lies in their wide penumbrae, so a pixel's variance is
    mostly the visibility of the light sample, and nothing surrounds the scene: a bounce mostly escapes, so the
    camera ray and the first vertex cost more than a shadow ray. Light-sample splitting should pay here."""
    b = Builder()
    floor = b.material("floor", (0.5, 0.5, 0.5))
    grey = b.material("grey", (0.6, 0.6, 0.6))
    lamp = b.material("lamp", (0.0, 0.0, 0.0), emission=(1.0, 0.95, 0.9), strength=4.0)
    b.mesh("floor", quad([-2, 0, -2], [-2, 0, 2], [2, 0, 2], [2, 0, -2]), floor)
    b.mesh("block", box([-0.55, 0.25, 0.1], [0.5, 0.5, 0.5], 30), grey)
    b.mesh("slab", box([0.5, 0.55, -0.3], [0.7, 0.04, 0.5], -15), grey)
    posts = []
    for i in range(7):
        posts += box([-0.9 + 0.3 * i, 0.35, 0.75], [0.05, 0.7, 0.05], 0)
    b.mesh("posts", posts, grey)
    s = 0.6
    # Facing -y (down): its front face is where u x v points.
    b.mesh("lamp", quad([-s, 1.4, -s], [s, 1.4, -s], [s, 1.4, s], [-s, 1.4, s]), lamp)
    b.camera("camera", [0.0, 2.1, 2.5], [0.0, 0.0, 0.2], 50.0)
    b.write(path, ["KHR_materials_emissive_strength", "KHR_materials_specular"])

def desk_lamp(path):
    """Where roulette should learn (EARS): a small, bright lamp 0.45 above a table in a large, closed white room
    (8 x 3 x 8, albedo 0.75). The camera frames the table top, lit mostly directly; its paths go on bouncing through
    the white room (throughput roulette keeps them: their throughput stays high) while what they gather there adds
    little to these pixels."""
    b = Builder()
    white = b.material("white", (0.75, 0.75, 0.75), double_sided=True)
    wood = b.material("table", (0.55, 0.4, 0.3))
    blue = b.material("blue", (0.2, 0.3, 0.6))
    lamp = b.material("lamp", (0.0, 0.0, 0.0), emission=(1.0, 0.9, 0.75), strength=40.0)
    w, h = 4.0, 3.0
    b.mesh("floor", quad([-w, 0, -w], [-w, 0, w], [w, 0, w], [w, 0, -w]), white)
    b.mesh("ceiling", quad([-w, h, -w], [w, h, -w], [w, h, w], [-w, h, w]), white)
    b.mesh("walls", quad([-w, 0, -w], [w, 0, -w], [w, h, -w], [-w, h, -w]) + quad([-w, 0, w], [-w, h, w], [w, h, w], [w, 0, w])
           + quad([-w, 0, -w], [-w, h, -w], [-w, h, w], [-w, 0, w]) + quad([w, 0, -w], [w, 0, w], [w, h, w], [w, h, -w]), white)
    b.mesh("table", box([0, 0.375, 0], [1.6, 0.75, 1.0], 0), wood)
    b.mesh("book", box([-0.3, 0.79, 0.1], [0.35, 0.08, 0.25], 20), blue)
    b.mesh("cup", box([0.35, 0.82, -0.05], [0.12, 0.14, 0.12], 0), white)
    s = 0.08
    b.mesh("lamp", quad([-s, 1.2, -s], [s, 1.2, -s], [s, 1.2, s], [-s, 1.2, s]), lamp)
    b.camera("camera", [0.0, 2.0, 0.35], [0.0, 0.75, 0.0], 32.0)
    b.write(path, ["KHR_materials_emissive_strength", "KHR_materials_specular"])

def dark_room(path):
    """Where throughput roulette fails (ADRRS's motivating case, Vorba and Krivanek 2016): the camera's room (x in
    [-1, 1]) has dark walls (albedo 0.1) and is lit only through a wide doorway in the wall x = 1 from a bright room
    (x in [1, 3], albedo 0.9) whose lamp faces away from the doorway. Most of the bright room's radiance is its own
    multi-bounce light, so a camera path gathers most of its value at its fourth vertex and later, after a dark
    bounce has cut its throughput tenfold: throughput roulette keeps it with probability about 0.1 and weight 10."""
    b = Builder()
    dark = b.material("dark", (0.1, 0.1, 0.1), double_sided=True)
    bright = b.material("bright", (0.9, 0.9, 0.9), double_sided=True)
    lamp = b.material("lamp", (0.0, 0.0, 0.0), emission=(1.0, 0.9, 0.75), strength=20.0)
    b.mesh("dark_room", quad([-1, 0, -1], [-1, 0, 1], [1, 0, 1], [1, 0, -1]) + quad([-1, 2, -1], [1, 2, -1], [1, 2, 1], [-1, 2, 1])
           + quad([-1, 0, -1], [1, 0, -1], [1, 2, -1], [-1, 2, -1]) + quad([-1, 0, 1], [-1, 2, 1], [1, 2, 1], [1, 0, 1])
           + quad([-1, 0, -1], [-1, 2, -1], [-1, 2, 1], [-1, 0, 1]), dark)
    door = 0.35
    b.mesh("bright_room", quad([1, 0, -1], [1, 0, 1], [3, 0, 1], [3, 0, -1]) + quad([1, 2, -1], [3, 2, -1], [3, 2, 1], [1, 2, 1])
           + quad([1, 0, -1], [3, 0, -1], [3, 2, -1], [1, 2, -1]) + quad([1, 0, 1], [1, 2, 1], [3, 2, 1], [3, 0, 1])
           + quad([3, 0, -1], [3, 0, 1], [3, 2, 1], [3, 2, -1]), bright)
    # The dividing wall x = 1: dark on the camera's side, bright on the other; the doorway z in [-door, door], y < 1.6.
    divider = quad([1, 0, -1], [1, 0, -door], [1, 2, -door], [1, 2, -1]) + quad([1, 0, door], [1, 0, 1], [1, 2, 1], [1, 2, door]) \
        + quad([1, 1.6, -door], [1, 1.6, door], [1, 2, door], [1, 2, -door])
    b.mesh("divider_dark_side", divider, dark)
    offset = lambda tris: [tuple([p[0] + 0.001, p[1], p[2]] for p in t) for t in tris]
    b.mesh("divider_bright_side", offset(divider), bright)
    # Facing +x (away from the doorway), towards the bright room's far wall.
    b.mesh("lamp", quad([2.2, 0.8, -0.2], [2.2, 1.2, -0.2], [2.2, 1.2, 0.2], [2.2, 0.8, 0.2]), lamp)
    b.camera("camera", [-0.85, 1.2, 0.85], [1.0, 0.8, -0.2], 70.0)
    b.write(path, ["KHR_materials_emissive_strength", "KHR_materials_specular"])

def basement(path):
    """Dark surfaces lit by bright multi-bounce light, a second geometry (beside dark_room): a basement (x, z in
    [-1, 1], y in [0, 2], albedo 0.15) lit only through a 0.7 x 0.7 hatch in its ceiling from a white room above
    (y in [2, 4], albedo 0.9) whose only lamp faces that room's ceiling. The light comes down after two bounces at
    least, and a camera path reaches it after one or more dark bounces."""
    b = Builder()
    dark = b.material("dark", (0.15, 0.15, 0.15), double_sided=True)
    white = b.material("white", (0.9, 0.9, 0.9), double_sided=True)
    lamp = b.material("lamp", (0.0, 0.0, 0.0), emission=(1.0, 0.9, 0.75), strength=20.0)
    def walls(y0, y1):
        return (quad([-1, y0, -1], [1, y0, -1], [1, y1, -1], [-1, y1, -1]) + quad([-1, y0, 1], [-1, y1, 1], [1, y1, 1], [1, y0, 1])
                + quad([-1, y0, -1], [-1, y1, -1], [-1, y1, 1], [-1, y0, 1]) + quad([1, y0, -1], [1, y0, 1], [1, y1, 1], [1, y1, -1]))
    b.mesh("basement", quad([-1, 0, -1], [-1, 0, 1], [1, 0, 1], [1, 0, -1]) + walls(0, 2), dark)
    hx0, hx1, hz0, hz1 = 0.1, 0.8, -0.8, -0.1
    slab = (quad([-1, 2, -1], [1, 2, -1], [1, 2, hz0], [-1, 2, hz0]) + quad([-1, 2, hz1], [1, 2, hz1], [1, 2, 1], [-1, 2, 1])
            + quad([-1, 2, hz0], [hx0, 2, hz0], [hx0, 2, hz1], [-1, 2, hz1]) + quad([hx1, 2, hz0], [1, 2, hz0], [1, 2, hz1], [hx1, 2, hz1]))
    b.mesh("basement_ceiling", slab, dark)
    b.mesh("upper_floor", [tuple([p[0], p[1] + 0.001, p[2]] for p in t) for t in slab], white)
    b.mesh("upper_room", quad([-1, 4, -1], [1, 4, -1], [1, 4, 1], [-1, 4, 1]) + walls(2.001, 4), white)
    s = 0.15
    # Facing +y (up, onto the upper room's ceiling), in the corner away from the hatch.
    b.mesh("lamp", quad([-0.6 - s, 2.6, 0.6 - s], [-0.6 - s, 2.6, 0.6 + s], [-0.6 + s, 2.6, 0.6 + s], [-0.6 + s, 2.6, 0.6 - s]), lamp)
    b.camera("camera", [-0.85, 1.0, 0.85], [0.6, 0.7, -0.6], 75.0)
    b.write(path, ["KHR_materials_emissive_strength", "KHR_materials_specular"])

def png_rgba(width, height, pixel):
    """An 8-bit RGBA PNG; pixel(x, y) -> (r, g, b, a) in 0-255, y = 0 the top row."""
    rows = b"".join(b"\0" + bytes(c for x in range(width) for c in pixel(x, y)) for y in range(height))
    chunk = lambda kind, data: struct.pack(">I", len(data)) + kind + data + struct.pack(">I", zlib.crc32(kind + data))
    return (b"\x89PNG\r\n\x1a\n" + chunk(b"IHDR", struct.pack(">IIBBBBB", width, height, 8, 6, 0, 0, 0)) +
            chunk(b"IDAT", zlib.compress(rows, 9)) + chunk(b"IEND", b""))

def leaves(path):
    """Alpha testing under load: a canopy of 12 x 12 tilted leaf cards (alphaMode MASK on a 64 x 64 texture whose
    alpha cuts out a leaf shape: about half of each card is a hole) between a white floor and a ceiling lamp.
    Every camera, bounce and shadow ray that crosses the canopy runs the alpha test (a texture lookup) in the
    walk; `vkmc bench-kernels scenes/textures/leaves.gltf` measures it."""
    def leaf(x, y):
        u, v = (x + 0.5) / 64 - 0.5, (y + 0.5) / 64 - 0.5
        inside = (u / 0.48) ** 2 + (v / 0.3) ** 2 < 1.0 and abs(v) > 0.02
        return (40 + 3 * x, 120 + y, 30, 255 if inside else 0)
    b = Builder()
    card = b.material("leaf", (1.0, 1.0, 1.0), double_sided=True)
    b.materials[card]["pbrMetallicRoughness"]["baseColorTexture"] = {"index": b.texture(png_rgba(64, 64, leaf))}
    b.materials[card]["alphaMode"] = "MASK"
    floor = b.material("floor", (0.8, 0.8, 0.8))
    lamp = b.material("lamp", (0, 0, 0), emission=(1.0, 1.0, 1.0), strength=8.0)
    b.mesh("floor", quad([-2, 0, -2], [-2, 0, 2], [2, 0, 2], [2, 0, -2]), floor)
    b.mesh("lamp", quad([-0.6, 2.4, -0.6], [0.6, 2.4, -0.6], [0.6, 2.4, 0.6], [-0.6, 2.4, 0.6]), lamp)
    rng = random.Random(7)
    tris, uvs = [], []
    for i in range(12):
        for j in range(12):
            cx, cz, cy = -1.65 + 0.3 * i, -1.65 + 0.3 * j, 1.0 + 0.5 * rng.random()
            a, t, h = rng.uniform(0, math.pi), rng.uniform(-0.6, 0.6), 0.22
            ex, ez = [h * math.cos(a), 0, h * math.sin(a)], [-h * math.sin(a) * math.cos(t), h * math.sin(t), h * math.cos(a) * math.cos(t)]
            c = [cx, cy, cz]
            p = [[c[k] + sx * ex[k] + sz * ez[k] for k in range(3)] for sx, sz in ((-1, -1), (1, -1), (1, 1), (-1, 1))]
            tris += quad(p[0], p[1], p[2], p[3])
            uvs += [([0, 1], [1, 1], [1, 0]), ([0, 1], [1, 0], [0, 0])]
    b.mesh("leaves", tris, card, uvs)
    b.camera("camera", [0.0, 3.2, 3.4], [0.0, 0.6, 0.0], 45.0)
    b.write(path, ["KHR_materials_emissive_strength", "KHR_materials_specular"])

if __name__ == "__main__":
    os.makedirs("scenes", exist_ok=True)
    cornell_box("scenes/cornell_box.gltf")
    furnace("scenes/furnace.gltf", 0.5, 1.0, "furnace_albedo_0.5")
    furnace("scenes/furnace_stiff.gltf", 0.99, 1.0, "furnace_albedo_0.99")
    veach_mis("scenes/veach_mis.gltf")
    many_lights("scenes/many_lights.gltf")
    two_rooms("scenes/two_rooms.gltf")
    glossy_room("scenes/glossy_room.gltf")
    soft_shadows("scenes/soft_shadows.gltf")
    desk_lamp("scenes/desk_lamp.gltf")
    dark_room("scenes/dark_room.gltf")
    basement("scenes/basement.gltf")
    os.makedirs("scenes/stiff", exist_ok=True)
    tiny_light("scenes/stiff/tiny_light.gltf")
    furnace("scenes/stiff/furnace_albedo_0999.gltf", 0.999, 1.0, "furnace_albedo_0.999")
    os.makedirs("scenes/materials", exist_ok=True)
    material_furnace("scenes/materials/glass_furnace.gltf", "glass")
    material_furnace("scenes/materials/mirror_furnace.gltf", "mirror")
    caustic("scenes/materials/caustic.gltf")
    glass_bulb("scenes/materials/glass_bulb.gltf")
    os.makedirs("scenes/textures", exist_ok=True)
    leaves("scenes/textures/leaves.gltf")
    print("wrote scenes/cornell_box.gltf, furnace.gltf, furnace_stiff.gltf, veach_mis.gltf, many_lights.gltf")
