#!/usr/bin/python3
"""Reads volume meshes with meshio and prints, for each file, one line holding a JSON object
of what meshio found in its 3D cells:

    cells      cell count per meshio type (tetra, polyhedron<N>, ...)
    volume     their total volume
    regions    volume per region, by region number
    min_tet    the smallest tetra volume (positive when meshio reads the corners as
               positively oriented)
    min_hex    the smallest hexahedron volume, likewise

A cell's region is its "region" cell data (VTU), its physical group (Gmsh "gmsh:physical"),
its reference (MEDIT "medit:ref") or the ELSET region_<r> holding it (Abaqus); with
--region-array NAME, the first component of its cell data NAME instead. Tetra volumes are
signed, in VTK's corner order; a polyhedron's is summed over its outward faces, each fanned
about its vertex average as volmesh measures them, and so is a hexahedron's, its faces taken
in VTK's corner order.
Usage: meshio_region_volumes.py [--region-array NAME] FILE..."""
import json
import sys
from collections import Counter, defaultdict

import meshio
import numpy as np

REGION_ARRAYS = ("region", "gmsh:physical", "medit:ref")
# Outward faces of a VTK hexahedron in its corner numbers.
HEX_FACES = ((0, 3, 2, 1), (4, 5, 6, 7), (0, 1, 5, 4), (1, 2, 6, 5), (2, 3, 7, 6), (3, 0, 4, 7))


def tet_volumes(points, tets):
    a, b, c, d = (points[tets[:, i]] for i in range(4))
    return np.einsum("ij,ij->i", b - a, np.cross(c - a, d - a)) / 6.0


def polyhedron_volumes(points, cells):
    out = []
    for faces in cells:
        total = 0.0
        for face in faces:
            loop = points[face]
            centre = loop.mean(axis=0)
            nxt = np.roll(loop, -1, axis=0)
            fan = np.cross(nxt, np.broadcast_to(centre, loop.shape))
            total += np.einsum("ij,ij->i", loop, fan).sum()
        out.append(total / 6.0)
    return np.array(out)


def block_regions(mesh, i, size, arrays):
    """The region of each cell of block i."""
    for name in arrays:
        if name in mesh.cell_data:
            return np.asarray(mesh.cell_data[name][i]).reshape(size, -1)[:, 0].astype(int)
    regions = np.zeros(size, dtype=int)
    for name, blocks in mesh.cell_sets.items():
        if name.startswith("region_") and i < len(blocks) and len(blocks[i]):
            regions[np.asarray(blocks[i], dtype=int)] = int(name[len("region_"):])
    return regions


def summary(path, arrays):
    mesh = meshio.read(path)
    cells, regions = Counter(), defaultdict(float)
    min_tet = min_hex = None
    for i, block in enumerate(mesh.cells):
        if block.type == "tetra":
            volumes = tet_volumes(mesh.points, block.data)
            smallest = float(volumes.min())
            min_tet = smallest if min_tet is None else min(min_tet, smallest)
        elif block.type == "hexahedron":
            volumes = polyhedron_volumes(mesh.points, [[hexa[list(f)] for f in HEX_FACES]
                                                       for hexa in block.data])
            smallest = float(volumes.min())
            min_hex = smallest if min_hex is None else min(min_hex, smallest)
        elif block.type.startswith("polyhedron"):
            volumes = polyhedron_volumes(mesh.points, block.data)
        else:
            continue
        cells[block.type] += len(block.data)
        for region, volume in zip(block_regions(mesh, i, len(block.data), arrays), volumes):
            regions[int(region)] += float(volume)
    return {"cells": dict(cells), "volume": sum(regions.values()),
            "regions": {str(r): v for r, v in sorted(regions.items())}, "min_tet": min_tet,
            "min_hex": min_hex}


if __name__ == "__main__":
    args, arrays = sys.argv[1:], REGION_ARRAYS
    if args[:1] == ["--region-array"]:
        arrays, args = (args[1],), args[2:]
    for path in args:
        print(json.dumps(summary(path, arrays)))
