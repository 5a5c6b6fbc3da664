#!/usr/bin/env python3
"""A product file whose fabric has neither UVs nor tangents (a sheen cushion exported without a
UV map): `weft bake` takes it as cloth with a fixed warp and says there is no weave, and `weft run`
shows it all the way zoomed in (where the weave layer would draw) instead of stopping.

Usage: no_uv_cloth_test.py WEFT ASSETS_DIR WORK_DIR   (Python 3 standard library only)
"""
import json
import os
import shutil
import struct
import sys
from pathlib import Path

sys.path.insert(0, str(Path(__file__).resolve().parent))
from make_product_gltf import cushion  # noqa: E402
from product_gltf_round_trip_test import COARSE, FRAME, png_pixels, run  # noqa: E402


def main(weft, assets, work):
    work = Path(work)
    shutil.rmtree(work, ignore_errors=True)
    work.mkdir(parents=True)
    env = dict(os.environ, WEFT_ASSETS=str(assets))
    positions, _, indices = cushion()
    blob = b"".join(struct.pack("<3f", *p) for p in positions)
    index_offset = len(blob)
    blob += b"".join(struct.pack("<H", i) for i in indices)
    (work / "cushion.bin").write_bytes(blob)
    lo = [min(p[k] for p in positions) for k in range(3)]
    hi = [max(p[k] for p in positions) for k in range(3)]
    gltf = {
        "asset": {"version": "2.0"},
        "extensionsUsed": ["KHR_materials_sheen"],
        "scene": 0,
        "scenes": [{"nodes": [0]}],
        "nodes": [{"name": "Cushion", "mesh": 0}],
        "meshes": [{"primitives": [{"attributes": {"POSITION": 0}, "indices": 1, "material": 0}]}],
        "materials": [{
            "name": "Fabric_Velvet.001",
            "pbrMetallicRoughness": {"baseColorFactor": [0.5, 0.1, 0.1, 1.0], "roughnessFactor": 0.8},
            "extensions": {"KHR_materials_sheen": {"sheenColorFactor": [0.9, 0.3, 0.3], "sheenRoughnessFactor": 0.4}},
        }],
        "accessors": [
            {"bufferView": 0, "componentType": 5126, "count": len(positions), "type": "VEC3", "min": lo, "max": hi},
            {"bufferView": 1, "componentType": 5123, "count": len(indices), "type": "SCALAR"},
        ],
        "bufferViews": [
            {"buffer": 0, "byteOffset": 0, "byteLength": index_offset},
            {"buffer": 0, "byteOffset": index_offset, "byteLength": 2 * len(indices)},
        ],
        "buffers": [{"byteLength": len(blob), "uri": "cushion.bin"}],
    }
    (work / "cushion.gltf").write_text(json.dumps(gltf))

    bundle = work / "cushion.weft"
    bake_log = run([weft, "bake", "--scene", work / "cushion.gltf", *COARSE, "--out", bundle], env, work / "bake.log")
    assert "no weave" in bake_log, f"the bake does not say the cloth without UVs gets no weave:\n{bake_log}"
    shot = work / "zoomed.png"
    run([weft, "run", "--bundle", bundle, "--state-dir", work / "state", "--panel", "none", "--frames", "2", "--zoom", "1",
         *FRAME, "--screenshot", shot], env, work / "run.log")
    rows = png_pixels(shot)
    lit = sum(1 for row in rows for p in row if max(p) > 8)
    assert lit > len(rows) * len(rows[0]) // 10, f"the zoomed frame shows almost nothing: {lit} lit pixels"
    print(f"PASS: the cushion without UVs baked as cloth and drawn zoomed in ({lit} lit pixels)")


if __name__ == "__main__":
    if len(sys.argv) != 4:
        sys.exit(__doc__)
    main(*sys.argv[1:])
