#!/usr/bin/python3
"""Reads a mesh with meshio and prints what it found, one "key value" line each, for the
writer tests:

    points N                number of points
    cells TYPE N            cells of a meshio type (tetra, hexahedron, triangle, quad)
    ref TYPE R N            cells of TYPE with MEDIT reference R
    cellset NAME N          cells in a cell set (Abaqus ELSET)
    pointset NAME N         points in a point set (Abaqus NSET)
    volume TYPE V           total volume of the tetra / hexahedron cells
    minvolume TYPE V        smallest tet volume; for hexes, of the 6 tets around diagonal 0-6
    enclosed R V            sum over faces with MEDIT reference R of centre . area / 3:
                            the volume they enclose if their normals point outward

Volumes use meshio's (VTK's) corner order, so a positive minvolume means the file's corner
order is read as positively oriented.
"""
import sys

import meshio
import numpy as np

# The 6 Kuhn tets of a hex around its diagonal 0-6, positive for a VTK-ordered hex.
HEX_TETS = [(0, 1, 2, 6), (0, 2, 3, 6), (0, 3, 7, 6), (0, 7, 4, 6), (0, 4, 5, 6), (0, 5, 1, 6)]


def tet_volumes(points, tets):
    a, b, c, d = (points[tets[:, i]] for i in range(4))
    return np.einsum("ij,ij->i", b - a, np.cross(c - a, d - a)) / 6.0


def face_volume_terms(points, faces):
    """centre . area_vector / 3 per planar face (fan around corner 0)."""
    area = np.zeros((len(faces), 3))
    for k in range(1, faces.shape[1] - 1):
        area += 0.5 * np.cross(points[faces[:, k]] - points[faces[:, 0]],
                               points[faces[:, k + 1]] - points[faces[:, 0]])
    centre = points[faces].mean(axis=1)
    return np.einsum("ij,ij->i", centre, area) / 3.0


def main(path):
    mesh = meshio.read(path)
    print("points", len(mesh.points))
    refs = mesh.cell_data.get("medit:ref")
    enclosed = {}
    for i, block in enumerate(mesh.cells):
        print("cells", block.type, len(block.data))
        if refs is not None:
            for ref, count in zip(*np.unique(refs[i], return_counts=True)):
                print("ref", block.type, ref, count)
        if block.type == "tetra":
            sub = tet_volumes(mesh.points, block.data)
            print("volume tetra", sub.sum())
            print("minvolume tetra", sub.min())
        elif block.type == "hexahedron":
            sub = np.stack([tet_volumes(mesh.points, block.data[:, list(t)]) for t in HEX_TETS])
            print("volume hexahedron", sub.sum())
            print("minvolume hexahedron", sub.min())
        elif block.type in ("triangle", "quad") and refs is not None:
            terms = face_volume_terms(mesh.points, block.data)
            for ref in np.unique(refs[i]):
                enclosed[ref] = enclosed.get(ref, 0.0) + terms[refs[i] == ref].sum()
    for ref, volume in sorted(enclosed.items()):
        print("enclosed", ref, volume)
    for name, blocks in mesh.cell_sets.items():
        print("cellset", name, sum(len(b) for b in blocks))
    for name, points in mesh.point_sets.items():
        print("pointset", name, len(points))


if __name__ == "__main__":
    main(sys.argv[1])
