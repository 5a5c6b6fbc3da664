#!/usr/bin/env python3
"""A product tool's glTF, end to end: make_product_gltf.py writes it, `weft bake` bakes it at the
coarsest settings, `weft bundle info --json` must list its object, fabric, both colourways and the
texture, and one headless frame per colourway must show the cloth in that colourway's colour.

Usage: product_gltf_round_trip_test.py WEFT ASSETS_DIR WORK_DIR   (Python 3 standard library only)
"""
import json
import os
import shutil
import struct
import subprocess
import sys
import zlib
from pathlib import Path

HERE = Path(__file__).resolve().parent
# As tests/support/small_bundle.h: the smallest tables, seconds of CPU.
COARSE = ["--table-grid", "4", "--lambda-levels", "2", "--tangent-samples", "1", "1", "--sdf-resolution", "8",
          "--floor-sdf-resolution", "8"]
FRAME = ["--display", "headless", "--turntable", "0", "--width", "96", "--height", "72", "--probe", "none"]


def run(args, env, log):
    r = subprocess.run(args, env=env, stdout=subprocess.PIPE, stderr=subprocess.STDOUT, text=True, timeout=600)
    Path(log).write_text(r.stdout)
    if r.returncode != 0:
        sys.exit(f"FAIL: {' '.join(map(str, args))} exited {r.returncode}:\n{r.stdout}")
    return r.stdout


def png_pixels(path):
    """8-bit RGB or RGBA PNG → list of (r, g, b) rows (the five PNG row filters undone)."""
    data = Path(path).read_bytes()
    pos, idat, width = 8, b"", 0
    while pos < len(data):
        length, kind = struct.unpack(">I4s", data[pos:pos + 8])
        body = data[pos + 8:pos + 8 + length]
        if kind == b"IHDR":
            width, height, depth, colour = struct.unpack(">IIBB", body[:10])
            assert depth == 8 and colour in (2, 6), f"{path}: unexpected PNG depth {depth} colour type {colour}"
            channels = 3 if colour == 2 else 4
        elif kind == b"IDAT":
            idat += body
        pos += 12 + length
    raw, stride, rows, prev = zlib.decompress(idat), width * channels, [], bytearray(width * channels)
    for y in range(height):
        kind, line = raw[y * (stride + 1)], bytearray(raw[y * (stride + 1) + 1:(y + 1) * (stride + 1)])
        for i in range(stride):
            a = line[i - channels] if i >= channels else 0
            b, c = prev[i], prev[i - channels] if i >= channels else 0
            if kind == 1:
                line[i] = (line[i] + a) & 255
            elif kind == 2:
                line[i] = (line[i] + b) & 255
            elif kind == 3:
                line[i] = (line[i] + (a + b) // 2) & 255
            elif kind == 4:
                p = a + b - c
                pa, pb, pc = abs(p - a), abs(p - b), abs(p - c)
                line[i] = (line[i] + (a if pa <= pb and pa <= pc else b if pb <= pc else c)) & 255
        rows.append([tuple(line[x * channels:x * channels + 3]) for x in range(width)])
        prev = line
    return rows


def main(weft, assets, work):
    work = Path(work)
    shutil.rmtree(work, ignore_errors=True)
    work.mkdir(parents=True)
    env = dict(os.environ, WEFT_ASSETS=str(assets))
    subprocess.run([sys.executable, str(HERE / "make_product_gltf.py"), str(work)], check=True)

    bundle = work / "cushion.weft"
    run([weft, "bake", "--scene", work / "cushion.gltf", *COARSE, "--out", bundle], env, work / "bake.log")
    info = json.loads(run([weft, "bundle", "info", "--json", bundle], env, work / "info.json"))
    objects = [o["name"] for o in info["objects"]]
    assert objects == ["linen_plain.001"], f"objects: {objects}"
    assert info["objects"][0]["fabric"] == "linen_plain", info["objects"][0]
    assert "linen_plain" in info["fabrics"], info["fabrics"]
    assert [c["name"] for c in info["colourways"]] == ["Natural", "Indigo"], info["colourways"]
    sections = [s["name"] for s in info["sections"]]
    assert any(s.startswith("texture/") for s in sections), f"no texture section in {sections}"

    # Natural: the first colourway, worn at boot. Indigo: one press of the colourway button, which
    # the state directory remembers; then the same single frame as Natural's.
    natural, indigo = work / "natural.png", work / "indigo.png"
    run([weft, "run", "--bundle", bundle, "--state-dir", work / "natural_state", *FRAME, "--panel", "none", "--frames",
         "1", "--screenshot", natural], env, work / "natural.log")
    (work / "panel.json").write_text('{"colourway_button": 3}')
    (work / "click.knobs").write_text("wait 5\nclick 3\nwait 10\n")
    state = work / "indigo_state"
    log = run([weft, "run", "--bundle", bundle, "--state-dir", state, *FRAME, "--panel", f"sim:{work / 'click.knobs'}",
               "--panel-config", work / "panel.json", "--frames", "30"], env, work / "click.log")
    assert "wearing colourway 'Indigo'" in log, log
    run([weft, "run", "--bundle", bundle, "--state-dir", state, *FRAME, "--panel", "none", "--frames", "1",
         "--screenshot", indigo], env, work / "indigo.log")

    a, b = png_pixels(natural), png_pixels(indigo)
    changed = [(p, q) for ra, rb in zip(a, b) for p, q in zip(ra, rb) if p != q]
    assert len(changed) > 0.02 * len(a) * len(a[0]), f"only {len(changed)} pixels differ between the colourways"
    # Where they differ (the cushion), Indigo is bluer than Natural relative to its red.
    blue_share = lambda px: sum(p[2] for p in px) / max(1, sum(p[0] + p[1] + p[2] for p in px))
    natural_blue, indigo_blue = blue_share([p for p, _ in changed]), blue_share([q for _, q in changed])
    assert indigo_blue > natural_blue + 0.05, f"blue share: Natural {natural_blue:.3f}, Indigo {indigo_blue:.3f}"
    print(f"ok: {len(changed)} pixels differ; blue share Natural {natural_blue:.3f}, Indigo {indigo_blue:.3f}")


if __name__ == "__main__":
    if len(sys.argv) != 4:
        sys.exit(__doc__)
    main(*sys.argv[1:])
