#!/usr/bin/env python3
"""The content bench: product files as a customer's pipeline exports them, each baked and shown
the way it would arrive (default flags, no hand tuning), one row per file and rung.

Usage: content_bench.py OUT_DIR [--build DIR] [--size small|full] [--files F,F,...] [--no-reference]
                        [--frames N] [--readme PATH] [--only PRODUCT,...]
                        [--reference-supersample N]

  For each file (default: the corpus tests/scene/make_corpus.py writes, at --size, plus Debian's
  assimp-testmodels glTF 2.0 samples that are installed):
    weft bake                 time, bundle MB, peak memory
    weft run (auto, sheen)    first frame, median ms a frame (640×480 headless, --profile cpu)
    filament_peer --speed-only   Filament's frame on the same file and map (needs Xvfb)
    weft render --method reference (320×240; 2×2 rays a pixel where a material has a normal map)
                              against each rung's frame (frame_compare):
                              relative RMSE over the product's pixels, worst 32×32 block of fine
                              detail over the reference's (an artefact past 2×)
  Writes OUT_DIR/results.csv and OUT_DIR/README.md (or --readme), logs under OUT_DIR/logs.
Python 3 standard library only. Not a test: long (minutes per file), run by hand.
"""
import argparse
import csv
import json
import os
import re
import shutil
import subprocess
import sys
import time
from pathlib import Path

SOURCE = Path(__file__).resolve().parents[2]
ASSIMP = Path("/usr/share/assimp/models/glTF2")
ASSIMP_FILES = ["BoxTextured-glTF-Binary/BoxTextured.glb", "draco/2CylinderEngine.gltf"]
COLUMNS = ["file", "rung", "vertices", "bake_s", "bundle_mb", "bake_peak_mb", "first_frame_ms", "kiosk_ms",
           "filament_ms", "kiosk_over_filament", "relative_rmse", "detail_worst", "detail_blocks_over"]


def run(cmd, log, env=None, timeout=3600):
    """Runs cmd, its output into log; returns (exit code, output, seconds)."""
    start = time.monotonic()
    with open(log, "w") as f:
        p = subprocess.run(cmd, stdout=subprocess.PIPE, stderr=subprocess.STDOUT, text=True, env=env, timeout=timeout)
        f.write(" ".join(str(c) for c in cmd) + "\n" + p.stdout)
    return p.returncode, p.stdout, time.monotonic() - start


def kiosk(weft, bundle, method, frames, logs, tag):
    """weft run headless: (rung drawn, first frame ms, median ms a frame) or Nones."""
    state = logs / f"{tag}_state"
    shutil.rmtree(state, ignore_errors=True)
    cmd = [weft, "run", "--bundle", bundle, "--display", "headless", "--frames", str(frames), "--profile", "cpu",
           "--panel", "none", "--state-dir", state, "--stats-every", "0", "--method", method]
    code, out, _ = run(cmd, logs / f"{tag}.log")
    first = re.search(r"first frame after (\d+) ms \(\d+x\d+, [^,]+, ([a-z_]+)", out)
    median = re.search(r"median ([\d.]+) ms/frame", out)
    if code != 0 or not first or not median:
        return None, None, None
    return first.group(2), float(first.group(1)), float(median.group(1))


def vertices_of(info):
    """The bundle's vertex count from `weft bundle info`'s text, or None."""
    m = re.findall(r"(\d+) vertices", info)
    return sum(int(v) for v in m) if m else None


def bench_file(path, args, tools, out):
    name = Path(path).stem if Path(path).parent.name in ("", ".") else f"{Path(path).parent.name}/{Path(path).stem}"
    tag = re.sub(r"[^A-Za-z0-9_]+", "_", name)
    logs = out / "logs"
    bundle = out / "bundles" / f"{tag}.weft"
    print(f"content_bench: {name}: bake", file=sys.stderr, flush=True)
    code, text, bake_s = run(["/usr/bin/time", "-f", "peak_kib %M", tools["weft"], "bake", "--scene", path,
                              "--out", bundle], logs / f"{tag}_bake.log")
    base = {"file": name, "vertices": None, "bake_s": None, "bundle_mb": None, "bake_peak_mb": None}
    if code != 0:
        print(f"content_bench: {name}: bake failed (logs/{tag}_bake.log)", file=sys.stderr)
        return [dict(base, rung="bake failed")]
    peak = re.search(r"peak_kib (\d+)", text)
    _, info, _ = run([tools["weft"], "bundle", "info", bundle], logs / f"{tag}_info.log")
    base.update(bake_s=round(bake_s, 1), bundle_mb=round(bundle.stat().st_size / 1e6, 2),
                bake_peak_mb=round(int(peak.group(1)) / 1024) if peak else None, vertices=vertices_of(info))

    filament_ms, filament_frame = None, None
    if tools.get("filament"):
        fdir = out / "filament" / tag
        code, ftext, _ = run([tools["run_peer"], tools["filament"], "--speed-only", "--scenes", path, "--speed-width", "640",
                              "--speed-height", "480", "--speed-frames", "20", "--width", "320", "--height", "240",
                              "--out", fdir], logs / f"{tag}_filament.log")
        speed = fdir / "speed.csv"
        if code == 0 and speed.exists():
            rows = list(csv.DictReader(open(speed)))
            if rows:
                filament_ms, filament_frame = float(rows[0]["ms"]), fdir / rows[0]["image"]

    reference = None
    if not args.no_reference:
        print(f"content_bench: {name}: reference", file=sys.stderr, flush=True)
        reference = out / "frames" / f"{tag}_reference.exr"
        ss = args.reference_supersample or (2 if has_normal_map(path) else 1)
        code, _, _ = run([tools["offline"], "render", "--scene", path, "--method", "reference", "--width", "320",
                          "--height", "240", "--supersample", str(ss), "--out", reference], logs / f"{tag}_reference.log")
        if code != 0:
            reference = None

    rows = []
    for method in ("auto", "sheen"):
        print(f"content_bench: {name}: kiosk {method}", file=sys.stderr, flush=True)
        rung, first_ms, ms = kiosk(tools["weft"], bundle, method, args.frames, logs, f"{tag}_{method}")
        row = dict(base, rung=rung or f"{method} (no frame)", first_frame_ms=first_ms, kiosk_ms=ms, filament_ms=filament_ms)
        if ms and filament_ms:
            row["kiosk_over_filament"] = round(ms / filament_ms, 2)
        if reference and rung:
            frame = out / "frames" / f"{tag}_{rung}.exr"
            render = [tools["offline"], "render", "--scene", path, "--method", rung, "--backdrop", "measure",
                      "--width", "320", "--height", "240", "--frames", "1", "--out", frame]
            # The bundle's tables where the rung reads them (weft render refuses them otherwise).
            code, text, _ = run(render + ["--bundle", bundle], logs / f"{tag}_{rung}_render.log")
            if code != 0 and "--bundle: only with" in text:
                code, _, _ = run(render, logs / f"{tag}_{rung}_render.log")
            if code == 0:
                code, text, _ = run([tools["compare"], frame, reference], logs / f"{tag}_{rung}_compare.log")
                if code == 0:
                    m = json.loads(text.strip().splitlines()[-1])
                    row.update(relative_rmse=round(m["relative_rmse"], 4), detail_worst=round(m["detail_worst"], 2),
                               detail_blocks_over=m["detail_blocks_over"])
        rows.append(row)
    return rows


def cell(v):
    return "—" if v is None or v == "" else str(v)


def write_readme(path, rows, command, machine):
    lines = [
        "# Content bench: product files as they arrive",
        "",
        "Generated by `tests/bench/content_bench.py` (its docstring says what each column measures). "
        "Every file baked and shown with default flags; 640×480 headless kiosk frames (median), "
        "Filament 1.9 drawing the same triangles under the same map (`filament_peer --speed-only`), "
        "error and fine-detail artefact measure against the reference at 320×240, 2×2 rays a pixel where a "
        "material has a normal map (`frame_compare`: "
        "relative RMSE over the product's pixels; worst 32×32 block's fine detail over the reference's, "
        "an artefact past 2×).",
        "",
        f"Machine: {machine}. Regenerate: `{command}` (`--size small` for a quick pass, "
        "`--no-reference` without the reference renders). The files: `tests/scene/make_corpus.py` "
        "(its docstring describes each product) and Debian's assimp-testmodels glTF 2.0 samples. "
        "`findings.md` here says what the rows show and what limits them; `dense_cushion.md` compares "
        "every vertex against the pass subset on one dense export.",
        "",
        "| file | rung | vertices | bake s | MB | bake peak MB | first frame ms | kiosk ms | Filament ms | × Filament | "
        "error | detail worst | blocks > 2× |",
        "|---|---|---|---|---|---|---|---|---|---|---|---|---|",
    ]
    for r in rows:
        lines.append("| " + " | ".join(cell(r.get(c)) for c in COLUMNS) + " |")
    Path(path).write_text("\n".join(lines) + "\n")


def has_normal_map(path):
    """Whether a glTF file's materials carry a normal map (one sample a pixel aliases its bumps)."""
    path = Path(path)
    try:
        if path.suffix == ".gltf":
            doc = json.loads(path.read_text())
        elif path.suffix == ".glb":
            data = path.read_bytes()
            doc = json.loads(data[20:20 + int.from_bytes(data[12:16], "little")])
        else:
            return False
    except (OSError, ValueError):
        return False
    return any("normalTexture" in m for m in doc.get("materials", []))


def main():
    p = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    p.add_argument("out")
    p.add_argument("--build", default=str(SOURCE / "build"))
    p.add_argument("--size", choices=["small", "full"], default="full")
    p.add_argument("--files", help="comma-separated glTF/scene files instead of the corpus")
    p.add_argument("--no-reference", action="store_true", help="skip the reference, the error and the artefact measure")
    p.add_argument("--reference-supersample", type=int, default=0,
                   help="the reference's rays a pixel along each axis (default 2 where a material has a normal map, "
                   "whose bumps one ray a pixel aliases, else 1)")
    p.add_argument("--frames", type=int, default=40, help="kiosk frames a run")
    p.add_argument("--readme", help="where the table goes (default OUT/README.md)")
    p.add_argument("--only", help="comma-separated corpus products (e.g. chair,sofa) to run again; "
                   "the other files' rows of OUT/results.csv are kept")
    args = p.parse_args()
    out = Path(args.out).resolve()
    build = Path(args.build).resolve()
    for d in ("logs", "bundles", "frames", "filament"):
        (out / d).mkdir(parents=True, exist_ok=True)
    tools = {"weft": build / "render/app/weft", "offline": build / "render/app/weft-offline",
             "compare": build / "tests/bench/frame_compare", "run_peer": SOURCE / "tests/bench/filament_peer/run_peer.sh"}
    for k, t in tools.items():
        if not Path(t).exists():
            sys.exit(f"content_bench: {t} missing (build the project: cmake --build {build})")
    peer = build / "tests/bench/filament_peer/filament_peer"
    if peer.exists():
        tools["filament"] = peer
    else:
        print("content_bench: no filament_peer (libfilament-dev not installed): no Filament column", file=sys.stderr)

    if args.files:
        files = args.files.split(",")
    else:
        corpus = out / "corpus"
        compress = build / "tests/scene/gltf_compress"
        cmd = [sys.executable, SOURCE / "tests/scene/make_corpus.py", corpus, "--size", args.size]
        if compress.exists():
            cmd += ["--compress-tool", compress]
        subprocess.run(cmd, check=True)
        files = sorted(str(f) for f in corpus.glob("*/*.gltf"))
        files += [str(ASSIMP / f) for f in ASSIMP_FILES if (ASSIMP / f).exists()]

    rows, kept = [], []
    if args.only:
        wanted = set(args.only.split(","))
        files = [f for f in files if Path(f).parent.name in wanted]
        if (out / "results.csv").exists():
            kept = [r for r in csv.DictReader(open(out / "results.csv")) if r["file"].split("/")[0] not in wanted]
    for f in files:
        rows += bench_file(f, args, tools, out)
        with open(out / "results.csv", "w", newline="") as c:
            w = csv.DictWriter(c, fieldnames=COLUMNS, extrasaction="ignore")
            w.writeheader()
            w.writerows(sorted(kept + rows, key=lambda r: r["file"]))
    rows = sorted(kept + rows, key=lambda r: r["file"])
    machine = f"{os.cpu_count()} cores, " + (subprocess.run(["uname", "-m"], capture_output=True, text=True).stdout.strip())
    # The command that regenerates the whole table (an --only rerun keeps the other rows).
    argv = sys.argv[2:]
    if "--only" in argv:
        i = argv.index("--only")
        argv = argv[:i] + argv[i + 2:]
    command = "tests/bench/content_bench.py OUT " + " ".join(a for a in argv if not a.startswith("/"))
    write_readme(args.readme or out / "README.md", rows, command.strip(), machine)
    print(f"content_bench: wrote {args.readme or out / 'README.md'}", file=sys.stderr)


if __name__ == "__main__":
    main()
