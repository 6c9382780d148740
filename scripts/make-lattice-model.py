#!/usr/bin/env python3
"""Writes data/scenes/models/lattice.gltf, lattice.bin and lattice.png: a 2 x 2 m carved wooden
screen (one quad, uv 0..1) whose base-colour texture cuts a diamond lattice out of it by
its alpha (alphaMode MASK, cutoff 0.5). The cut-out scene data/scenes/atrium-cutouts.json
stands copies of it in the atrium, so that `bench --scenario materials/` measures what
textured, alpha-tested casters cost beside the untextured atrium. Run from the repository
root; the output is committed (no third-party asset: the texture is made here)."""
import base64, json, math, struct, zlib
from pathlib import Path

SIZE = 128

def texel(x, y):
    u, v = (x + 0.5) / SIZE, (y + 0.5) / SIZE
    # Diamond lattice: bars along both diagonals, 6 cells across, and a solid frame.
    a = (u + v) * 6.0
    b = (u - v) * 6.0
    bar = min(abs(a - round(a)), abs(b - round(b))) < 0.12
    frame = min(u, v, 1.0 - u, 1.0 - v) < 0.06
    grain = 0.85 + 0.15 * math.sin(40.0 * v + 3.0 * math.sin(9.0 * u))
    r, g, bl = (int(255 * c * grain) for c in (0.55, 0.36, 0.20))
    return bytes((r, g, bl, 255 if (bar or frame) else 0))

def png(width, height, rows):
    def chunk(kind, data):
        body = kind + data
        return struct.pack(">I", len(data)) + body + struct.pack(">I", zlib.crc32(body))
    raw = b"".join(b"\x00" + row for row in rows)
    return (b"\x89PNG\r\n\x1a\n" + chunk(b"IHDR", struct.pack(">IIBBBBB", width, height, 8, 6, 0, 0, 0))
            + chunk(b"IDAT", zlib.compress(raw, 9)) + chunk(b"IEND", b""))

def main():
    out = Path("data/scenes/models")
    out.mkdir(parents=True, exist_ok=True)
    rows = [b"".join(texel(x, y) for x in range(SIZE)) for y in range(SIZE)]
    (out / "lattice.png").write_bytes(png(SIZE, SIZE, rows))
    # Quad in the XY plane facing +Z, 2 x 2 m, bottom edge at y = 0.
    positions = [(-1, 0, 0), (1, 0, 0), (1, 2, 0), (-1, 2, 0)]
    normals = [(0, 0, 1)] * 4
    uvs = [(0, 1), (1, 1), (1, 0), (0, 0)]
    indices = [0, 1, 2, 0, 2, 3]
    blob = b"".join(struct.pack("<3f", *p) for p in positions)
    blob += b"".join(struct.pack("<3f", *n) for n in normals)
    blob += b"".join(struct.pack("<2f", *t) for t in uvs)
    blob += struct.pack("<6H", *indices)
    (out / "lattice.bin").write_bytes(blob)
    gltf = {
        "asset": {"version": "2.0", "generator": "scripts/make-lattice-model.py"},
        "scene": 0,
        "scenes": [{"nodes": [0]}],
        "nodes": [{"name": "screen", "mesh": 0}],
        "meshes": [{"primitives": [{"attributes": {"POSITION": 0, "NORMAL": 1, "TEXCOORD_0": 2},
                                    "indices": 3, "material": 0}]}],
        "materials": [{"name": "lattice", "alphaMode": "MASK", "alphaCutoff": 0.5,
                       "doubleSided": True,
                       "pbrMetallicRoughness": {"baseColorTexture": {"index": 0},
                                                "metallicFactor": 0.0, "roughnessFactor": 0.8}}],
        "textures": [{"source": 0, "sampler": 0}],
        "samplers": [{"magFilter": 9729, "minFilter": 9987}],
        "images": [{"uri": "lattice.png"}],
        "buffers": [{"uri": "lattice.bin", "byteLength": len(blob)}],
        "bufferViews": [{"buffer": 0, "byteOffset": 0, "byteLength": 48},
                        {"buffer": 0, "byteOffset": 48, "byteLength": 48},
                        {"buffer": 0, "byteOffset": 96, "byteLength": 32},
                        {"buffer": 0, "byteOffset": 128, "byteLength": 12}],
        "accessors": [
            {"bufferView": 0, "componentType": 5126, "count": 4, "type": "VEC3",
             "min": [-1, 0, 0], "max": [1, 2, 0]},
            {"bufferView": 1, "componentType": 5126, "count": 4, "type": "VEC3"},
            {"bufferView": 2, "componentType": 5126, "count": 4, "type": "VEC2"},
            {"bufferView": 3, "componentType": 5123, "count": 6, "type": "SCALAR"}],
    }
    (out / "lattice.gltf").write_text(json.dumps(gltf, indent=1) + "\n")

if __name__ == "__main__":
    main()
