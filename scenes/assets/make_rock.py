#!/usr/bin/env python3
"""Writes rock.gltf: a low-poly rock for scenes/lake.json (glTF 2.0, one embedded base64 buffer).

An icosahedron subdivided once (80 triangles), each vertex pushed in or out along its radius
by a fixed pseudo-random amount and the whole squashed vertically, flat shaded (3 vertices
per triangle, each with the face normal). About 0.9 m across and 0.7 m tall, centred on the
origin; the scene's transform places it.
Run: python3 scenes/assets/make_rock.py  (deterministic: the output never changes)
"""
import base64
import json
import math
import random
import struct
from pathlib import Path

random.seed(7)
t = (1.0 + math.sqrt(5.0)) / 2.0
ico = [(-1, t, 0), (1, t, 0), (-1, -t, 0), (1, -t, 0), (0, -1, t), (0, 1, t),
       (0, -1, -t), (0, 1, -t), (t, 0, -1), (t, 0, 1), (-t, 0, -1), (-t, 0, 1)]
faces = [(0, 11, 5), (0, 5, 1), (0, 1, 7), (0, 7, 10), (0, 10, 11), (1, 5, 9), (5, 11, 4),
         (11, 10, 2), (10, 7, 6), (7, 1, 8), (3, 9, 4), (3, 4, 2), (3, 2, 6), (3, 6, 8),
         (3, 8, 9), (4, 9, 5), (2, 4, 11), (6, 2, 10), (8, 6, 7), (9, 8, 1)]
verts = [tuple(c / math.sqrt(1 + t * t) for c in v) for v in ico]
midpoints = {}


# The stone's albedo: (0.45, 0.4, 0.35) squared, in double precision. The renderers once applied
# a glTF base colour twice, and lake's committed references were made that way; the file now says
# what they show, so the references still hold bit for bit.
STONE = [0.45 * 0.45, 0.4 * 0.4, 0.35 * 0.35]

def midpoint(a, b):
    key = (min(a, b), max(a, b))
    if key not in midpoints:
        m = [(verts[a][i] + verts[b][i]) / 2 for i in range(3)]
        n = math.sqrt(sum(c * c for c in m))
        verts.append(tuple(c / n for c in m))
        midpoints[key] = len(verts) - 1
    return midpoints[key]


subdivided = []
for a, b, c in faces:
    ab, bc, ca = midpoint(a, b), midpoint(b, c), midpoint(c, a)
    subdivided += [(a, ab, ca), (b, bc, ab), (c, ca, bc), (ab, bc, ca)]

shaped = []
for v in verts:
    r = 0.5 * (0.85 + 0.3 * random.random())
    shaped.append((v[0] * r, v[1] * r * 0.7, v[2] * r))


def sub(p, q):
    return [p[i] - q[i] for i in range(3)]


def cross(u, v):
    return [u[1] * v[2] - u[2] * v[1], u[2] * v[0] - u[0] * v[2], u[0] * v[1] - u[1] * v[0]]


positions, normals = [], []
for a, b, c in subdivided:
    pa, pb, pc = shaped[a], shaped[b], shaped[c]
    n = cross(sub(pb, pa), sub(pc, pa))
    length = math.sqrt(sum(x * x for x in n))
    n = [x / length for x in n]
    for p in (pa, pb, pc):
        positions.append(p)
        normals.append(n)

# Round through float32 so that the accessor's min/max equal the stored values exactly.
positions = [tuple(struct.unpack("<3f", struct.pack("<3f", *p))) for p in positions]
count = len(positions)
indices = list(range(count))
data = b"".join(struct.pack("<3f", *p) for p in positions)
data += b"".join(struct.pack("<3f", *n) for n in normals)
index_offset = len(data)
data += b"".join(struct.pack("<H", i) for i in indices)
while len(data) % 4:
    data += b"\0"

gltf = {
    "asset": {"version": "2.0", "generator": "scenes/assets/make_rock.py"},
    "scene": 0,
    "scenes": [{"nodes": [0]}],
    "nodes": [{"name": "Rock", "mesh": 0}],
    "meshes": [{"name": "Rock", "primitives": [{
        "attributes": {"POSITION": 0, "NORMAL": 1}, "indices": 2, "material": 0, "mode": 4}]}],
    "materials": [{"name": "Stone", "pbrMetallicRoughness": {
        "baseColorFactor": STONE + [1.0], "metallicFactor": 0.0, "roughnessFactor": 1.0}}],
    "accessors": [
        {"bufferView": 0, "componentType": 5126, "count": count, "type": "VEC3",
         "min": [min(p[i] for p in positions) for i in range(3)],
         "max": [max(p[i] for p in positions) for i in range(3)]},
        {"bufferView": 0, "byteOffset": 12 * count, "componentType": 5126, "count": count, "type": "VEC3"},
        {"bufferView": 1, "componentType": 5123, "count": count, "type": "SCALAR"},
    ],
    "bufferViews": [
        {"buffer": 0, "byteOffset": 0, "byteLength": 24 * count, "target": 34962},
        {"buffer": 0, "byteOffset": index_offset, "byteLength": 2 * count, "target": 34963},
    ],
    "buffers": [{"byteLength": len(data),
                 "uri": "data:application/octet-stream;base64," + base64.b64encode(data).decode()}],
}
Path(__file__).with_name("rock.gltf").write_text(json.dumps(gltf, indent=1) + "\n")
