#!/usr/bin/env python3
"""Writes armchair.gltf: the default showroom's armchair (linen body, satin cushions) on a floor.

Run from this folder: python3 make_armchair.py  (standard library only; the output is
deterministic). Every part is a rounded box: a cube's six faces as grids, each grid point
pushed onto a box of the given half sizes whose edges are rounded with radius r; cushions
also puff out along their normals. Each face has its own UVs in metres (u along the face's
first axis), so the warp comes from TEXCOORD_0 (no TANGENT). Normals are area-weighted over
vertices welded by position, so the face seams shade smoothly. Coordinates are glTF's:
+Y up, metres, the chair facing +Z (the camera's side).
"""
import base64
import json
import math
import struct

FACES = [  # (normal axis, sign, first in-face axis, second in-face axis)
    (0, 1, 2, 1), (0, -1, 2, 1), (1, 1, 0, 2), (1, -1, 0, 2), (2, 1, 0, 1), (2, -1, 0, 1)]


def face_coords(half, r, n_flat, n_round):
    """Grid coordinates along one axis: n_round cells over each rounded band, n_flat between."""
    inner = half - r
    out = [-half + r * (i / n_round) for i in range(n_round)]
    out += [-inner + 2 * inner * (i / n_flat) for i in range(n_flat)]
    out += [inner + r * (i / n_round) for i in range(n_round + 1)]
    return out


def rounded_box(center, half, r, puff=0.0, n_flat=6, n_round=2, skip=()):
    """Vertices (position, uv) and triangles of a rounded box; faces in `skip` are left out."""
    pos, uv, tri = [], [], []
    for f, (a, s, b, c) in enumerate(FACES):
        if f in skip:
            continue
        cb = face_coords(half[b], r, n_flat, n_round)
        cc = face_coords(half[c], r, n_flat, n_round)
        base = len(pos)
        for j, y in enumerate(cc):
            for i, x in enumerate(cb):
                p = [0.0, 0.0, 0.0]
                p[a], p[b], p[c] = s * half[a], x, y
                inner = [max(-(h - r), min(h - r, q)) for q, h in zip(p, half)]
                d = [q - w for q, w in zip(p, inner)]
                ln = math.sqrt(sum(t * t for t in d)) or 1.0
                nrm = [t / ln for t in d]
                bulge = puff * max(0.0, 1 - (x / half[b]) ** 2) * max(0.0, 1 - (y / half[c]) ** 2)
                q = [w + (r + bulge) * t + o for w, t, o in zip(inner, nrm, center)]
                pos.append(q)
                uv.append((x * s, y))  # metres along the face: u mirrored on the −side keeps warps parallel
        w = len(cb)
        for j in range(len(cc) - 1):
            for i in range(w - 1):
                v0 = base + j * w + i
                quad = (v0, v0 + 1, v0 + w + 1, v0 + w)
                t1, t2 = (quad[0], quad[1], quad[2]), (quad[0], quad[2], quad[3])
                # Counter-clockwise seen from outside: flip where the face's axes are left-handed.
                e = [[0] * 3 for _ in range(2)]
                e[0][b], e[1][c] = 1, 1
                cross = [e[0][1] * e[1][2] - e[0][2] * e[1][1], e[0][2] * e[1][0] - e[0][0] * e[1][2],
                         e[0][0] * e[1][1] - e[0][1] * e[1][0]]
                if cross[a] * s < 0:
                    t1, t2 = (t1[0], t1[2], t1[1]), (t2[0], t2[2], t2[1])
                tri += [t1, t2]
    return pos, uv, tri


def merge(parts):
    pos, uv, tri = [], [], []
    for p, u, t in parts:
        o = len(pos)
        pos += p
        uv += u
        tri += [(a + o, b + o, c + o) for a, b, c in t]
    return pos, uv, tri


def smooth_normals(pos, tri):
    key = lambda p: tuple(round(c, 5) for c in p)
    acc = {}
    for a, b, c in tri:
        pa, pb, pc = pos[a], pos[b], pos[c]
        u = [pb[i] - pa[i] for i in range(3)]
        v = [pc[i] - pa[i] for i in range(3)]
        n = [u[1] * v[2] - u[2] * v[1], u[2] * v[0] - u[0] * v[2], u[0] * v[1] - u[1] * v[0]]
        for k in (a, b, c):
            s = acc.setdefault(key(pos[k]), [0.0, 0.0, 0.0])
            for i in range(3):
                s[i] += n[i]
    out = []
    for p in pos:
        s = acc[key(p)]
        ln = math.sqrt(sum(t * t for t in s)) or 1.0
        out.append([t / ln for t in s])
    return out


def floor_coords():
    """Fine 0.15 m cells over ±1.2 m (contact shadows), then cells growing ×1.45 out to ±15 m."""
    c = [-1.2 + 0.15 * i for i in range(17)]
    step, x = 0.15, 1.2
    while x < 15.0:
        step *= 1.45
        x = min(15.0, x + step)
        c = [-x] + c + [x]
    return c


def floor():
    c = floor_coords()
    pos = [[x, 0.0, z] for z in c for x in c]
    w = len(c)
    tri = []
    for j in range(w - 1):
        for i in range(w - 1):
            v0 = j * w + i
            tri += [(v0, v0 + w, v0 + w + 1), (v0, v0 + w + 1, v0 + 1)]
    return pos, [[0.0, 1.0, 0.0]] * len(pos), tri


# The chair (metres): seat 0.42 high, arms 0.62, back 0.86; 0.9 wide, 0.82 deep.
body = merge([
    rounded_box((0.0, 0.21, 0.0), (0.45, 0.21, 0.41), 0.05, skip=(3,)),           # base, open below
    rounded_box((-0.375, 0.31, 0.0), (0.075, 0.31, 0.41), 0.05, skip=(3,)),       # left arm
    rounded_box((0.375, 0.31, 0.0), (0.075, 0.31, 0.41), 0.05, skip=(3,)),        # right arm
    rounded_box((0.0, 0.43, -0.33), (0.30, 0.43, 0.08), 0.05, skip=(3,)),         # back
])


def tilt(part, angle_deg, pivot):
    """Leans a part back: rotation about the x axis through `pivot`."""
    pos, uv, tri = part
    a = math.radians(angle_deg)
    ca, sa = math.cos(a), math.sin(a)
    out = []
    for x, y, z in pos:
        y0, z0 = y - pivot[1], z - pivot[2]
        out.append([x, pivot[1] + ca * y0 + sa * z0, pivot[2] - sa * y0 + ca * z0])
    return out, uv, tri


seat = rounded_box((0.0, 0.49, 0.06), (0.295, 0.07, 0.33), 0.05, puff=0.025)
back = tilt(rounded_box((0.0, 0.74, -0.20), (0.29, 0.19, 0.06), 0.05, puff=0.02), 10.0, (0.0, 0.56, -0.20))
cushions = merge([seat, back])

meshes = [("chair_body", body), ("chair_cushions", cushions)]
buf = bytearray()
views, accessors, gl_meshes, nodes = [], [], [], []


def add(data, fmt, comp, typ, count, target, minmax=None):
    while len(buf) % 4:
        buf.append(0)
    off = len(buf)
    buf.extend(struct.pack("<" + fmt * (len(data)), *data))
    views.append({"buffer": 0, "byteOffset": off, "byteLength": len(buf) - off, "target": target})
    acc = {"bufferView": len(views) - 1, "componentType": comp, "count": count, "type": typ}
    if minmax:
        acc["min"], acc["max"] = minmax
    accessors.append(acc)
    return len(accessors) - 1


def add_mesh(name, pos, nrm, uv, tri, material):
    flat = [c for p in pos for c in p]
    mm = ([min(p[i] for p in pos) for i in range(3)], [max(p[i] for p in pos) for i in range(3)])
    attrs = {"POSITION": add(flat, "f", 5126, "VEC3", len(pos), 34962, mm),
             "NORMAL": add([c for n in nrm for c in n], "f", 5126, "VEC3", len(nrm), 34962)}
    if uv is not None:
        attrs["TEXCOORD_0"] = add([c for t in uv for c in t], "f", 5126, "VEC2", len(uv), 34962)
    idx = add([i for t in tri for i in t], "I", 5125, "SCALAR", 3 * len(tri), 34963)
    gl_meshes.append({"name": name, "primitives": [{"attributes": attrs, "indices": idx, "material": material}]})
    nodes.append({"name": name, "mesh": len(gl_meshes) - 1})


for m, (name, (pos, uv, tri)) in enumerate(meshes):
    add_mesh(name, pos, smooth_normals(pos, tri), uv, tri, m)
fp, fn, ft = floor()
add_mesh("floor", fp, fn, None, ft, 2)

# The camera: 2.6 m in front and to the right, 1.2 m up, looking at the seat.
eye, target = (1.25, 1.15, 2.3), (0.0, 0.42, 0.0)
f = [t - e for t, e in zip(target, eye)]
ln = math.sqrt(sum(c * c for c in f))
f = [c / ln for c in f]
# Quaternion turning the camera's −Z onto f with +Y staying up (yaw, then pitch).
yaw = math.atan2(-f[0], -f[2])
pitch = math.asin(f[1])
cy, sy, cp, sp = math.cos(yaw / 2), math.sin(yaw / 2), math.cos(pitch / 2), math.sin(pitch / 2)
rotation = [cy * sp, sy * cp, -sy * sp, cy * cp]  # q_yaw(Y) · q_pitch(X), as x, y, z, w
nodes.append({"name": "camera", "camera": 0, "translation": list(eye), "rotation": rotation})

gltf = {
    "asset": {"version": "2.0", "generator": "weft assets/scenes/make_armchair.py"},
    "scene": 0,
    "scenes": [{"nodes": list(range(len(nodes)))}],
    "nodes": nodes,
    "cameras": [{"type": "perspective", "perspective": {"yfov": math.radians(30.0), "aspectRatio": 4 / 3,
                                                         "znear": 0.05, "zfar": 100.0}}],
    "materials": [
        {"name": "chair_body", "extras": {"weft": {"fabric": "linen_plain"}}},
        {"name": "chair_cushions", "extras": {"weft": {"fabric": "polyester_satin_charmeuse"}}},
        {"name": "floor", "pbrMetallicRoughness": {"baseColorFactor": [0.62, 0.6, 0.57, 1.0]}},
    ],
    "meshes": gl_meshes,
    "accessors": accessors,
    "bufferViews": views,
    "buffers": [{"byteLength": len(buf),
                 "uri": "data:application/octet-stream;base64," + base64.b64encode(bytes(buf)).decode()}],
}
with open("armchair.gltf", "w") as out:
    json.dump(gltf, out, separators=(",", ":"))
print("armchair.gltf: %d body, %d cushion, %d floor vertices; %d bytes of buffer" %
      (len(body[0]), len(cushions[0]), len(fp), len(buf)))
