#!/usr/bin/python3
"""Reads a partitioned mesh with meshio the way a user would: a .pvtu's pieces (meshio has no
PVTU reader: the piece names come from the summary file), or one .vtu / .msh file. Prints one
JSON object per file:

    files        pieces read (1 for a .vtu or .msh)
    cells        cell count per meshio cell type, over all pieces
    volume       total volume of the cells (tets, hexes as 6 tets, polyhedra by their faces)
    cell_data    names of the cell arrays; point_data likewise
    partitions   for a .pvtu: cells per piece; for an MSH 2.2 file that gmsh wrote from a
                 partitioned mesh: volume elements per partition (its elements' partition tags)
    cell_ids     for a .pvtu: whether GlobalCellIds of all pieces are 0 .. N-1, each once
    regions      for a .pvtu: the region of each cell, by GlobalCellIds
    point_ids    for a .pvtu: distinct GlobalPointIds, and whether every piece puts a point id
                 at the same coordinates

Usage: meshio_pvtu.py FILE...
"""
import json
import os
import sys
import xml.etree.ElementTree as ET
from collections import Counter

import meshio
import numpy as np

HEX_TETS = [(0, 1, 2, 6), (0, 2, 3, 6), (0, 3, 7, 6), (0, 7, 4, 6), (0, 4, 5, 6), (0, 5, 1, 6)]


def tet_volumes(points, tets):
    a, b, c, d = (points[tets[:, i]] for i in range(4))
    return np.einsum("ij,ij->i", b - a, np.cross(c - a, d - a)) / 6.0


def polyhedra_volume(points, cells):
    """Divergence theorem over the outward faces, each fanned from its first vertex."""
    t = np.array([(face[0], face[k], face[k + 1]) for cell in cells for face in cell
                  for k in range(1, len(face) - 1)])
    products = np.einsum("ij,ij->i", points[t[:, 0]], np.cross(points[t[:, 1]], points[t[:, 2]]))
    return products.sum() / 6.0


def volume(mesh):
    total = 0.0
    for block in mesh.cells:
        if block.type == "tetra":
            total += tet_volumes(mesh.points, block.data).sum()
        elif block.type == "hexahedron":
            total += sum(tet_volumes(mesh.points, block.data[:, list(t)]).sum() for t in HEX_TETS)
        elif block.type.startswith("polyhedron"):
            total += polyhedra_volume(mesh.points, block.data)
    return total


def msh22_partitions(path):
    """Volume elements per partition in an MSH 2.2 file: tags are physical, elementary,
    number of partitions, partitions (the first is the owner)."""
    counts = Counter()
    with open(path) as f:
        lines = iter(f.read().splitlines())
    for line in lines:
        if line == "$Elements":
            for _ in range(int(next(lines))):
                words = [int(w) for w in next(lines).split()]
                if words[1] in (4, 5) and words[2] >= 4 and words[5] >= 1:
                    counts[words[6]] += 1
    return dict(sorted(counts.items()))


def read_one(path):
    mesh = meshio.read(path)
    cells = Counter()
    for block in mesh.cells:
        cells[block.type] += len(block.data)
    return mesh, cells


def main():
    for path in sys.argv[1:]:
        if not path.endswith(".pvtu"):
            mesh, cells = read_one(path)
            out = {"files": 1, "cells": dict(cells), "volume": volume(mesh),
                   "cell_data": sorted(mesh.cell_data), "point_data": sorted(mesh.point_data)}
            if path.endswith(".msh"):
                out["partitions"] = msh22_partitions(path)
            print(json.dumps(out))
            continue
        root = ET.parse(path).getroot()
        sources = [p.get("Source") for p in root.iter("Piece")]
        cells, total, per_piece = Counter(), 0.0, []
        cell_ids, regions, point_at, consistent = [], {}, {}, True
        cell_data, point_data = set(), set()
        for source in sources:
            mesh, piece_cells = read_one(os.path.join(os.path.dirname(path), source))
            cells.update(piece_cells)
            per_piece.append(sum(piece_cells.values()))
            total += volume(mesh)
            cell_data.update(mesh.cell_data)
            point_data.update(mesh.point_data)
            for ids, region in zip(mesh.cell_data["GlobalCellIds"], mesh.cell_data["region"]):
                cell_ids.extend(int(i) for i in ids)
                regions.update((int(i), int(r)) for i, r in zip(ids, region))
            for point, gid in zip(mesh.points, mesh.point_data["GlobalPointIds"]):
                known = point_at.setdefault(int(gid), tuple(point))
                consistent = consistent and known == tuple(point)
        print(json.dumps({
            "files": len(sources), "cells": dict(cells), "volume": total,
            "cell_data": sorted(cell_data), "point_data": sorted(point_data),
            "partitions": per_piece,
            "cell_ids": sorted(cell_ids) == list(range(len(cell_ids))),
            "regions": [regions.get(i, 0) for i in range(len(cell_ids))],
            "point_ids": {"distinct": len(point_at), "consistent": consistent},
        }))


if __name__ == "__main__":
    main()
