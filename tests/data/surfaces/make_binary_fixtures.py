#!/usr/bin/env python3
"""Writes the binary fixtures of tests/data/surfaces and tests/data/bad (standard library only)."""
import os
import struct

HERE = os.path.dirname(os.path.dirname(os.path.abspath(__file__)))  # tests/data
CUBE_POINTS = [(0, 0, 0), (1, 0, 0), (1, 1, 0), (0, 1, 0), (0, 0, 1), (1, 0, 1), (1, 1, 1), (0, 1, 1)]
CUBE_QUADS = [(0, 3, 2, 1), (4, 5, 6, 7), (0, 1, 5, 4), (3, 7, 6, 2), (0, 4, 7, 3), (1, 2, 6, 5)]
CUBE_TRIANGLES = [t for a, b, c, d in CUBE_QUADS for t in ((a, b, c), (a, c, d))]


def write(name, data):
    with open(os.path.join(HERE, name), "wb") as f:
        f.write(data)


def stl_records(triangles):
    out = b""
    for t in triangles:
        out += struct.pack("<3f", 0, 0, 0)  # readers recompute normals
        for v in t:
            out += struct.pack("<3f", *CUBE_POINTS[v])
        out += struct.pack("<H", 0)
    return out


# A binary STL whose header starts with "solid", as some exporters write it.
header = b"solid cube written as binary, as SolidWorks does".ljust(80, b" ")
write("surfaces/cube_solid_header.stl",
      header + struct.pack("<I", len(CUBE_TRIANGLES)) + stl_records(CUBE_TRIANGLES))

# Binary little-endian PLY: float coordinates with normals to skip, quads with uchar/int lists,
# a per-face colour to skip, and a trailing element of lists to skip.
ply = (b"ply\nformat binary_little_endian 1.0\ncomment unit cube\n"
       b"element vertex 8\nproperty float x\nproperty float y\nproperty float z\n"
       b"property float nx\nproperty float ny\nproperty float nz\n"
       b"element face 6\nproperty list uchar int vertex_indices\nproperty uchar red\n"
       b"element material 2\nproperty list uchar float weights\n"
       b"end_header\n")
for p in CUBE_POINTS:
    ply += struct.pack("<6f", *p, 0, 0, 1)
for q in CUBE_QUADS:
    ply += struct.pack("<B4iB", 4, *q, 200)
ply += struct.pack("<B2f", 2, 0.5, 0.5) + struct.pack("<B", 0)
write("surfaces/cube_le.ply", ply)

# Binary big-endian PLY: double coordinates listed z, x, y; triangles as int counts of uint indices.
ply = (b"ply\nformat binary_big_endian 1.0\n"
       b"element vertex 8\nproperty double z\nproperty double x\nproperty double y\n"
       b"element face 12\nproperty list int uint vertex_index\n"
       b"end_header\n")
for x, y, z in CUBE_POINTS:
    ply += struct.pack(">3d", z, x, y)
for t in CUBE_TRIANGLES:
    ply += struct.pack(">i3I", 3, *t)
write("surfaces/cube_be.ply", ply)

# Bad inputs.
write("bad/truncated.stl", b"binary cube".ljust(80, b" ") + struct.pack("<I", 12) +
      stl_records(CUBE_TRIANGLES[:5]) + b"\0" * 20)
write("bad/huge_count.stl", (b"binary".ljust(80, b" ") + struct.pack("<I", 4_000_000_000)).ljust(200, b"\0"))
write("bad/truncated.ply", b"ply\nformat binary_little_endian 1.0\nelement vertex 8\n"
      b"property float x\nproperty float y\nproperty float z\nelement face 12\n"
      b"property list uchar int vertex_indices\nend_header\n" +
      b"".join(struct.pack("<3f", *p) for p in CUBE_POINTS) +
      b"".join(struct.pack("<B3i", 3, *t) for t in CUBE_TRIANGLES[:7]))
