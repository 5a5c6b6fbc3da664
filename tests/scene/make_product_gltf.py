#!/usr/bin/env python3
"""Writes a glTF as the product tool exports it (Blender's glTF exporter): a cushion with UVs, a
separate .bin, a baseColorTexture PNG under KHR_texture_transform, materials named as Blender names
copies ("linen_plain.001"), and two colourways as KHR_materials_variants.

Usage: make_product_gltf.py OUT_DIR [--grid N]   (writes OUT_DIR/cushion.gltf, cushion.bin, cushion_weave.png)
  --grid N: each sheet an N×N grid (default 16: 578 vertices; 160: 51 842, as a product tool's dense export)
Python 3 standard library only.
"""
import json
import math
import struct
import sys
import zlib
from pathlib import Path

VARIANTS = ["Natural", "Indigo"]


def cushion(n=16, size=0.45, height=0.14):
    """Top and bottom sheets of an n×n grid, puffed towards the middle, meeting at the seam; glTF +Y up."""
    positions, uvs, indices = [], [], []
    for sheet, sign in ((0, 1.0), (1, -1.0)):
        base = len(positions)
        for j in range(n + 1):
            for i in range(n + 1):
                s, t = i / n, j / n
                x, z = (s - 0.5) * size, (t - 0.5) * size
                puff = (1 - (2 * s - 1) ** 2) * (1 - (2 * t - 1) ** 2)
                positions.append((x, height * 0.5 + sign * 0.5 * height * puff ** 0.45, z))
                uvs.append((s, t if sheet == 0 else 1 - t))
        for j in range(n):
            for i in range(n):
                a, b = base + j * (n + 1) + i, base + j * (n + 1) + i + 1
                c, d = a + n + 1, b + n + 1
                # Both sheets face outwards: the bottom one is wound the other way.
                indices += [a, c, b, b, c, d] if sheet == 0 else [a, b, c, b, d, c]
    return positions, uvs, indices


def png(width, height, pixel):
    """An 8-bit RGB PNG; pixel(x, y) → (r, g, b)."""
    rows = b"".join(b"\0" + bytes(c for x in range(width) for c in pixel(x, y)) for y in range(height))

    def chunk(kind, data):
        return struct.pack(">I", len(data)) + kind + data + struct.pack(">I", zlib.crc32(kind + data))

    header = struct.pack(">IIBBBBB", width, height, 8, 2, 0, 0, 0)
    return b"\x89PNG\r\n\x1a\n" + chunk(b"IHDR", header) + chunk(b"IDAT", zlib.compress(rows)) + chunk(b"IEND", b"")


def main(out_dir, grid=16):
    out = Path(out_dir)
    out.mkdir(parents=True, exist_ok=True)
    positions, uvs, indices = cushion(grid)
    wide = len(positions) > 65535  # 32-bit indices past what 16 bits can name
    blob = b"".join(struct.pack("<3f", *p) for p in positions)
    uv_offset = len(blob)
    blob += b"".join(struct.pack("<2f", *uv) for uv in uvs)
    index_offset = len(blob)
    blob += b"".join(struct.pack("<I" if wide else "<H", i) for i in indices)
    while len(blob) % 4:
        blob += b"\0"
    (out / "cushion.bin").write_bytes(blob)
    # A soft two-tone stripe, light enough that each colourway's factor shows through.
    (out / "cushion_weave.png").write_bytes(
        png(16, 16, lambda x, y: (235, 230, 220) if (x // 4 + y // 4) % 2 else (200, 195, 185)))

    lo = [min(p[k] for p in positions) for k in range(3)]
    hi = [max(p[k] for p in positions) for k in range(3)]

    def material(name, colour):
        return {
            "name": name,
            "doubleSided": True,
            "pbrMetallicRoughness": {
                "baseColorFactor": colour + [1.0],
                "baseColorTexture": {
                    "index": 0,
                    "extensions": {"KHR_texture_transform": {"scale": [4.0, 4.0], "rotation": 0.1}},
                },
                "metallicFactor": 0.0,
                "roughnessFactor": 0.9,
            },
        }

    gltf = {
        "asset": {"version": "2.0", "generator": "Khronos glTF Blender I/O v3.6.28 (as written by make_product_gltf.py)"},
        "extensionsUsed": ["KHR_texture_transform", "KHR_materials_variants"],
        "extensions": {"KHR_materials_variants": {"variants": [{"name": v} for v in VARIANTS]}},
        "scene": 0,
        "scenes": [{"name": "Scene", "nodes": [0]}],
        "nodes": [{"name": "Cushion", "mesh": 0}],
        "meshes": [{
            "name": "Cushion",
            "primitives": [{
                "attributes": {"POSITION": 0, "TEXCOORD_0": 1},
                "indices": 2,
                "material": 0,
                "extensions": {"KHR_materials_variants": {"mappings": [
                    {"material": 0, "variants": [0]},
                    {"material": 1, "variants": [1]},
                ]}},
            }],
        }],
        "materials": [material("linen_plain.001", [0.9, 0.85, 0.75]), material("linen_plain.002", [0.12, 0.2, 0.55])],
        "textures": [{"sampler": 0, "source": 0}],
        "samplers": [{"magFilter": 9729, "minFilter": 9987}],
        "images": [{"name": "cushion_weave", "mimeType": "image/png", "uri": "cushion_weave.png"}],
        "accessors": [
            {"bufferView": 0, "componentType": 5126, "count": len(positions), "type": "VEC3", "min": lo, "max": hi},
            {"bufferView": 1, "componentType": 5126, "count": len(uvs), "type": "VEC2"},
            {"bufferView": 2, "componentType": 5125 if wide else 5123, "count": len(indices), "type": "SCALAR"},
        ],
        "bufferViews": [
            {"buffer": 0, "byteOffset": 0, "byteLength": uv_offset, "target": 34962},
            {"buffer": 0, "byteOffset": uv_offset, "byteLength": index_offset - uv_offset, "target": 34962},
            {"buffer": 0, "byteOffset": index_offset, "byteLength": (4 if wide else 2) * len(indices), "target": 34963},
        ],
        "buffers": [{"byteLength": len(blob), "uri": "cushion.bin"}],
    }
    (out / "cushion.gltf").write_text(json.dumps(gltf, indent=2))


if __name__ == "__main__":
    if len(sys.argv) == 2:
        main(sys.argv[1])
    elif len(sys.argv) == 4 and sys.argv[2] == "--grid" and sys.argv[3].isdigit() and int(sys.argv[3]) >= 1:
        main(sys.argv[1], int(sys.argv[3]))
    else:
        sys.exit(__doc__)
