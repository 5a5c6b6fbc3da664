#!/usr/bin/env python3
"""A corpus of product glTF files as a customer's pipeline exports them: +Y up, metres, a separate
.bin, PNG textures, Blender-style material names, KHR_materials_sheen, a shop-photo camera.
One folder per product: pole_cushion, sofa, throw, chair, curtain, cushion_draco, cushion_meshopt.

Usage: make_corpus.py OUT_DIR [--size small|full] [--compress-tool PATH]
  --size full (default): the vertex counts a product tool exports; small: the same files at
      1/10 to 1/50 of them (for CI)
  --compress-tool PATH: gltf_compress (tests/scene/gltf_compress.cpp), which writes the Draco and
      meshopt cushions; without it those two are skipped with a note
Prints one line per file: its path, vertices, triangles. Python 3 standard library only.
"""
import argparse
import json
import math
import random
import subprocess
import tempfile
from array import array
from pathlib import Path

from make_product_gltf import cushion, png

GENERATOR = "Khronos glTF Blender I/O v3.6.28 (as written by make_corpus.py)"


def add(a, b):
    return tuple(x + y for x, y in zip(a, b))


def mul(a, k):
    return tuple(x * k for x in a)


def cross(a, b):
    return (a[1] * b[2] - a[2] * b[1], a[2] * b[0] - a[0] * b[2], a[0] * b[1] - a[1] * b[0])


def unit(a):
    length = math.sqrt(sum(x * x for x in a)) or 1.0
    return mul(a, 1.0 / length)


def quat(axis, degrees):
    """glTF's [x, y, z, w] for a rotation about `axis`."""
    s, c = math.sin(math.radians(degrees) / 2), math.cos(math.radians(degrees) / 2)
    return [*mul(unit(axis), s), c]


class Mesh:
    """Positions, UVs and triangles (front faces counter-clockwise); normals come from finish()."""

    def __init__(self):
        self.p, self.uv, self.tri, self.n = [], [], [], []

    def grid(self, nu, nv, at):
        """An nu × nv quad grid; at(s, t) → (position, uv), with ∂p/∂s × ∂p/∂t pointing out."""
        base, row = len(self.p), nu + 1
        for j in range(nv + 1):
            for i in range(nu + 1):
                pos, uv = at(i / nu, j / nv)
                self.p.append(pos)
                self.uv.append(uv)
        for j in range(nv):
            for i in range(nu):
                a = base + j * row + i
                self.tri += [(a, a + 1, a + row + 1), (a, a + row + 1, a + row)]
        return self

    def finish(self, weld=True):
        """Drops the triangles a collapsed grid row makes (an exporter writes none) and the vertices
        left unused; area-weighted normals, shared by vertices at one place when `weld` (smooth
        shading across UV seams, as Blender exports it)."""
        key = [tuple(round(x, 6) for x in q) for q in self.p]
        self.tri = [t for t in self.tri if len({key[i] for i in t}) == 3]
        used = sorted({i for t in self.tri for i in t})
        renumber = {old: new for new, old in enumerate(used)}
        self.p, self.uv, key = [self.p[i] for i in used], [self.uv[i] for i in used], [key[i] for i in used]
        self.tri = [tuple(renumber[i] for i in t) for t in self.tri]
        sums = {}
        acc = [(0.0, 0.0, 0.0)] * len(self.p)
        for a, b, c in self.tri:
            fn = cross(add(self.p[b], mul(self.p[a], -1)), add(self.p[c], mul(self.p[a], -1)))
            for i in (a, b, c):
                if weld:
                    sums[key[i]] = add(sums.get(key[i], (0.0, 0.0, 0.0)), fn)
                else:
                    acc[i] = add(acc[i], fn)
        self.n = [unit(sums[key[i]]) if weld else unit(acc[i]) for i in range(len(self.p))]
        return self


def lathe(mesh, profile, nu, nv, uv_scale=(1.0, 1.0)):
    """A surface of revolution about +Y; profile(t) → (radius, height) from bottom to top. A radius
    of 0 is a pole: its vertices sit mid-segment in u, as a UV sphere exports."""
    def at(s, t):
        r, h = profile(t)
        u = s + (0.5 if t < 0.5 else -0.5) / nu if r == 0 else s  # the pole's triangle between s and s ± 1/nu
        phi = 2 * math.pi * s
        return (r * math.cos(phi), h, -r * math.sin(phi)), (u * uv_scale[0], (1 - t) * uv_scale[1])
    return mesh.grid(nu, nv, at)


# A box's faces (top, bottom, right, left, front, back) as (outward normal, u, v), u × v = the normal.
FACES = [((0, 1, 0), (1, 0, 0), (0, 0, -1)), ((0, -1, 0), (1, 0, 0), (0, 0, 1)), ((1, 0, 0), (0, 0, -1), (0, 1, 0)),
         ((-1, 0, 0), (0, 0, 1), (0, 1, 0)), ((0, 0, 1), (1, 0, 0), (0, 1, 0)), ((0, 0, -1), (-1, 0, 0), (0, 1, 0))]


def axis(d):
    return max(range(3), key=lambda k: abs(d[k]))


def box_panels(centre, size, puff, edge, density):
    """A box cushion sewn from six panels, each puffed out by up to `puff` metres (its seams stay on
    the box's edges). Returns [(panel, island width, island height)]; panel(mesh, uv_of) adds it."""
    half = mul(size, 0.5)
    thin = min(range(3), key=lambda k: size[k])
    out = []
    for n, u, v in FACES:
        hn, hu, hv = half[axis(n)], half[axis(u)], half[axis(v)]
        big = axis(n) == thin  # the two large faces: full texel density and puff; the sides half
        dens, bulge = density * (1.0 if big else 0.5), puff * (1.0 if big else 0.4)
        nu, nv = max(2, round(2 * hu / edge)), max(2, round(2 * hv / edge))

        def panel(mesh, uv_of, n=n, u=u, v=v, hn=hn, hu=hu, hv=hv, bulge=bulge, nu=nu, nv=nv):
            def at(s, t):
                b = ((1 - (2 * s - 1) ** 2) * (1 - (2 * t - 1) ** 2)) ** 0.6 * bulge
                q = add(add(add(centre, mul(n, hn + b)), mul(u, (2 * s - 1) * hu)), mul(v, (2 * t - 1) * hv))
                return q, uv_of(s, t)
            mesh.grid(nu, nv, at)
        out.append((panel, 2 * hu * dens, 2 * hv * dens))
    return out


def pack_atlas(islands, gap=0.02):
    """Shelf-packs islands [(w, h)] into one [0, 1]² atlas, all scaled alike (their texel
    densities keep their ratios); returns each island's uv_of(s, t)."""
    side = max(max(w for w, _ in islands), math.sqrt(sum((w + gap) * (h + gap) for w, h in islands)) * 1.15)
    order = sorted(range(len(islands)), key=lambda i: -islands[i][1])
    x = y = shelf = 0.0
    spots = [None] * len(islands)
    for i in order:
        w, h = islands[i]
        if x + w > side:
            x, y, shelf = 0.0, y + shelf + gap, 0.0
        spots[i] = (x, y)
        x, shelf = x + w + gap, max(shelf, h)
    k = 0.98 / max(side, y + shelf)
    return [lambda s, t, o=spots[i], w=islands[i][0], h=islands[i][1]: (0.01 + k * (o[0] + s * w), 0.01 + k * (o[1] + t * h))
            for i in range(len(islands))]


def sewn(groups):
    """One finished Mesh per group of box_panels() boxes, all their panels packed into one atlas."""
    uv_of = iter(pack_atlas([(w, h) for group in groups for box in group for _, w, h in box]))
    meshes = []
    for group in groups:
        m = Mesh()
        for box in group:
            for panel, _, _ in box:
                panel(m, next(uv_of))
        meshes.append(m.finish())
    return meshes


def tube(mesh, points, radius, segments, bend=0.06, step=0.02):
    """A round tube along a polyline, its corners bent with radius ~`bend`; UVs around and along."""
    path = [points[0]]
    for a, b, c in zip(points, points[1:], points[2:]):
        da, dc = unit(add(b, mul(a, -1))), unit(add(c, mul(b, -1)))
        p0, p2 = add(b, mul(da, -bend)), add(b, mul(dc, bend))
        path += [add(add(mul(p0, (1 - t) ** 2), mul(b, 2 * t * (1 - t))), mul(p2, t * t)) for t in (i / 8 for i in range(9))]
    path.append(points[-1])
    dense = [path[0]]
    for a, b in zip(path, path[1:]):
        d = math.dist(a, b)
        dense += [add(a, mul(add(b, mul(a, -1)), k / max(1, round(d / step)))) for k in range(1, max(1, round(d / step)) + 1)]
    tangents = [unit(add(dense[min(i + 1, len(dense) - 1)], mul(dense[max(i - 1, 0)], -1))) for i in range(len(dense))]
    side = unit(cross(tangents[0], (0.3, 0.5, 0.8)))
    frames, length, lengths = [], 0.0, [0.0]
    for i, t in enumerate(tangents):  # parallel transport: the rings do not twist
        side = unit(cross(cross(t, side), t))
        frames.append((side, cross(t, side)))
        if i:
            length += math.dist(dense[i - 1], dense[i])
            lengths.append(length)

    def at(s, t):
        i = round(t * (len(dense) - 1))
        a, b = frames[i]
        phi = 2 * math.pi * s  # s runs anticlockwise about the path: ∂p/∂s × ∂p/∂t points out
        return add(dense[i], add(mul(a, radius * math.cos(phi)), mul(b, radius * math.sin(phi)))), (s, lengths[i] / (2 * math.pi * radius))
    return mesh.grid(segments, len(dense) - 1, at)


def normal_png(size, height, strength):
    """A tangent-space normal map (OpenGL convention, +Y up the image) of a periodic height field."""
    def pixel(x, y):
        dx = height((x + 1) % size, y) - height((x - 1) % size, y)
        dy = height(x, (y - 1) % size) - height(x, (y + 1) % size)
        n = unit((-dx * strength, -dy * strength, 1.0))
        return tuple(int(round((c * 0.5 + 0.5) * 255)) for c in n)
    return png(size, size, pixel)


class Gltf:
    """One product file: meshes, materials, textures, nodes and a camera, written with its .bin."""

    def __init__(self, name):
        self.name, self.blob, self.pngs, self.vertices, self.triangles = name, bytearray(), {}, 0, 0
        self.counts = []  # per mesh: (vertices, triangles), counted once per node that draws it
        self.j = {"asset": {"version": "2.0", "generator": GENERATOR}, "scene": 0, "scenes": [{"name": "Scene", "nodes": []}],
                  "nodes": [], "meshes": [], "materials": [], "accessors": [], "bufferViews": [], "extensionsUsed": []}

    def _accessor(self, values, code, component, count, kind, target, bounds=None):
        while len(self.blob) % 4:
            self.blob.append(0)
        data = array(code, values).tobytes()
        self.j["bufferViews"].append({"buffer": 0, "byteOffset": len(self.blob), "byteLength": len(data), "target": target})
        self.blob += data
        acc = {"bufferView": len(self.j["bufferViews"]) - 1, "componentType": component, "count": count, "type": kind}
        if bounds:
            acc["min"], acc["max"] = bounds
        self.j["accessors"].append(acc)
        return len(self.j["accessors"]) - 1

    def mesh(self, name, parts):
        """parts: [(finished Mesh, material index)] → mesh index."""
        prims = []
        for m, material in parts:
            wide = len(m.p) > 65535  # 32-bit indices past what 16 bits can name
            bounds = ([min(q[k] for q in m.p) for k in range(3)], [max(q[k] for q in m.p) for k in range(3)])
            attrs = {"POSITION": self._accessor([x for q in m.p for x in q], "f", 5126, len(m.p), "VEC3", 34962, bounds)}
            if m.n:
                attrs["NORMAL"] = self._accessor([x for q in m.n for x in q], "f", 5126, len(m.p), "VEC3", 34962)
            attrs["TEXCOORD_0"] = self._accessor([x for q in m.uv for x in q], "f", 5126, len(m.p), "VEC2", 34962)
            indices = self._accessor([i for t in m.tri for i in t], "I" if wide else "H", 5125 if wide else 5123,
                                     3 * len(m.tri), "SCALAR", 34963)
            prims.append({"attributes": attrs, "indices": indices, "material": material})
        self.j["meshes"].append({"name": name, "primitives": prims})
        self.counts.append((sum(len(m.p) for m, _ in parts), sum(len(m.tri) for m, _ in parts)))
        return len(self.j["meshes"]) - 1

    def texture(self, name, data, transform=None):
        """A textureInfo for PNG `data` (kept as NAME.png beside the file)."""
        self.pngs[name + ".png"] = data
        self.j.setdefault("images", []).append({"name": name, "mimeType": "image/png", "uri": name + ".png"})
        self.j.setdefault("samplers", [{"magFilter": 9729, "minFilter": 9987}])
        self.j.setdefault("textures", []).append({"sampler": 0, "source": len(self.j["images"]) - 1})
        info = {"index": len(self.j["textures"]) - 1}
        if transform:
            info["extensions"] = {"KHR_texture_transform": {"scale": [transform, transform]}}
            self.uses("KHR_texture_transform")
        return info

    def uses(self, extension):
        if extension not in self.j["extensionsUsed"]:
            self.j["extensionsUsed"].append(extension)

    def material(self, name, colour, roughness=0.8, metallic=0.0, sheen=None, base=None, normal=None, extras=None):
        """sheen: (sheenColorFactor, sheenRoughnessFactor); base, normal: textureInfos."""
        pbr = {"baseColorFactor": [*colour, 1.0], "metallicFactor": metallic, "roughnessFactor": roughness}
        m = {"name": name, "pbrMetallicRoughness": pbr}
        if base:
            pbr["baseColorTexture"] = base
        if normal:
            m["normalTexture"] = normal
        if sheen:
            m["extensions"] = {"KHR_materials_sheen": {"sheenColorFactor": sheen[0], "sheenRoughnessFactor": sheen[1]}}
            self.uses("KHR_materials_sheen")
        if extras:
            m["extras"] = extras
        if sheen or normal:
            m["doubleSided"] = True  # cloth is one sheet of triangles seen from both sides
        self.j["materials"].append(m)
        return len(self.j["materials"]) - 1

    def node(self, name, parent=None, **fields):
        """A node (mesh=, camera=, translation=, rotation=, scale=, children=) under `parent` or the scene."""
        self.j["nodes"].append({"name": name, **fields})
        if "mesh" in fields:
            self.vertices += self.counts[fields["mesh"]][0]
            self.triangles += self.counts[fields["mesh"]][1]
        index = len(self.j["nodes"]) - 1
        siblings = self.j["scenes"][0]["nodes"] if parent is None else self.j["nodes"][parent].setdefault("children", [])
        siblings.append(index)
        return index

    def camera(self, lo, hi, azimuth, elevation, yfov=35.0, fill=0.85):
        """A camera node looking at the box lo..hi's centre from `azimuth` degrees right of the front
        (+Z) and `elevation` above, near enough that the box's bounding sphere fills `fill` of the height."""
        centre = mul(add(lo, hi), 0.5)
        radius = 0.5 * math.dist(lo, hi)
        a, e = math.radians(azimuth), math.radians(elevation)
        back = (math.sin(a) * math.cos(e), math.sin(e), math.cos(a) * math.cos(e))  # the camera's +Z
        eye = add(centre, mul(back, fill * radius / math.sin(math.radians(yfov) / 2)))
        x = unit(cross((0, 1, 0), back))
        y = cross(back, x)
        # The rotation whose columns are x, y, back, as a quaternion (its trace is positive for |azimuth| < 90°).
        w = 0.5 * math.sqrt(1 + x[0] + y[1] + back[2])
        rotation = [(y[2] - back[1]) / (4 * w), (back[0] - x[2]) / (4 * w), (x[1] - y[0]) / (4 * w), w]
        self.j.setdefault("cameras", []).append({"name": "Shop", "type": "perspective", "perspective": {
            "aspectRatio": 4 / 3, "yfov": math.radians(yfov), "znear": 0.05, "zfar": 50.0}})
        self.node("Camera", camera=len(self.j["cameras"]) - 1, translation=list(eye), rotation=rotation)

    def save(self, out_dir, quiet=False):
        folder = Path(out_dir) / self.name
        folder.mkdir(parents=True, exist_ok=True)
        for name, data in self.pngs.items():
            (folder / name).write_bytes(data)
        (folder / f"{self.name}.bin").write_bytes(self.blob)
        self.j["buffers"] = [{"byteLength": len(self.blob), "uri": f"{self.name}.bin"}]
        if not self.j["extensionsUsed"]:
            del self.j["extensionsUsed"]
        path = folder / f"{self.name}.gltf"
        path.write_text(json.dumps(self.j, indent=1))
        if not quiet:
            print(f"{path} {self.vertices} vertices {self.triangles} triangles")


def pole_cushion(small):
    """A round ball cushion in eight gores, a UV sphere's mapping: u around, v from pole to pole."""
    g = Gltf("pole_cushion")
    velvet = g.material("Velvet", (0.28, 0.05, 0.12), sheen=([0.85, 0.45, 0.6], 0.3), roughness=0.75)
    radius, squash = 0.2, 0.72

    def profile(t):
        theta = math.pi * (1 - t)
        dimple = 1 - 0.25 * math.exp(-(min(t, 1 - t) / 0.08) ** 2)  # buttoned at both poles
        r = 0 if t in (0, 1) else radius * math.sin(theta)
        return r, radius * squash * math.cos(theta) * dimple + radius * squash
    nu, nv = (16, 10) if small else (48, 40)
    m = lathe(Mesh(), profile, nu, nv)
    m.p = [(x * (1 + 0.04 * math.cos(8 * math.atan2(z, x))), y, z * (1 + 0.04 * math.cos(8 * math.atan2(z, x))))
           for x, y, z in m.p]  # eight gores bulging between their seams
    g.node("Ball_Cushion", mesh=g.mesh("Ball_Cushion", [(m.finish(), velvet)]))
    g.camera((-0.2, 0, -0.2), (0.2, 0.29, 0.2), azimuth=-25, elevation=22)
    return g


def sofa(small):
    """Three seat and three back box cushions and an upholstered base on four oak legs; every
    fabric panel one island of one atlas, the big faces at full texel density, the sides at half,
    the base at 0.7."""
    g = Gltf("sofa")
    def loops(x, y):  # curly loops of yarn, tiling every 64 pixels
        h = math.sin(2 * math.pi * (x / 8 + 0.3 * math.sin(2 * math.pi * y / 16))) * math.sin(
            2 * math.pi * (y / 8 + 0.3 * math.sin(2 * math.pi * x / 32)))
        return int(222 + 28 * h), int(214 + 28 * h), int(196 + 26 * h)
    boucle = g.texture("boucle", png(64, 64, loops), transform=24.0)
    fabric = g.material("Fabric_Boucle.001", (0.93, 0.88, 0.8), sheen=([0.7, 0.68, 0.62], 0.55), base=boucle, roughness=0.95)
    rng = random.Random(7)
    knots = [rng.random() for _ in range(8)]
    def grain(x, y):  # growth rings, wavy along the leg
        h = (x / 5 + 0.8 * math.sin(2 * math.pi * y / 64) + knots[y // 8]) % 1.0
        return int(190 - 50 * h), int(142 - 40 * h), int(92 - 30 * h)
    oak = g.material("Oak", (1.0, 1.0, 1.0), roughness=0.55, base=g.texture("oak_grain", png(64, 64, grain)))
    edge = 0.031 if small else 0.0065
    # The cushions (name, size, puff), each a mesh its node places; the base's boxes (centre, size, puff)
    # in the sofa's frame, flat tight upholstery: coarser, at 0.7 of the cushions' texel density.
    cushions = [(f"Seat_Cushion_{k + 1}", (0.62, 0.16, 0.585), 0.025) for k in range(3)] + \
               [(f"Back_Cushion_{k + 1}", (0.62, 0.5, 0.18), 0.03) for k in range(3)]
    base = [((0, 0.27, 0.0875), (1.86, 0.3, 0.775), 0.006), ((-1.015, 0.39, 0), (0.17, 0.54, 0.95), 0.01),
            ((1.015, 0.39, 0), (0.17, 0.54, 0.95), 0.01), ((0, 0.46, -0.3875), (1.86, 0.68, 0.175), 0.006)]
    meshes = sewn([[box_panels((0, 0, 0), size, puff, edge, 1.0)] for _, size, puff in cushions] +
                  [[box_panels(c, size, puff, 2.5 * edge, 0.7) for c, size, puff in base]])
    sofa_node = g.node("Sofa")
    for k in range(3):
        x = (k - 1) * 0.62
        g.node(cushions[k][0], sofa_node, mesh=g.mesh(cushions[k][0], [(meshes[k], fabric)]),
               translation=[x, 0.5, 0.1875])
        g.node(cushions[3 + k][0], sofa_node, mesh=g.mesh(cushions[3 + k][0], [(meshes[3 + k], fabric)]),
               translation=[x, 0.67, -0.2], rotation=quat((1, 0, 0), -9))
    g.node("Sofa_Base", sofa_node, mesh=g.mesh("Sofa_Base", [(meshes[6], fabric)]))
    nu, nv = (10, 3) if small else (24, 8)
    leg = lathe(Mesh(), lambda t: (0, 0) if t == 0 else (0.018 + 0.008 * (t * nv - 1) / (nv - 1), 0.12 * (t * nv - 1) / (nv - 1)),
                nu, nv, uv_scale=(1.0, 2.0)).finish()
    legs = g.mesh("Oak_Leg", [(leg, oak)])
    for k, (x, z) in enumerate([(-1.0, 0.4), (1.0, 0.4), (-1.0, -0.4), (1.0, -0.4)]):
        g.node(f"Leg_{k + 1}", sofa_node, mesh=legs, translation=[x, 0, z])
    g.camera((-1.1, 0, -0.48), (1.1, 1.05, 0.48), azimuth=-28, elevation=14, fill=0.78)
    return g


def throw(small):
    """A linen throw folded over on itself, rippled; its UVs mirrored about its centre line (the left
    half's u is the right half's 1 − u), as a mirror modifier exports them."""
    g = Gltf("throw")
    def height(x, y):  # a basket weave: warp and weft floats over 4 pixels, alternating
        over = (x // 4 + y // 4) % 2
        return (math.sin(math.pi * x / 4) ** 2 if over else 0.35) + (0.35 if over else math.sin(math.pi * y / 4) ** 2)
    bump = g.texture("linen_weave_normal", normal_png(32, height, 1.5), transform=30.0)
    linen = g.material("Linen.002", (0.55, 0.62, 0.5), roughness=0.9, normal=dict(bump, scale=0.8))
    lower, r, length = 1.05, 0.03, 1.6  # the lower layer's length, the fold's radius, the whole length

    def at(s, t):
        x, ell = 0.5 - s, t * length  # s runs right to left: the lower layer's front faces up
        if ell < lower:
            z, y = -0.75 + ell, 0.0
        elif ell < lower + math.pi * r:
            a = (ell - lower) / r
            z, y = -0.75 + lower + r * math.sin(a), r - r * math.cos(a)
        else:
            z, y = -0.75 + lower - (ell - lower - math.pi * r), 2 * r
        # Ripples even in x: the mirror modifier's half is the other's image.
        y += 0.008 * math.cos(2 * math.pi * x / 0.23) * math.sin(3 * ell + 1) + 0.006 * math.cos(8 * x) * math.cos(4.4 * ell)
        return (x, y, z), (0.5 + abs(x), ell)
    nu, nv = (32, 40) if small else (160, 200)  # nu even: the centre line is a column of shared vertices
    m = Mesh().grid(nu, nv, at).finish()
    parent = g.node("Bench_Top", translation=[0.0, 0.45, 0.1])
    g.node("Throw", parent, mesh=g.mesh("Throw", [(m, linen)]), scale=[1.4, 1.0, 0.8], rotation=quat((0, 1, 0), 25))
    g.camera((-0.8, 0.45, -0.7), (0.8, 0.55, 0.75), azimuth=40, elevation=30, fill=0.62)
    return g


def chair(small):
    """An armchair: a steel tube frame (modelled in centimetres, scaled by its node), plastic feet, a
    wool seat pad and a tilted back pad."""
    g = Gltf("chair")
    twill = g.texture("wool_twill_normal", normal_png(32, lambda x, y: math.sin(2 * math.pi * (x + y) / 8), 1.2),
                      transform=20.0)
    wool = g.material("Fabric_Wool", (0.72, 0.5, 0.1), sheen=([0.9, 0.75, 0.4], 0.45), normal=twill, roughness=0.9)
    steel = g.material("Steel", (0.8, 0.81, 0.83), metallic=1.0, roughness=0.3)
    plastic = g.material("Plastic_Black", (0.03, 0.03, 0.03), roughness=0.5)
    edge, step, segments = (0.06, 10.0, 6) if small else (0.012, 2.0, 16)
    seat, back = sewn([[box_panels((0, 0, 0), (0.62, 0.09, 0.54), 0.02, edge, 1.0)],
                       [box_panels((0, 0, 0), (0.58, 0.46, 0.08), 0.02, edge, 1.0)]])
    frame = Mesh()
    for x in (-34, 34):
        tube(frame, [(x, 2.5, 30), (x, 64, 28), (x, 64, -26), (x, 2.5, -30)], 1.3, segments, bend=6, step=step)
        tube(frame, [(x, 36, 29), (x, 36, -28)], 1.3, segments, step=step)
    for z in (29, -28):
        tube(frame, [(-34, 36, z), (34, 36, z)], 1.3, segments, step=step)
    tube(frame, [(-30, 36, -28), (-30, 92, -40), (30, 92, -40), (30, 36, -28)], 1.3, segments, bend=6, step=step)
    rows = [(0, 0), (0.018, 0), (0.018, 0.02), (0.013, 0.027), (0, 0.027)]
    foot = lathe(Mesh(), lambda t: rows[round(t * 4)], 16 if not small else 8, 4).finish()
    root = g.node("Armchair", rotation=quat((0, 1, 0), -20))
    g.node("Frame", root, mesh=g.mesh("Frame", [(frame.finish(), steel)]), scale=[0.01, 0.01, 0.01])
    g.node("Seat_Pad", root, mesh=g.mesh("Seat_Pad", [(seat, wool)]), translation=[0, 0.42, 0.03])
    g.node("Back_Pad", root, mesh=g.mesh("Back_Pad", [(back, wool)]), translation=[0, 0.7, -0.29],
           rotation=quat((1, 0, 0), -12))
    feet, foot_mesh = g.node("Feet", root), g.mesh("Foot", [(foot, plastic)])
    for k, (x, z) in enumerate([(-0.34, 0.3), (0.34, 0.3), (-0.34, -0.3), (0.34, -0.3)]):
        g.node(f"Foot_{k + 1}", feet, mesh=foot_mesh, translation=[x, 0, z], scale=[1.0, 1.2, 1.0])
    g.camera((-0.42, 0, -0.45), (0.42, 0.93, 0.42), azimuth=-30, elevation=15, fill=0.9)
    return g


def curtain(small):
    """A sheer curtain in vertical folds hanging before a window: a wall with a rectangular opening,
    a window frame with a transom and a sill (both Lambertian)."""
    g = Gltf("curtain")
    voile = g.material("Voile", (0.96, 0.94, 0.88), sheen=([0.9, 0.9, 0.85], 0.35), roughness=0.85,
                       extras={"weft": {"optical_thickness": 0.6}})
    plaster = g.material("Wall_Plaster", (0.62, 0.66, 0.72), roughness=1.0)
    paint = g.material("Window_Frame_White", (0.9, 0.9, 0.88), roughness=0.4)
    wall = Mesh()
    for x0, x1, y0, y1 in [(-1.6, 1.6, 0, 0.9), (-1.6, 1.6, 2.3, 2.7), (-1.6, -0.6, 0.9, 2.3), (0.6, 1.6, 0.9, 2.3)]:
        wall.grid(4, 4, lambda s, t, x0=x0, x1=x1, y0=y0, y1=y1: ((x0 + s * (x1 - x0), y0 + t * (y1 - y0), 0.0),
                                                                  ((x0 + s * (x1 - x0)) / 2, (y0 + t * (y1 - y0)) / 2)))
    frame = Mesh()
    for c, size in [((-0.63, 1.6, 0), (0.06, 1.46, 0.12)), ((0.63, 1.6, 0), (0.06, 1.46, 0.12)),
                    ((0, 2.33, 0), (1.32, 0.06, 0.12)), ((0, 1.75, 0), (1.2, 0.05, 0.08)), ((0, 0.88, 0.04), (1.4, 0.04, 0.22))]:
        for panel, _, _ in box_panels(c, size, 0.0, 1.0, 1.0):
            panel(frame, lambda s, t: (s, t))
    nu, nv = (36, 48) if small else (240, 320)  # full: past 65 535 vertices, so 32-bit indices

    def at(s, t):
        x, y = -0.95 + 1.3 * s, 0.03 + 2.45 * t  # drawn to the left: the window shows beside it
        depth = (0.035 + 0.02 * (1 - t)) * (1 + 0.25 * math.sin(2 * math.pi * x / 0.9))  # fuller towards the hem
        return (x, y, 0.24 + depth * math.sin(2 * math.pi * x / 0.17 + 0.6 * math.sin(3 * y))), (2.6 * s, 2.45 * t)
    drape = Mesh().grid(nu, nv, at).finish()
    room = g.node("Window_Wall")
    g.node("Wall", room, mesh=g.mesh("Wall", [(wall.finish(weld=False), plaster)]))
    g.node("Window_Frame", room, mesh=g.mesh("Window_Frame", [(frame.finish(weld=False), paint)]))
    g.node("Curtain", room, mesh=g.mesh("Curtain", [(drape, voile)]))
    g.camera((-1.3, 0.0, 0.0), (1.3, 2.7, 0.25), azimuth=18, elevation=4, yfov=40, fill=0.72)
    return g


def compressed_cushion(small, name, material):
    """make_product_gltf.py's cushion with normals, to be compressed by gltf_compress."""
    g = Gltf(name)
    m = Mesh()
    m.p, m.uv, indices = cushion(10 if small else 50)
    m.tri = [tuple(indices[k:k + 3]) for k in range(0, len(indices), 3)]
    stripes = g.texture(name + "_stripes", png(16, 16, lambda x, y: (240, 236, 228) if (x // 4) % 2 else (205, 200, 190)),
                        transform=5.0)
    g.node("Cushion", mesh=g.mesh("Cushion", [(m.finish(), g.material(**material, base=stripes))]))
    g.camera((-0.225, 0, -0.225), (0.225, 0.14, 0.225), azimuth=-20, elevation=35, fill=0.8)
    return g


def main():
    args = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    args.add_argument("out_dir")
    args.add_argument("--size", choices=["small", "full"], default="full")
    args.add_argument("--compress-tool")
    a = args.parse_args()
    small = a.size == "small"
    for product in (pole_cushion, sofa, throw, chair, curtain):
        product(small).save(a.out_dir)
    for name, flag, material in [
            ("cushion_draco", "--draco", dict(name="Cushion_Cotton", colour=(0.72, 0.3, 0.18), roughness=0.9)),
            ("cushion_meshopt", "--meshopt", dict(name="Silk_Cushion.003", colour=(0.1, 0.45, 0.45), roughness=0.4,
                                                  sheen=([0.5, 0.8, 0.8], 0.25)))]:
        g = compressed_cushion(small, name, material)
        if not a.compress_tool:
            print(f"{name}: skipped (--compress-tool names no gltf_compress)")
            continue
        with tempfile.TemporaryDirectory() as plain:
            g.save(plain, quiet=True)
            path = Path(a.out_dir) / name / f"{name}.gltf"
            subprocess.run([a.compress_tool, str(Path(plain) / name / f"{name}.gltf"), str(path), flag], check=True,
                           stdout=subprocess.DEVNULL)
        print(f"{path} {g.vertices} vertices {g.triangles} triangles")


if __name__ == "__main__":
    main()
