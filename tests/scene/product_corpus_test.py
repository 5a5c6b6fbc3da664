#!/usr/bin/env python3
"""The small product corpus (make_corpus.py, with gltf_compress for the Draco and meshopt cushions)
imports: each file renders one frame with `weft-offline render --method sheen`, its log names the
materials the importer took as cloth, and the cloth is in the frame, lit and framed (the pixels a
different fabric changes, at the same exposure). From the glTF data itself: the throw's UVs are
mirrored about its centre line, the sofa's fabric islands are disjoint in one atlas at different
texel densities, the compressed cushions are compressed.

Usage: product_corpus_test.py WEFT_OFFLINE GLTF_COMPRESS ASSETS_DIR WORK_DIR   (Python 3 standard library only)
"""
import json
import math
import os
import shutil
import struct
import subprocess
import sys
from pathlib import Path

HERE = Path(__file__).resolve().parent
sys.path.insert(0, str(HERE))
from product_gltf_round_trip_test import png_pixels  # noqa: E402

# Per product: the materials the importer must take as cloth, and the preset each becomes.
CLOTH = {
    "pole_cushion": {"Velvet": "velvet"},
    "sofa": {"Fabric_Boucle.001": "linen_plain"},
    "throw": {"Linen.002": "linen_plain"},
    "chair": {"Fabric_Wool": "linen_plain"},
    "curtain": {"Voile": "polyester_voile"},
    "cushion_draco": {"Cushion_Cotton": "linen_plain"},
    "cushion_meshopt": {"Silk_Cushion.003": "silk_crepe_de_chine"},
}
OTHER_FABRIC = "polyester_satin_charmeuse"  # a weave none of the corpus's cloth has: its pixels change
SIZE = ["--width", "96", "--height", "72", "--frames", "1", "--method", "sheen"]


def render(weft, gltf, out, env, *extra):
    r = subprocess.run([weft, "render", "--scene", gltf, *SIZE, "--out", out, *extra], env=env, stdout=subprocess.PIPE,
                       stderr=subprocess.STDOUT, text=True, timeout=120)
    assert r.returncode == 0, f"{gltf}: weft-offline render exited {r.returncode}:\n{r.stdout}"
    summary = json.loads(next(line for line in r.stdout.splitlines() if line.startswith("{")))
    return r.stdout, summary


def check_frame(weft, gltf, work, env):
    product = gltf.parent.name
    log, summary = render(weft, gltf, work / f"{product}.exr", env)
    for material, preset in CLOTH[product].items():
        said = f"material '{material}' taken as cloth"
        assert said in log and f"preset {preset}" in log, f"{product}: the log does not say {said} in {preset}:\n{log}"
    # The same frame in another fabric at the same exposure: what changes is the cloth.
    render(weft, gltf, work / f"{product}_other.exr", env, "--fabric", OTHER_FABRIC, "--exposure", str(summary["png_exposure"]))
    a, b = png_pixels(work / f"{product}.png"), png_pixels(work / f"{product}_other.png")
    h, w = len(a), len(a[0])
    cloth = [(x, y) for y in range(h) for x in range(w) if max(abs(p - q) for p, q in zip(a[y][x], b[y][x])) > 3]
    share = len(cloth) / (w * h)
    assert share > 0.03, f"{product}: the cloth covers {share:.1%} of the frame"
    lit = sum(sum(a[y][x]) / 3 for x, y in cloth) / len(cloth)
    assert lit > 40, f"{product}: the cloth is dark (mean level {lit:.0f} of 255)"
    cx, cy = sum(x for x, _ in cloth) / len(cloth) / w, sum(y for _, y in cloth) / len(cloth) / h
    assert 0.2 < cx < 0.8 and 0.2 < cy < 0.8, f"{product}: the cloth sits at ({cx:.2f}, {cy:.2f}) of the frame, not framed"
    return f"{product}: cloth {share:.0%} of the frame, mean level {lit:.0f}, centred at ({cx:.2f}, {cy:.2f})"


def primitives(gltf, material_name):
    """The (positions, uvs, triangles) of each primitive wearing `material_name`, as the file stores them."""
    j = json.loads(gltf.read_text())
    blob = (gltf.parent / j["buffers"][0]["uri"]).read_bytes()

    def read(index):
        a = j["accessors"][index]
        v = j["bufferViews"][a["bufferView"]]
        n = {"SCALAR": 1, "VEC2": 2, "VEC3": 3}[a["type"]]
        code = {5126: "f", 5123: "H", 5125: "I"}[a["componentType"]]
        flat = struct.unpack_from(f"<{a['count'] * n}{code}", blob, v.get("byteOffset", 0) + a.get("byteOffset", 0))
        return [flat[k:k + n] for k in range(0, len(flat), n)] if n > 1 else list(flat)
    wanted = [k for k, m in enumerate(j["materials"]) if m["name"] == material_name]
    out = []
    for mesh in j["meshes"]:
        for p in mesh["primitives"]:
            if p.get("material") in wanted:
                idx = read(p["indices"])
                out.append((read(p["attributes"]["POSITION"]), read(p["attributes"]["TEXCOORD_0"]),
                            [idx[k:k + 3] for k in range(0, len(idx), 3)]))
    assert out, f"{gltf}: no primitive wears '{material_name}'"
    return out


def uv_area(uv, t):
    (a, b), (c, d), (e, f) = (uv[i] for i in t)
    return 0.5 * ((c - a) * (f - b) - (e - a) * (d - b))


def check_mirrored_throw(gltf):
    [(pos, uv, tris)] = primitives(gltf, "Linen.002")
    # Every vertex's mirror image across x = 0 is a vertex with the same UV.
    at = {(round(x, 5), round(y, 5), round(z, 5)): uv[i] for i, (x, y, z) in enumerate(pos)}
    for (x, y, z), t in zip(pos, uv):
        mirror = at.get((round(-x, 5), round(y, 5), round(z, 5)))
        assert mirror is not None and math.dist(mirror, t) < 1e-5, f"throw: vertex {(x, y, z)} has no mirror with its UV {t}"
    # Seen in UV space, the triangles of one half are wound the other way from the other half's.
    side = [sum(pos[i][0] for i in t) for t in tris]
    flipped = [uv_area(uv, t) < 0 for t in tris]
    left = {f for s, f in zip(side, flipped) if s < 0}
    right = {f for s, f in zip(side, flipped) if s > 0}
    assert len(left) == 1 and len(right) == 1 and left != right, f"throw: UV windings left {left}, right {right}"
    share = sum(flipped) / len(tris)
    assert 0.45 < share < 0.55, f"throw: {share:.0%} of the triangles have flipped UVs, not half"
    return f"throw: UVs mirrored, {share:.0%} of {len(tris)} triangles flipped"


def islands(tris):
    """The triangles' connected pieces (sharing vertices), as lists of triangles."""
    parent = {}

    def root(i):
        while parent.setdefault(i, i) != i:
            parent[i] = parent[parent[i]]
            i = parent[i]
        return i
    for a, b, c in tris:
        parent[root(b)] = root(a)
        parent[root(c)] = root(a)
    pieces = {}
    for t in tris:
        pieces.setdefault(root(t[0]), []).append(t)
    return list(pieces.values())


def check_sofa_atlas(gltf):
    boxes, densities = [], []
    for pos, uv, tris in primitives(gltf, "Fabric_Boucle.001"):
        for piece in islands(tris):
            us = [uv[i] for t in piece for i in t]
            boxes.append((min(u for u, _ in us), min(v for _, v in us), max(u for u, _ in us), max(v for _, v in us)))
            area3 = sum(0.5 * math.dist((0, 0, 0), cross(pos, t)) for t in piece)
            densities.append(math.sqrt(sum(abs(uv_area(uv, t)) for t in piece) / area3))
    assert len(boxes) == 6 * 6 + 4 * 6, f"sofa: {len(boxes)} fabric UV islands (six cushions and four base boxes of six panels)"
    assert all(0 <= b[0] and 0 <= b[1] and b[2] <= 1 and b[3] <= 1 for b in boxes), "sofa: an island leaves the atlas"
    for i, a in enumerate(boxes):
        for b in boxes[i + 1:]:
            assert a[2] <= b[0] or b[2] <= a[0] or a[3] <= b[1] or b[3] <= a[1], f"sofa: UV islands {a} and {b} overlap"
    ratio = max(densities) / min(densities)
    assert ratio > 1.8, f"sofa: texel densities vary only by {ratio:.2f}×"
    return f"sofa: {len(boxes)} disjoint UV islands in one atlas, texel densities {min(densities):.2f} to {max(densities):.2f} UV units per metre"


def cross(pos, t):
    a, b, c = (pos[i] for i in t)
    u, v = [b[k] - a[k] for k in range(3)], [c[k] - a[k] for k in range(3)]
    return (u[1] * v[2] - u[2] * v[1], u[2] * v[0] - u[0] * v[2], u[0] * v[1] - u[1] * v[0])


def main(weft, compress, assets, work):
    work = Path(work)
    shutil.rmtree(work, ignore_errors=True)
    work.mkdir(parents=True)
    made = subprocess.run([sys.executable, str(HERE / "make_corpus.py"), str(work / "corpus"), "--size", "small",
                           "--compress-tool", compress], stdout=subprocess.PIPE, text=True, check=True).stdout
    files = {Path(line.split()[0]).parent.name: Path(line.split()[0]) for line in made.splitlines()}
    assert sorted(files) == sorted(CLOTH), f"make_corpus.py wrote {sorted(files)}:\n{made}"
    for name, extension in [("cushion_draco", "KHR_draco_mesh_compression"), ("cushion_meshopt", "EXT_meshopt_compression")]:
        required = json.loads(files[name].read_text()).get("extensionsRequired", [])
        assert extension in required, f"{name}: requires {required}, not {extension}"
    for name, gltf in files.items():
        j = json.loads(gltf.read_text())
        assert any("camera" in n for n in j["nodes"]), f"{name}: no camera node"
    env = dict(os.environ, WEFT_ASSETS=str(assets))
    for gltf in files.values():
        print(check_frame(weft, gltf, work, env))
    print(check_mirrored_throw(files["throw"]))
    print(check_sofa_atlas(files["sofa"]))
    print("PASS")


if __name__ == "__main__":
    if len(sys.argv) != 5:
        sys.exit(__doc__)
    main(*sys.argv[1:])
