#!/usr/bin/python3
"""The kiosk VM test's pictures: takes QEMU screendumps and checks them against references.

  frames.py shot MONITOR_SOCKET OUT.ppm      screendump through QEMU's HMP monitor
  frames.py png IN.ppm OUT.png               PPM -> PNG (the artifacts)
  frames.py check REF_A.png REF_B.png VM_A.ppm VM_B.ppm LABEL
      REF_A/REF_B: the same bundle rendered headless on the host before/after the same knob
      turn. The cloth is where those two differ (the knobs only change the fabric). Checks that
      the VM's screen matches its reference before, that the cloth's colour changed on the VM
      as in the references, and that nothing outside the cloth changed.
  frames.py back SHOWN.ppm GONE.ppm BACK.ppm LABEL
      The display unplugged and plugged back: the screen while it was gone (SHOWN vs GONE)
      differs from the kiosk's picture, and the picture after (BACK) equals the one before.

Standard library only (Debian's python3): PPM P6 and 8-bit non-interlaced PNG (RGB/RGBA).
"""
import socket
import struct
import sys
import time
import zlib


def read_ppm(path):
    data = open(path, "rb").read()
    fields, pos = [], 0
    while len(fields) < 4:  # magic, width, height, maxval; '#' comments allowed
        while data[pos:pos + 1].isspace():
            pos += 1
        if data[pos:pos + 1] == b"#":
            pos = data.index(b"\n", pos) + 1
            continue
        end = pos
        while not data[end:end + 1].isspace():
            end += 1
        fields.append(data[pos:end])
        pos = end
    pos += 1
    if fields[0] != b"P6" or int(fields[3]) != 255:
        raise ValueError(f"{path}: not an 8-bit P6 PPM")
    w, h = int(fields[1]), int(fields[2])
    px = data[pos:pos + 3 * w * h]
    if len(px) != 3 * w * h:
        raise ValueError(f"{path}: truncated")
    return w, h, px


def read_png(path):
    data = open(path, "rb").read()
    if data[:8] != b"\x89PNG\r\n\x1a\n":
        raise ValueError(f"{path}: not a PNG")
    pos, idat, w = 8, b"", None
    while pos < len(data):
        n, kind = struct.unpack(">I4s", data[pos:pos + 8])
        body = data[pos + 8:pos + 8 + n]
        pos += 12 + n
        if kind == b"IHDR":
            w, h, depth, colour, _, _, interlace = struct.unpack(">IIBBBBB", body)
            if depth != 8 or colour not in (2, 6) or interlace:
                raise ValueError(f"{path}: only 8-bit RGB/RGBA non-interlaced PNGs")
            bpp = 3 if colour == 2 else 4
        elif kind == b"IDAT":
            idat += body
    raw, stride = zlib.decompress(idat), w * bpp
    out, prev = bytearray(), bytearray(stride)
    for y in range(h):
        f, line = raw[y * (stride + 1)], bytearray(raw[y * (stride + 1) + 1:(y + 1) * (stride + 1)])
        for i in range(stride):
            a = line[i - bpp] if i >= bpp else 0
            b, c = prev[i], prev[i - bpp] if i >= bpp else 0
            if f == 1:
                line[i] = (line[i] + a) & 255
            elif f == 2:
                line[i] = (line[i] + b) & 255
            elif f == 3:
                line[i] = (line[i] + (a + b) // 2) & 255
            elif f == 4:
                p = a + b - c
                pa, pb, pc = abs(p - a), abs(p - b), abs(p - c)
                line[i] = (line[i] + (a if pa <= pb and pa <= pc else b if pb <= pc else c)) & 255
        out += line if bpp == 3 else bytes(v for i, v in enumerate(line) if i % 4 != 3)
        prev = line
    return w, h, bytes(out)


def write_png(path, w, h, px):
    def chunk(kind, body):
        return struct.pack(">I", len(body)) + kind + body + struct.pack(">I", zlib.crc32(kind + body))
    raw = b"".join(b"\0" + px[y * 3 * w:(y + 1) * 3 * w] for y in range(h))
    with open(path, "wb") as f:
        f.write(b"\x89PNG\r\n\x1a\n" + chunk(b"IHDR", struct.pack(">IIBBBBB", w, h, 8, 2, 0, 0, 0))
                + chunk(b"IDAT", zlib.compress(raw, 6)) + chunk(b"IEND", b""))


def shot(sock_path, out_path, timeout=60):
    """HMP `screendump`; returns once the monitor prompt is back (the file is complete)."""
    s = socket.socket(socket.AF_UNIX, socket.SOCK_STREAM)
    s.settimeout(timeout)
    s.connect(sock_path)
    buf = b""
    while b"(qemu)" not in buf:
        buf += s.recv(4096)
    s.sendall(f"screendump {out_path}\n".encode())
    buf = b""
    while b"(qemu)" not in buf:
        buf += s.recv(4096)
    s.close()
    text = buf.decode(errors="replace")
    if "rror" in text:
        raise RuntimeError(f"screendump: {text.strip()}")


def load(path):
    return read_png(path) if path.endswith(".png") else read_ppm(path)


def check(ref_a_path, ref_b_path, vm_a_path, vm_b_path, label):
    ref_a, ref_b, vm_a, vm_b = (load(p) for p in (ref_a_path, ref_b_path, vm_a_path, vm_b_path))
    sizes = {(x[0], x[1]) for x in (ref_a, ref_b, vm_a, vm_b)}
    if len(sizes) != 1:
        print(f"{label}: FAIL: image sizes differ: {sizes}")
        return 1
    w, h = sizes.pop()
    ra, rb, va, vb = ref_a[2], ref_b[2], vm_a[2], vm_b[2]
    n = w * h
    # Cloth mask: where the references differ clearly (sum over RGB of |Δ| > 24 levels).
    mask = [sum(abs(ra[3 * i + c] - rb[3 * i + c]) for c in range(3)) > 24 for i in range(n)]
    inside = [i for i in range(n) if mask[i]]
    outside = [i for i in range(n) if not mask[i]]

    def mean(px, idx):
        return [sum(px[3 * i + c] for i in idx) / max(1, len(idx)) for c in range(3)]

    def mad(p, q, idx):  # mean absolute difference per channel, averaged over channels
        return sum(abs(p[3 * i + c] - q[3 * i + c]) for i in idx for c in range(3)) / max(1, 3 * len(idx))

    fmt = lambda v: "(" + ", ".join(f"{x:.1f}" for x in v) + ")"
    frac = len(inside) / n
    vm_shift = [b - a for a, b in zip(mean(va, inside), mean(vb, inside))]
    ref_shift = [b - a for a, b in zip(mean(ra, inside), mean(rb, inside))]
    results = {
        "cloth pixels": f"{len(inside)} ({100 * frac:.1f}% of {w}x{h})",
        "VM before vs reference, whole frame (mean |d|)": f"{mad(va, ra, range(n)):.2f}",
        "VM after vs reference, whole frame (mean |d|)": f"{mad(vb, rb, range(n)):.2f}",
        "cloth mean RGB, VM before -> after": f"{fmt(mean(va, inside))} -> {fmt(mean(vb, inside))}",
        "cloth mean RGB, reference before -> after": f"{fmt(mean(ra, inside))} -> {fmt(mean(rb, inside))}",
        "cloth change on the VM (mean |d|)": f"{mad(va, vb, inside):.2f}",
        "outside the cloth, VM before vs after (mean |d|)": f"{mad(va, vb, outside):.2f}",
    }
    for k, v in results.items():
        print(f"{label}: {k}: {v}")
    problems = []
    if not 0.02 <= frac <= 0.9:
        problems.append(f"the references disagree on {100 * frac:.1f}% of the frame: no plausible cloth region")
    if mad(va, ra, range(n)) > 6:
        problems.append("the VM's screen before does not match the host's reference render")
    if mad(vb, rb, range(n)) > 6:
        problems.append("the VM's screen after does not match the host's reference render")
    if mad(va, vb, inside) < 8:
        problems.append("the cloth's colour did not change on the VM's screen")
    if any(r * v < 0 and abs(r) > 4 for r, v in zip(ref_shift, vm_shift)):
        problems.append(f"the cloth changed the wrong way: VM {fmt(vm_shift)}, reference {fmt(ref_shift)}")
    if mad(va, vb, outside) > 2:
        problems.append("the screen changed outside the cloth")
    for p in problems:
        print(f"{label}: FAIL: {p}")
    return 1 if problems else 0


def back(shown_path, gone_path, back_path, label):
    shown, gone, again = (load(p) for p in (shown_path, gone_path, back_path))
    if (shown[0], shown[1]) != (again[0], again[1]):
        print(f"{label}: FAIL: the screen came back at {again[0]}x{again[1]}, not {shown[0]}x{shown[1]}")
        return 1
    n = shown[0] * shown[1]
    mad = lambda p, q: sum(abs(a - b) for a, b in zip(p, q)) / (3 * n)
    gone_mad = mad(shown[2], gone[2]) if (gone[0], gone[1]) == (shown[0], shown[1]) else float("inf")
    back_mad = mad(shown[2], again[2])
    print(f"{label}: while unplugged vs before (mean |d|): {gone_mad:.2f} ({gone[0]}x{gone[1]})")
    print(f"{label}: after the replug vs before (mean |d|): {back_mad:.2f}")
    problems = []
    if gone_mad < 8:
        problems.append("the screen still showed the picture while the display was unplugged")
    if back_mad > 2:
        problems.append("the picture did not come back as it was")
    for p in problems:
        print(f"{label}: FAIL: {p}")
    return 1 if problems else 0


def main(argv):
    if len(argv) >= 2 and argv[1] in ("-h", "--help"):
        print(__doc__)
        return 0
    try:
        if len(argv) == 4 and argv[1] == "shot":
            shot(argv[2], argv[3])
            return 0
        if len(argv) == 4 and argv[1] == "png":
            write_png(argv[3], *read_ppm(argv[2]))
            return 0
        if len(argv) == 7 and argv[1] == "check":
            return check(*argv[2:7])
        if len(argv) == 6 and argv[1] == "back":
            return back(*argv[2:6])
    except (OSError, ValueError, RuntimeError) as e:
        print(f"frames.py: {e}", file=sys.stderr)
        return 1
    print(__doc__, file=sys.stderr)
    return 2


if __name__ == "__main__":
    sys.exit(main(sys.argv))
