#!/usr/bin/env python3
"""Writes the showcase swimming pool's shell: pool.gltf (glTF 2.0, one embedded base64 buffer) and
its tile texture tiles.png, for scenes/showcase/pool.json.

The pool is 8 m square inside (x and z from -4 to 4) and 1.6 m deep (the water's mean level at 0),
with walls up to the deck at y = 0.25 and a deck around it. Its floor is the scene's own floor, whose
tiles (floor.tiles) both renderers evaluate exactly, also through the water. The walls and steps are
tiled alike: 25 cm tiles with a dark grout line, pale blue, the texture repeated
by the sampler (its wrap mode REPEAT) from texture coordinates in metres divided by the
texture's size (1 m: 4 x 4 tiles). Three steps along the left wall by the near corner lead down;
they are made of the faces that can be seen (treads, risers and their sides), so no two faces lie
in one plane over the same area (coplanar twins would fight for the same pixels). The deck is
a plain pale stone (a material without a texture). Faces point into the pool and up from the deck;
the renderers draw receivers two-sided anyway. Run: python3 scenes/showcase/assets/make_pool.py
(deterministic: the output never changes).
"""
import base64
import json
import struct
import zlib
from pathlib import Path

HALF = 4.0        # the pool's inner half width, m (the water's half_extent)
DEPTH = 1.6       # the floor below the mean water level, m
DECK = 0.25       # the deck above it, m
DECK_WIDTH = 40.0  # m: to beyond what the camera sees
TILE_TEXTURE_M = 1.0  # the texture's size in metres: 4 x 4 tiles of 25 cm
STEPS = [(0.6, -0.4), (1.2, -0.8), (1.8, -1.2)]  # (reach from the left wall, top height), m
STEPS_WIDTH = 2.0  # along the left wall, from the near corner, m


def tiles_png(size=256, tiles=4, grout=3):
    """Pale blue tiles with grey grout lines, sRGB 8-bit RGB."""
    tile = size // tiles
    rows = []
    for y in range(size):
        row = bytearray([0])  # filter: none
        for x in range(size):
            in_grout = (x % tile) < grout or (y % tile) < grout
            # A slight per-tile shade so the tiling reads as tiles, not as a grid on one colour.
            shade = ((x // tile) * 7 + (y // tile) * 13) % 5 - 2
            r, g, b = (150, 155, 150) if in_grout else (150 + 2 * shade, 205 + 2 * shade, 228 + shade)
            row += bytes((r, g, b))
        rows.append(bytes(row))
    raw = b"".join(rows)

    def chunk(kind, data):
        return struct.pack(">I", len(data)) + kind + data + struct.pack(">I", zlib.crc32(kind + data) & 0xFFFFFFFF)

    header = struct.pack(">IIBBBBB", size, size, 8, 2, 0, 0, 0)
    return (b"\x89PNG\r\n\x1a\n" + chunk(b"IHDR", header) + chunk(b"IDAT", zlib.compress(raw, 9)) +
            chunk(b"IEND", b""))


class Mesh:
    """Quads as two triangles each, 3 vertices per triangle (flat normals), with UVs."""

    def __init__(self):
        self.positions, self.normals, self.uvs = [], [], []

    def quad(self, corners, normal, uv_axes):
        """corners: 4 points in order around the quad; uv_axes: two axis indices for (u, v)."""
        a, b, c, d = corners
        for p in (a, b, c, a, c, d):
            self.positions.append(p)
            self.normals.append(normal)
            self.uvs.append((p[uv_axes[0]] / TILE_TEXTURE_M, -p[uv_axes[1]] / TILE_TEXTURE_M))



def pool_shell():
    h, d, t = HALF, -DEPTH, DECK
    tiled = Mesh()
    tiled.quad([(-h, d, -h), (h, d, -h), (h, t, -h), (-h, t, -h)], (0, 0, 1), (0, 1))   # far wall
    tiled.quad([(h, d, h), (-h, d, h), (-h, t, h), (h, t, h)], (0, 0, -1), (0, 1))      # near wall
    tiled.quad([(-h, d, h), (-h, d, -h), (-h, t, -h), (-h, t, h)], (1, 0, 0), (2, 1))   # left wall
    tiled.quad([(h, d, -h), (h, d, h), (h, t, h), (h, t, -h)], (-1, 0, 0), (2, 1))      # right wall
    z0 = h - STEPS_WIDTH  # the steps' side facing the pool's far end
    x = -h
    for i, (reach, top) in enumerate(STEPS):
        x1 = -h + reach
        below = STEPS[i + 1][1] if i + 1 < len(STEPS) else d  # the next tread, or the floor
        tiled.quad([(x, top, z0), (x, top, h), (x1, top, h), (x1, top, z0)], (0, 1, 0), (0, 2))       # tread
        tiled.quad([(x1, below, z0), (x1, below, h), (x1, top, h), (x1, top, z0)], (1, 0, 0), (2, 1))  # riser
        tiled.quad([(x, d, z0), (x1, d, z0), (x1, top, z0), (x, top, z0)], (0, 0, -1), (0, 1))        # side
        x = x1
    deck = Mesh()
    o = h + DECK_WIDTH
    for corners in ([(-o, t, -o), (-o, t, -h), (o, t, -h), (o, t, -o)], [(-o, t, h), (-o, t, o), (o, t, o), (o, t, h)],
                    [(-o, t, -h), (-o, t, h), (-h, t, h), (-h, t, -h)], [(h, t, -h), (h, t, h), (o, t, h), (o, t, -h)]):
        deck.quad(corners, (0, 1, 0), (0, 2))
    return tiled, deck


def pack(meshes):
    """One buffer: each mesh's positions, normals and UVs; returns the bytes and the glTF parts."""
    data = bytearray()
    views, accessors, primitives = [], [], []
    for material, mesh in enumerate(meshes):
        attributes = {}
        for name, values, kind in (("POSITION", mesh.positions, "VEC3"), ("NORMAL", mesh.normals, "VEC3"),
                                   ("TEXCOORD_0", mesh.uvs, "VEC2")):
            offset = len(data)
            for v in values:
                data += struct.pack("<%df" % len(v), *v)
            views.append({"buffer": 0, "byteOffset": offset, "byteLength": len(data) - offset})
            accessor = {"bufferView": len(views) - 1, "componentType": 5126, "count": len(values), "type": kind}
            if name == "POSITION":
                accessor["min"] = [min(v[i] for v in values) for i in range(3)]
                accessor["max"] = [max(v[i] for v in values) for i in range(3)]
            accessors.append(accessor)
            attributes[name] = len(accessors) - 1
        primitives.append({"attributes": attributes, "material": material})
    return bytes(data), views, accessors, primitives


def main():
    here = Path(__file__).resolve().parent
    (here / "tiles.png").write_bytes(tiles_png())
    data, views, accessors, primitives = pack(pool_shell())
    gltf = {
        "asset": {"version": "2.0", "generator": "scenes/showcase/assets/make_pool.py"},
        "scene": 0,
        "scenes": [{"nodes": [0]}],
        "nodes": [{"mesh": 0, "name": "pool shell"}],
        "meshes": [{"name": "pool shell", "primitives": primitives}],
        "materials": [
            {"name": "tiles", "pbrMetallicRoughness": {"baseColorTexture": {"index": 0}, "metallicFactor": 0}},
            {"name": "deck stone", "pbrMetallicRoughness": {"baseColorFactor": [0.42, 0.39, 0.35, 1], "metallicFactor": 0}},
        ],
        "textures": [{"source": 0, "sampler": 0}],
        "images": [{"uri": "tiles.png"}],
        # REPEAT on both axes (10497), trilinear minification (9987), linear magnification (9729).
        "samplers": [{"magFilter": 9729, "minFilter": 9987, "wrapS": 10497, "wrapT": 10497}],
        "buffers": [{"byteLength": len(data),
                     "uri": "data:application/octet-stream;base64," + base64.b64encode(data).decode()}],
        "bufferViews": views,
        "accessors": accessors,
    }
    (here / "pool.gltf").write_text(json.dumps(gltf, indent=1) + "\n")


if __name__ == "__main__":
    main()
